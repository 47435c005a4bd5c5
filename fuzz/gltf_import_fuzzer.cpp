// libFuzzer entry for the glTF importer (fuzz/fuzz_targets.h). External URIs resolve in
// $SYLVA_FUZZ_MODEL_DIR (fuzz/run_fuzzers points it at the seed fixtures' folder, so their
// .bin and image files are there to be read), else the current folder. It reads the file
// (gltf_import_stage::read) unless SYLVA_FUZZ_WHOLE_PLANT=1 asks for the whole import.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include "fuzz/fuzz_targets.h"

namespace {

std::filesystem::path model_folder() {
    const char* dir = std::getenv("SYLVA_FUZZ_MODEL_DIR");
    return std::filesystem::absolute(dir && *dir ? dir : ".");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::filesystem::path folder = model_folder();
    static const bool whole_plant = std::getenv("SYLVA_FUZZ_WHOLE_PLANT") != nullptr &&
                                    std::string_view(std::getenv("SYLVA_FUZZ_WHOLE_PLANT")) == "1";
    sylva::fuzz::gltf_import(data, size, folder, whole_plant);
    return 0;
}
