#pragma once
// The fuzz targets (fuzz/README.md): one function per input format, shared by the libFuzzer
// programs (built with clang, -DSYLVA_BUILD_FUZZERS=ON) and by the regression test that replays
// every committed crash input with the normal compiler (tests/fuzz/fuzz_regression_test.cpp).
// Each returns normally for any input; a crash, a sanitizer report, or an exception other than
// the documented error escaping is a finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace sylva::fuzz {

// The scenario loader on `size` bytes of JSON text; scenario_error is the only expected outcome
// besides success.
void scenario_loader(const std::uint8_t* data, std::size_t size);

// The glTF importer on a .glb (when the bytes start with "glTF") or a .gltf, as a file in
// `folder` (external URIs resolve there); std::runtime_error (a named import error) is the only
// expected outcome besides success. `whole_plant` false stops after reading the file
// (gltf_import_stage::read): the libFuzzer program's default, at ~100x the rate.
void gltf_import(const std::uint8_t* data, std::size_t size, const std::filesystem::path& folder,
                 bool whole_plant = true);

}  // namespace sylva::fuzz
