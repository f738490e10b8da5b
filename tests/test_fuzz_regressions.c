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

static void test_replay_all(void **state)
{
    (void)state;
    DIR *dir = opendir(folder);
    assert_non_null(dir);
    int replayed = 0;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL) {
        if (entry->d_name[0] == '.' || strcmp(entry->d_name, "mesh") == 0)
            continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", folder, entry->d_name);
        size_t length = 0;
        char *text = read_all(path, &length);
        assert_non_null(text);
        int result = fuzz_one((const uint8_t *)text, length);
        if (result != 0)
            fail_msg("%s: the library broke a promise on this input", entry->d_name);
        /* the split parse where fuzz_split splits it */
        int split;
        if (length >= 2 &&
            split_one(text, length, split_place(text, length), &split) != 0)
            fail_msg("%s: split in two, the parse differs from a whole one",
                     entry->d_name);
        free(text);
        replayed++;
    }
    closedir(dir);
    print_message("replayed %d fuzzer findings\n", replayed);
    assert_true(replayed > 0);
}

/* The mesh readers' findings; none is no failure (that fuzzer has found
 * nothing yet), but the folder is there for the first. */
static void test_replay_meshes(void **state)
{
    (void)state;
    DIR *dir = opendir(mesh_folder);
    assert_non_null(dir);
    int replayed = 0;
    struct dirent *entry;
    while ((entry = readdir(dir)) != NULL) {
        if (entry->d_name[0] == '.')
            continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", mesh_folder, entry->d_name);
        size_t length = 0;
        char *data = read_all(path, &length);
        assert_non_null(data);
        if (fuzz_mesh_one((const uint8_t *)data, length) != 0)
            fail_msg("mesh/%s: the library broke a promise on this input", entry->d_name);
        free(data);
        replayed++;
    }
    closedir(dir);
    print_message("replayed %d mesh reader findings\n", replayed);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_replay_all),
        cmocka_unit_test(test_replay_meshes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
