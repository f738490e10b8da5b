/* Replays every fuzzer finding in tests/fuzz-regressions/ through the same
 * load path the fuzzer drives (fuzz/harness.h: load, compile, 8 x 8 render),
 * and through the split parse's check (fuzz/split_harness.h) at the place
 * its fuzzer picks; and every finding of the mesh readers' fuzzer, in
 * tests/fuzz-regressions/mesh/ (its first byte picks the reader and mode,
 * as fuzz_mesh's input does), through fuzz/mesh_harness.h.
 *
 * Each file is an input that once crashed, leaked or tripped a sanitizer;
 * here it must load or fail with a message, render or fail with a message,
 * and leave nothing behind. The normal build checks the library's promises;
 * the sanitizer build of scripts/test checks memory and undefined behaviour
 * on exactly these inputs. scripts/fuzz replays them under clang too.
 */
#include <dirent.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "../fuzz/harness.h"
#include "../fuzz/mesh_harness.h"
#include "../fuzz/split_harness.h"

static const char folder[] = SPANCAST_SOURCE_DIR "/tests/fuzz-regressions";
static const char mesh_folder[] = SPANCAST_SOURCE_DIR "/tests/fuzz-regressions/mesh";

/* Reads a whole file; NULL when it cannot be read. */
static char *read_all(const char *path, size_t *length)
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    while (buf) {
        n += fread(buf + n, 1, cap - n, f);
        if (n < cap)
            break;
        char *bigger = realloc(buf, cap * 2);
        if (!bigger) {
            free(buf);
            buf = NULL;
            break;
        }
        buf = bigger;
        cap *= 2;
    }
    fclose(f);
    *length = n;
    return buf;
}

/* The .csg text of a finding: the load path, and the split parse where
 * fuzz_split splits it. */
static void replay_csg(const char *name, const char *text, size_t length)
{
    if (fuzz_one((const uint8_t *)text, length) != 0)
        fail_msg("%s: the library broke a promise on this input", name);
    int split;
    if (length >= 2 && split_one(text, length, split_place(text, length), &split) != 0)
        fail_msg("%s: split in two, the parse differs from a whole one", name);
}

/* A mesh reader's finding: its first byte picks the reader and mode. */
static void replay_mesh(const char *name, const char *data, size_t length)
{
    if (fuzz_mesh_one((const uint8_t *)data, length) != 0)
        fail_msg("mesh/%s: the library broke a promise on this input", name);
}

/* Replays every file of dir but hidden ones and the folder mesh/ through
 * each; returns how many. */
static int replay(const char *dir_path,
                  void (*each)(const char *name, const char *data, size_t length))
{
    DIR *dir = opendir(dir_path);
    assert_non_null(dir);
    int replayed = 0;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL) {
        if (entry->d_name[0] == '.' || strcmp(entry->d_name, "mesh") == 0)
            continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir_path, entry->d_name);
        size_t length = 0;
        char *data = read_all(path, &length);
        assert_non_null(data);
        each(entry->d_name, data, length);
        free(data);
        replayed++;
    }
    closedir(dir);
    return replayed;
}

static void test_replay_all(void **state)
{
    (void)state;
    int replayed = replay(folder, replay_csg);
    print_message("replayed %d fuzzer findings\n", replayed);
    assert_true(replayed > 0);
}

/* The mesh readers' findings; none is no failure (that fuzzer has found
 * nothing yet), but the folder is there for the first. */
static void test_replay_meshes(void **state)
{
    (void)state;
    print_message("replayed %d mesh reader findings\n", replay(mesh_folder, replay_mesh));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_replay_all),
        cmocka_unit_test(test_replay_meshes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
