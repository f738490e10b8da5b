/* The tool's help: `spancast --help` prints every section below in order;
 * `spancast COMMAND --help` only those of COMMAND, so that each command's
 * help lists the options it takes and no other (the bash completion reads
 * them from it). The texts are kept once, here. */
#include <stdio.h>
#include <string.h>

#include "cli/cli.h"
#include "spancast/spancast.h"

enum {
    C_RENDER = 1 << 0,
    C_INFO = 1 << 1,
    C_SPANS = 1 << 2,
    C_INSIDE = 1 << 3,
    C_MEASURE = 1 << 4,
    C_OVERLAPS = 1 << 5,
    C_COMPARE = 1 << 6,
    C_BATCH = 1 << 7,
    C_BENCH = 1 << 8,
    C_VIEW = 1 << 9,
    C_CHECKS = C_MEASURE | C_OVERLAPS | C_COMPARE,
    C_MODELS = C_RENDER | C_INFO | C_SPANS | C_INSIDE | C_CHECKS | C_VIEW | C_BATCH,
    C_ALL = C_MODELS | C_BENCH,
    C_ALONE = 1 << 10 /* a section only in one command's help */
};

static const struct {
    const char *name;
    unsigned bit;
} commands[] = {
    {"render", C_RENDER},   {"info", C_INFO},       {"spans", C_SPANS},
    {"inside", C_INSIDE},   {"measure", C_MEASURE}, {"overlaps", C_OVERLAPS},
    {"compare", C_COMPARE}, {"view", C_VIEW},       {"batch", C_BATCH},
    {"bench", C_BENCH},
};

/* The usage lines, one command each (continuation lines included): the
 * first follows "usage: ", the others "       ". */
static const struct {
    unsigned command;
    const char *text;
} usages[] = {
    {C_RENDER, "spancast render MODEL -o OUT.png [options]\n"},
    {C_INFO, "spancast info MODEL [--faithful] [--strict] [--threads=N]\n"},
    {C_SPANS,
     "spancast spans MODEL --ray=OX,OY,OZ,DX,DY,DZ | --rays=FILE | --pixel=I,J\n"
     "                      [--both-ways] [--json] [--strict] [camera options]\n"},
    {C_INSIDE,
     "spancast inside MODEL --point=X,Y,Z | --points=FILE [--json] [--strict]\n"},
    {C_MEASURE, "spancast measure MODEL [--tolerance=REL] [--density=D]\n"},
    {C_OVERLAPS, "spancast overlaps MODEL [--min-volume=V] [--tolerance=REL]\n"},
    {C_COMPARE,
     "spancast compare A B [--tolerance=REL] [--max-pixels=N] [--diff=PREFIX]\n"
     "                        [--imgsize=W,H]\n"},
    {C_VIEW, "spancast view MODEL [--imgsize=W,H] [--spp=N] [--faithful] [--strict]\n"},
    {C_BATCH, "spancast batch JOBS [--json] [--strict]\n"},
    {C_BENCH, "spancast bench accuracy --csv FILE [--plot FILE.png] [--rays N]\n"
              "spancast bench stability --csv FILE [--dir DIR] [--size N] [--depth N]\n"},
};

/* The sections after the usage lines, in the order of the whole help.
 * Sections of the same block print as one paragraph or option list: the
 * first of them printed opens it after a blank line, under its heading
 * (`heading` in the whole help, `own` when given in one command's, where a
 * heading that names several commands would mislead, or where a block
 * opens with a later section). The whole help leaves out the sections
 * marked C_ALONE. */
enum {
    B_ABOUT,
    B_CHECKS,
    B_BATCH,
    B_BENCH,
    B_MODEL,
    B_DEFINE,
    B_QUERY,
    B_RENDER,
    B_MPI,
    B_PREVIEW,
    B_LIMITS,
    B_REPORT,
    B_CAMERA,
    B_VALUE,
    B_EXIT
};

typedef struct section {
    unsigned commands;
    int block;
    const char *heading, *own;
    const char *text;
} section;

static const section sections[] = {
    {C_RENDER, B_ABOUT, NULL, NULL,
     "Renders a CSG model (OpenSCAD's .csg export, plus spancast's own nodes)\n"
     "exactly, by casting rays.\n"},
    {C_INFO, B_ABOUT, NULL, NULL,
     "'info' prints the size and bounds of a model's tree.\n"},
    {C_SPANS, B_ABOUT, NULL, NULL,
     "'spans' lists where rays enter and leave the solid (t in units of the\n"
     "direction given, t >= 0 unless --both-ways, distance inside = dt |d|).\n"},
    {C_INSIDE, B_ABOUT, NULL, NULL,
     "'inside' says whether points are in, out or on the surface.\n"},
    {C_MEASURE, B_CHECKS, NULL, NULL,
     "'measure' prints volume, area, centroid, inertia and the tight box, each\n"
     "with an error bound (--tolerance, relative, default 1e-4).\n"},
    {C_OVERLAPS, B_CHECKS, NULL, NULL,
     "'overlaps' prints the pairs of top-level objects that share volume, to\n"
     "--tolerance (default 1e-3) of it (exit 1 when one shares more than\n"
     "--min-volume, default 0; exit 2 on any error).\n"},
    {C_COMPARE, B_CHECKS, NULL, NULL,
     "'compare' prints the volume between two models or a model and a mesh (.stl,\n"
     ".off, .amf, .3mf), and mask and depth mismatches from seven views (exit 1\n"
     "when the volume passes --tolerance, default 1e-6 of the larger volume, or\n"
     "a view has more than --max-pixels, default 0, mismatched pixels away from\n"
     "silhouette edges; exit 2 on any error; --diff=PREFIX writes PREFIXpx.png\n"
     "... PREFIXdiagonal.png).\n"},
    {C_BATCH, B_BATCH, NULL, NULL,
     "'batch' runs the spancast command of each line of JOBS (shell quoting, '#'\n"
     "comments, paths relative to JOBS' folder), each once, across the ranks\n"
     "under mpirun; a failed job does not stop the others; it prints a table of\n"
     "every job with what it printed, or JSON with --json, and exits 1 when a\n"
     "job failed; --strict passes --strict on to every job.\n"},
    {C_BENCH, B_BENCH, NULL, NULL,
     "'bench accuracy' measures the implicit-surface root finders against time\n"
     "on scenes with known answers, one CSV row per method and tolerance, on an\n"
     "N x N grid of rays (--rays, default 16); --plot draws it with gnuplot.\n"
     "'bench stability' runs the numerical stability suite (scales, far\n"
     "translations, coincident faces, ill-conditioned transforms, deep and wide\n"
     "trees, and the models of DIR/models; --dir, default .) and writes one CSV\n"
     "row per case, on images of N x N pixels (--size, default 64) and a deep\n"
     "tree of N levels (--depth, default 10000).\n"},
    {C_MODELS, B_MODEL, NULL, NULL,
     "MODEL may be a .scad file: OpenSCAD (in PATH) converts it first; its\n"
     "WARNING lines are shown as warnings, and an ERROR (even one OpenSCAD exits\n"
     "0 after, as a failing assert()) fails the command. A model that draws\n"
     "nothing gives a warning. A .csg that uses more of OpenSCAD's language\n"
     "(variables, modules, for, ...) is converted the same way, with a note.\n"
     "MODEL may also be a mesh, .stl (ASCII or binary), .off, .amf or .3mf, taken\n"
     "as the model import(\"MODEL\");.\n"},
    {C_MODELS, B_DEFINE,
     "render, info, spans, inside, measure, overlaps, compare, view and batch "
     "options\n(OpenSCAD's):\n",
     "OpenSCAD's options:\n",
     "  -D NAME=VALUE          set a variable of a model OpenSCAD converts, as\n"
     "                         OpenSCAD's -D (repeatable, in order; batch passes\n"
     "                         them to every job)\n"},
    {C_CHECKS, B_QUERY, "measure, overlaps and compare options:\n", "options:\n",
     "  --threads=N            worker threads (default 0: all cores)\n"},
    {C_CHECKS | C_SPANS | C_INSIDE, B_QUERY, NULL, "options:\n",
     "  --json                 the report as JSON on stdout\n"},
    {C_INFO | C_ALONE, B_QUERY, NULL, "options:\n",
     "  --threads=N            threads to load with (default 0: all cores; a file\n"
     "                         of 1 MiB or more is parsed in two parts at once)\n"},
    {C_CHECKS | C_SPANS | C_INSIDE | C_INFO, B_QUERY, NULL, "options:\n",
     "  --faithful             the polyhedra OpenSCAD makes (default: exact solids)\n"
     "  --strict               a warning that leaves a part out or renders it\n"
     "                         otherwise (a mesh that is not closed, a file that\n"
     "                         cannot be read, a matrix that is not finite, a child\n"
     "                         of the other dimension, OpenSCAD's warnings of a\n"
     "                         node's arguments, for a .scad model OpenSCAD's first\n"
     "                         warning) is an error (default: a warning, as for\n"
     "                         render)\n"},
    {C_CHECKS, B_QUERY, NULL, NULL, "  -q, --quiet            no progress on stderr\n"},
    {C_RENDER, B_RENDER, "render options:\n", NULL,
     "  -o, --output=FILE      colour image; the format follows the extension\n"
     "                         (.png, .jpg, .tif, .exr, ...)\n"
     "  --mask=FILE            coverage mask: 255 where the model is hit, 0 elsewhere\n"
     "  --depth=FILE           distance from the ray origin to the hit, 32-bit float,\n"
     "                         +inf on a miss (.exr or .tif)\n"
     "  --normal=FILE          world-space normal at the hit, 3 floats, 0 on a miss\n"
     "                         (.exr or .tif)\n"
     "  --id=FILE              index of the leaf hit (source order), -1 on a miss\n"
     "                         (.exr or .tif)\n"},
    {C_RENDER | C_SPANS, B_RENDER, NULL, "camera options:\n",
     "  --camera=EX,EY,EZ,CX,CY,CZ\n"
     "                         look from eye E at centre C, z up\n"
     "  --camera=TX,TY,TZ,RX,RY,RZ,D\n"
     "                         OpenSCAD's gimbal camera: translate, rotate (degrees),\n"
     "                         distance\n"
     "  --imgsize=W,H          image size in pixels (default 800,600)\n"
     "  --fov=DEG              vertical field of view in degrees (default 22.5)\n"
     "  --projection=p|o       perspective (default) or orthographic\n"
     "  --viewall              move the camera until the whole model is in view\n"
     "  --autocenter           with --viewall: look at the centre of the model\n"},
    {C_RENDER, B_RENDER, NULL, NULL,
     "  --spp=N                samples per pixel, stratified and jittered (default 1)\n"
     "  --max-depth=N          reflection and refraction bounces (default 5)\n"
     "  --region=X0,Y0,X1,Y1   render only this crop (X1, Y1 exclusive)\n"
     "  --threads=N            worker threads (default 0: all cores)\n"
     "  --faithful             spheres and cylinders as the polyhedra OpenSCAD makes\n"
     "                         from $fn, $fa, $fs (default: exact solids)\n"
     "  --strict               a warning that leaves a part out or renders it\n"
     "                         otherwise is an error: a polyhedron or imported mesh\n"
     "                         that is not closed (or not consistently wound; by\n"
     "                         default drawn by the parity rule, or left out with\n"
     "                         --faithful as OpenSCAD does), a file that cannot be\n"
     "                         read, a matrix that is not finite, a child of the\n"
     "                         other dimension (a 2D one in a 3D operation, or the\n"
     "                         reverse), OpenSCAD's warnings of a node's arguments\n"
     "                         (centre for center, a name given twice, a colour\n"
     "                         it cannot parse, $fs clamped, a primitive's children),\n"
     "                         and for a .scad model OpenSCAD's first warning\n"
     "  --tiled                write tiled .exr or .tif files, each tile as soon as it\n"
     "                         is rendered, never holding the whole image (the default\n"
     "                         for images whose buffers do not fit in memory)\n"
     "  --animate=N            N frames, a .scad model at OpenSCAD's $t = i/N, named\n"
     "                         like OpenSCAD's: -o frame.png gives frame00000.png, ...\n"
     "  --turntable=N          N frames turning the camera once about its centre\n"
     "  --shutter=OPEN,CLOSE   motion blur over this part of the frame (0..1):\n"
     "                         motion() nodes move during it, and with frames each\n"
     "                         frame averages --subframes renders across $t\n"
     "                         (default closed)\n"
     "  --subframes=K          renders averaged per frame with an open shutter\n"
     "                         (default 8)\n"
     "  --video=FILE           encode the frames with ffmpeg (H.264)\n"
     "  --fps=F                the video's frames per second (default 24)\n"
     "  --aperture=A           depth of field: a thin lens A model units wide\n"
     "                         (default 0: a pinhole); blur needs --spp above 1\n"
     "  --focus=D              distance from the eye to the sharp plane (default:\n"
     "                         to the view's centre)\n"},
    {C_RENDER | C_BATCH | C_CHECKS, B_MPI, NULL, NULL,
     "Under mpirun -np N (N > 1), render hands tiles out to all N ranks, batch\n"
     "its jobs, and measure, overlaps and compare share their lines; the files\n"
     "and numbers are the same as one process writes.\n"},
    {C_RENDER, B_PREVIEW, "preview options (CAD-style renders):\n", NULL,
     "  --colorscheme=NAME     OpenSCAD's colour scheme: Cornfield (built in) or one\n"
     "                         of " SC_COLOR_SCHEME_FOLDER "\n"
     "                         (Metallic, Sunset, Tomorrow Night, ...)\n"
     "  --preview              OpenSCAD's preview (F5) rather than its render (F6):\n"
     "                         its colours, '#' and '%' parts, colour alpha\n"
     "  --lighting=NAME        default: the file's lights or spancast's rig, with\n"
     "                         shadows; openscad: OpenSCAD's own lights\n"
     "  --view=LIST            edges, axes, scales (with axes), crosshairs; several\n"
     "                         separated by commas\n"
     "  --edge-angle=DEG       creases where faces turn more than this (default 30)\n"
     "  --edge-width=PX        edge lines' width in pixels (default 1)\n"
     "  --view-preset=NAME     top, bottom, left, right, front, back, diagonal\n"
     "                         (OpenSCAD's View menu), framed like --viewall\n"
     "                         --autocenter\n"
     "  --sheet=LIST           one labelled tile per view (--imgsize each), in a grid,\n"
     "                         orthographic unless --projection is given\n"
     "  --section=NX,NY,NZ,D   keep only the half-space n.p <= D, caps on the cut;\n"
     "                         repeatable (the half-spaces intersect)\n"
     "  --section-style=STYLE  solid (default) or hatch\n"
     "  --ao=N                 ambient occlusion with N rays per sample (default 0)\n"
     "  --ao-radius=F          their reach, a fraction of the model's diagonal\n"
     "                         (default 0.1)\n"},
    {C_RENDER | C_INFO | C_CHECKS, B_LIMITS,
     "render, info, measure, overlaps and compare limits:\n", "limits:\n",
     "  --max-time=SECONDS     give up after this long (loading included), with an\n"
     "                         error and exit status 1; when watching, per render\n"},
    {C_ALL & ~C_VIEW, B_LIMITS, NULL, "limits:\n",
     "  --max-memory=SIZE      never use more memory than SIZE (512M, 2G; every\n"
     "                         command): past it, an error and exit status 1\n"},
    {C_RENDER, B_REPORT, "report options:\n", NULL,
     "  --stats[=json]         print rays by kind, primitive tests, span operations\n"
     "                         and time per stage on stdout\n"
     "  -q, --quiet            no progress bar and no summary line on stderr\n"
     "  --watch                render again whenever the model (or a file a .scad\n"
     "                         model uses) changes, until interrupted\n"},
    {C_RENDER | C_SPANS, B_CAMERA, NULL, NULL,
     "Without --camera, spancast uses the model's camera() node if it has one, else\n"
     "it looks at the centre of the model from OpenSCAD's default direction\n"
     "(rotate 55,0,25), far enough to show all of it. Command-line options win\n"
     "over the file's settings.\n"},
    {C_ALL & ~C_BATCH, B_VALUE, NULL, NULL,
     "An option that takes a value may also take it as the next argument.\n"},
    {C_RENDER, B_EXIT, NULL, NULL,
     "Exit status: 0 success; 1 the model could not be loaded, or an image not\n"
     "rendered or written; 2 a bad command line (an output named with an\n"
     "extension spancast cannot write, -o x.xyz, is one).\n"},
    {C_ALONE | (C_ALL & ~C_RENDER & ~C_OVERLAPS & ~C_COMPARE), B_EXIT, NULL, NULL,
     "Exit status: 0 success; 1 a failure; 2 a bad command line.\n"},
};

/* The bit of a command name, or 0 for none of them. */
static unsigned command_bit(const char *name)
{
    for (size_t i = 0; name && i < sizeof commands / sizeof commands[0]; i++)
        if (!strcmp(commands[i].name, name))
            return commands[i].bit;
    return 0;
}

void cli_print_help(FILE *out, const char *command)
{
    unsigned only = command_bit(command);
    unsigned want = only ? only : C_ALL;
    const char *lead = "usage: ";
    for (size_t i = 0; i < sizeof usages / sizeof usages[0]; i++) {
        if (!(usages[i].command & want))
            continue;
        /* Each line of the entry after its lead. */
        const char *p = usages[i].text;
        while (*p) {
            const char *end = strchr(p, '\n');
            int cont = *p == ' ';
            fprintf(out, "%s%.*s\n", cont ? "" : lead, (int)(end - p), p);
            if (!cont)
                lead = "       ";
            p = end + 1;
        }
    }
    if (!only)
        fprintf(out, "       spancast --help | --version\n");
    int open = -1;
    for (size_t i = 0; i < sizeof sections / sizeof sections[0]; i++) {
        const section *s = &sections[i];
        if (!(s->commands & want) || ((s->commands & C_ALONE) && !only))
            continue;
        if (s->block != open) {
            const char *heading = only && s->own ? s->own : s->heading;
            fputc('\n', out);
            if (heading)
                fputs(heading, out);
            open = s->block;
        }
        fputs(s->text, out);
    }
}
