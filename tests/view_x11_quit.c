/* The viewer's X error handler survives SDL_Quit (src/cli/view_x11.c).
 *
 * SDL 2.26's late wake-up is a SendEvent to a window already destroyed,
 * whose BadWindow error Xlib reads only inside SDL_Quit, after SDL has put
 * back the handler SDL_Init found. This reproduces that order on a
 * connection of the test's own: the errors of a SendEvent and of a MapWindow
 * to a destroyed window are still unread when SDL_Quit returns, and are
 * read after it. The SendEvent's must be ignored; the MapWindow's must
 * reach the process's handler from before the viewer's, which stands for
 * Xlib's default one (print, exit 1) here.
 *
 * Run under a display (xvfb-run, tests/CMakeLists.txt); without one, or
 * with a video driver other than SDL's X11 one, it exits 77 (skipped).
 */
#include <SDL.h>
#include <X11/Xlib.h>
#include <X11/Xproto.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/view.h"

static int errors_seen;
static int last_request;

static int count_errors(Display *display, XErrorEvent *event)
{
    (void)display;
    errors_seen++;
    last_request = event->request_code;
    return 0;
}

int main(void)
{
    const char *display_name = getenv("DISPLAY");
    if (!display_name || !*display_name) {
        fputs("view_x11_quit: skipped: no DISPLAY\n", stderr);
        return 77;
    }
    XSetErrorHandler(count_errors);
    view_x11_guard();
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        fprintf(stderr, "view_x11_quit: FAIL: SDL_Init: %s\n", SDL_GetError());
        return 1;
    }
    const char *driver = SDL_GetCurrentVideoDriver();
    if (!driver || strcmp(driver, "x11") != 0) {
        fprintf(stderr, "view_x11_quit: skipped: SDL's video driver is '%s'\n",
                driver ? driver : "none");
        SDL_Quit();
        return 77;
    }
    SDL_Window *window =
        SDL_CreateWindow("view_x11_quit", 0, 0, 16, 16, SDL_WINDOW_HIDDEN);
    Display *own = XOpenDisplay(NULL);
    if (!window || !own) {
        fprintf(stderr, "view_x11_quit: FAIL: no window or no second connection\n");
        return 1;
    }
    Window gone = XCreateSimpleWindow(own, DefaultRootWindow(own), 0, 0, 1, 1, 0, 0, 0);
    XDestroyWindow(own, gone);
    XSync(own, False);

    XEvent wakeup;
    memset(&wakeup, 0, sizeof wakeup);
    wakeup.xclient.type = ClientMessage;
    wakeup.xclient.window = gone;
    wakeup.xclient.format = 8;
    XSendEvent(own, gone, False, NoEventMask, &wakeup);
    XMapWindow(own, gone);
    XFlush(own);

    SDL_DestroyWindow(window);
    SDL_Quit();
    XSync(own, False); /* the two errors are read here */
    XCloseDisplay(own);

    int failures = 0;
    if (errors_seen != 1) {
        fprintf(stderr,
                "view_x11_quit: FAIL: %d errors reached the handler before the viewer's; "
                "want 1 (MapWindow's)\n",
                errors_seen);
        failures++;
    } else if (last_request != X_MapWindow) {
        fprintf(stderr,
                "view_x11_quit: FAIL: the error that got through was request %d\n",
                last_request);
        failures++;
    }
    if (!failures)
        puts("view_x11_quit: the late SendEvent error ignored after SDL_Quit, "
             "the MapWindow error handed on");
    return failures ? 1 : 0;
}
