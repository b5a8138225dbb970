/* libFuzzer's entry, compiled once per target with -DFUZZ_ENTRY=fuzz_NAME (tests/fuzz/fuzz.mk). */
#include "fuzz/fuzz.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return FUZZ_ENTRY(data, size); }
