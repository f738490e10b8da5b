/* libFuzzer target over the mesh readers: see mesh_harness.h. Built as
 * fuzz_load is (fuzz/CMakeLists.txt). */
#include <stdlib.h>

#include "mesh_harness.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (fuzz_mesh_one(data, size) != 0)
        abort();
    return 0;
}
