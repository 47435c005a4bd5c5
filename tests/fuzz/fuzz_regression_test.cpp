// Every input the fuzzers ever crashed on (tests/fuzz/regressions/<target>/, committed with the
// fix) replayed through the same target functions with the normal compiler, so CI keeps each
// fixed crash fixed without clang or libFuzzer. fuzz/run_fuzzers copies new crash inputs here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/fuzz_targets.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> inputs_of(const std::string& target) {
    std::vector<fs::path> files;
    const fs::path dir = fs::path(SYLVA_SOURCE_DIR) / "tests" / "fuzz" / "regressions" / target;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::string bytes_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(fuzz_regression, scenario_loader_survives_every_recorded_crash_input) {
    const auto files = inputs_of("scenario_loader");
    EXPECT_FALSE(files.empty());
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.filename().string());
        const std::string bytes = bytes_of(file);
        fuzz::scenario_loader(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
    }
}

TEST(fuzz_regression, gltf_import_survives_every_recorded_crash_input) {
    const auto files = inputs_of("gltf_import");
    EXPECT_FALSE(files.empty());
    const fs::path folder = fs::path(SYLVA_SOURCE_DIR) / "tests" / "fuzz" / "regressions" / "gltf_import";
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.filename().string());
        const std::string bytes = bytes_of(file);
        fuzz::gltf_import(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), folder);
    }
}

}  // namespace
}  // namespace sylva
