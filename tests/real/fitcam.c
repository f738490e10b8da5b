/* fitcam: the camera of a real-model cross-check, from the reference mesh.
 *
 * usage: fitcam MESH.stl [FOV]
 *
 * Real models name no camera, so the runner (tests/real/run) frames each
 * one from the binary STL OpenSCAD made of it, and gives spancast and the
 * reference caster the same eye and centre. The framing is OpenSCAD's own
 * default view (docs/camera.md, "--viewall and --autocenter"): the forward
 * direction of the gimbal rotate 55, 0, 25,
 *   F = (-sin 55 sin 25, sin 55 cos 25, -cos 55),
 * the centre c the centre of the mesh's bounding box, and the eye at
 * c - dist F with dist = (|hi - lo| / 2) / sin(fov / 2), so the box's
 * circumscribed sphere fits the vertical field of view (default 22.5
 * degrees, spancast's and OpenSCAD's default). The box is the mesh's own,
 * from every vertex of every triangle, not spancast's conservative tree
 * bounds, so the framing does not depend on the side under test.
 *
 * Prints "ex,ey,ez,cx,cy,cz" (the --camera form both casters take) with 9
 * significant digits; exits 1 on an unreadable or empty mesh, 2 on bad
 * usage. The STL layout: 80-byte header, uint32 count, then per triangle a
 * normal and three vertices as little-endian float32, and a uint16.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

int main(int argc, char **argv)
{
    double fov = 22.5;
    if (argc < 2 || argc > 3 ||
        (argc == 3 && !((fov = atof(argv[2])) > 0 && fov < 180))) {
        fprintf(stderr, "usage: fitcam MESH.stl [FOV]\n");
        return 2;
    }
    FILE *in = fopen(argv[1], "rb");
    if (!in) {
        fprintf(stderr, "fitcam: cannot open '%s'\n", argv[1]);
        return 1;
    }
    unsigned char header[84];
    uint32_t count = 0;
    int ok = fread(header, 1, sizeof header, in) == sizeof header;
    if (ok)
        count = (uint32_t)header[80] | (uint32_t)header[81] << 8 |
                (uint32_t)header[82] << 16 | (uint32_t)header[83] << 24;
    double lo[3] = {INFINITY, INFINITY, INFINITY},
           hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (uint32_t k = 0; ok && k < count; k++) {
        unsigned char record[50];
        if (fread(record, 1, sizeof record, in) != sizeof record) {
            ok = 0;
            break;
        }
        for (int v = 1; v < 4; v++) {
            for (int axis = 0; axis < 3; axis++) {
                float x;
                memcpy(&x, record + 12 * v + 4 * axis, sizeof x);
                if (!isfinite(x)) {
                    ok = 0;
                    continue;
                }
                lo[axis] = fmin(lo[axis], x);
                hi[axis] = fmax(hi[axis], x);
            }
        }
    }
    fclose(in);
    if (!ok || count == 0) {
        fprintf(stderr, "fitcam: '%s' is not a binary STL with triangles\n", argv[1]);
        return 1;
    }
    double rx = 55 * PI / 180, rz = 25 * PI / 180;
    double forward[3] = {-sin(rx) * sin(rz), sin(rx) * cos(rz), -cos(rx)};
    double centre[3], diagonal = 0;
    for (int axis = 0; axis < 3; axis++) {
        centre[axis] = (lo[axis] + hi[axis]) / 2;
        diagonal += (hi[axis] - lo[axis]) * (hi[axis] - lo[axis]);
    }
    double radius = sqrt(diagonal) / 2;
    if (!(radius > 0)) {
        fprintf(stderr, "fitcam: '%s' has no extent\n", argv[1]);
        return 1;
    }
    double dist = radius / sin(fov / 2 * PI / 180);
    printf("%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", centre[0] - dist * forward[0],
           centre[1] - dist * forward[1], centre[2] - dist * forward[2], centre[0],
           centre[1], centre[2]);
    return 0;
}
