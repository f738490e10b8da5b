/* libFuzzer target of the split parse: see split_harness.h.
 *
 * Each input is parsed and lowered whole, then split in two threads at a
 * place that a hash of the input picks, so that the corpus's mutations
 * move the place too. A difference between the two (status, message,
 * model, warnings) aborts, which libFuzzer reports as a crash like any
 * sanitizer finding (the library is built with address and undefined
 * behaviour sanitizers, fuzz/CMakeLists.txt).
 */
#include <stdlib.h>

#include "split_harness.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 2)
        return 0;
    int split;
    const char *text = (const char *)data;
    if (split_one(text, size, split_place(text, size), &split) != 0)
        abort();
    return 0;
}
