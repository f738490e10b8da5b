/* Frame sequences of `spancast render` (frames.c): --animate, --turntable,
 * --shutter with --subframes, --video with --fps. */
#ifndef SPANCAST_CLI_FRAMES_H
#define SPANCAST_CLI_FRAMES_H

#include <stddef.h>

#include "spancast/spancast.h"

/* frames_run's status when an interrupt stopped it (the caller ends the
 * process by the signal). */
#define FRAMES_INTERRUPTED 130

typedef struct frames_job {
    const char *input, *output; /* the model; the output name frames are numbered in */
    int faithful, quiet;
    int animate;       /* --animate=N frames at OpenSCAD's $t = i / N; 0: none */
    int turntable;     /* --turntable=N: one turn over the N frames; 0: none */
    double shutter[2]; /* open and close, fractions of a frame; equal: closed */
    int subframes;     /* renders averaged per frame with an open shutter */
    const char *video; /* --video=FILE, or NULL */
    double fps;        /* the video's frame rate */
    /* The render options for a loaded scene: the file's settings and the
     * command line over them. Returns 0 or an exit status. */
    int (*options_for)(void *user, const sc_scene *scene, sc_render_options *out);
    void *user;
} frames_job;

void frames_job_init(frames_job *job);

/* Frame frame's file name for output, OpenSCAD's way: the number in five
 * digits before the extension. Returns 0 when it does not fit in size. */
int frames_name(const char *output, int frame, char *out, size_t size);

/* Renders and writes every frame, then the video; returns 0, an exit
 * status after printing why, or FRAMES_INTERRUPTED. */
int frames_run(const frames_job *job);

#endif
