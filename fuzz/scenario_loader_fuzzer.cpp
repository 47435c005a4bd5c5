// libFuzzer entry for the scenario loader (fuzz/fuzz_targets.h).
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    sylva::fuzz::scenario_loader(data, size);
    return 0;
}
