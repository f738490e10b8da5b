/* libFuzzer target over the whole load path: see harness.h.
 *
 * Built only with -DSPANCAST_FUZZ=ON under clang (fuzz/CMakeLists.txt),
 * where the library itself is compiled with -fsanitize=fuzzer-no-link,
 * address,undefined so that coverage guides the fuzzer through the lexer,
 * parser, builder and compile. A broken promise of the library (harness.h)
 * aborts, which libFuzzer reports as a crash like any sanitizer finding.
 */
#include <stdlib.h>

#include "harness.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (fuzz_one(data, size) != 0)
        abort();
    return 0;
}
