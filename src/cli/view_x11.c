/* The viewer's Xlib error handler (view_x11_guard in view.h).
 *
 * SDL 2.26 wakes a window that waits for events by sending it an X client
 * message on a second display connection (its "request" display). A wake-up
 * sent just before the window is destroyed can reach the X server after the
 * window is gone: the server answers BadWindow to that SendEvent, and Xlib
 * reads the error only when SDL_Quit closes that connection. Requests from
 * two connections have no order between them at the server, so waiting
 * cannot rule it out; SDL 2.28 no longer sends the wake-up to a destroyed
 * window.
 *
 * SDL_Init saves the handler in place and installs its own; SDL_Quit puts
 * the saved one back before it closes the request connection. A handler
 * installed after SDL_Init is therefore gone by the time the late error is
 * read, and Xlib's default one (print, exit 1) ends a clean quit. Installed
 * before SDL_Init, this one is what SDL saves, chains to and puts back.
 */
#include <X11/Xlib.h>
#include <X11/Xproto.h>

#include "view.h"

/* The handler before ours (Xlib's default one unless the process set
 * another). Written once, on the main thread, before any thread starts. */
static XErrorHandler previous_handler;
static int guarded;

/* Ignores exactly a SendEvent to a window that no longer exists, which the
 * wake-up needs no answer from; hands every other error to the handler
 * before it. */
static int ignore_late_wakeup(Display *display, XErrorEvent *event)
{
    if (event->error_code == BadWindow && event->request_code == X_SendEvent)
        return 0;
    return previous_handler ? previous_handler(display, event) : 0;
}

void view_x11_guard(void)
{
    if (guarded)
        return;
    guarded = 1;
    previous_handler = XSetErrorHandler(ignore_late_wakeup);
}
