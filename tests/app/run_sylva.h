#pragma once
// Runs a shell command (or the sylva binary under test) and returns its exit code and merged
// stdout/stderr, for tests of the command-line contract.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace sylva::test {

struct command_result {
    int exit_code = -1;
    std::string output;
};

inline command_result run_command(const std::string& command) {
    command_result r;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    std::array<char, 4096> buffer{};
    while (pipe && fgets(buffer.data(), int(buffer.size()), pipe)) r.output += buffer.data();
    const int status = pipe ? pclose(pipe) : -1;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// The binary under test: the one built by this tree (SYLVA_BINARY, set by tests/CMakeLists.txt),
// or $SYLVA_TEST_BINARY, to run a contract test against another build (an older commit's, to
// show the test fails there).
inline std::string sylva_binary() {
    const char* other = std::getenv("SYLVA_TEST_BINARY");
    return other && *other ? other : SYLVA_BINARY;
}

// `arguments` after the binary under test.
inline command_result run_sylva(const std::string& arguments) {
    return run_command(sylva_binary() + " " + arguments);
}

// An empty folder of its own under the system's temporary directory (per process, so parallel
// test runs do not meet), created afresh.
inline std::filesystem::path fresh_temp_dir(const std::string& name) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("sylva_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// A file's bytes (to compare two exports).
inline std::string bytes_of(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The Khronos glTF validator's report on `file` (tests/tools/validate_gltf.mjs), or nothing when
// node or the package is missing (./sylva test installs it).
inline std::optional<nlohmann::json> validate_gltf(const std::filesystem::path& file) {
    namespace fs = std::filesystem;
    const fs::path tools = fs::path(SYLVA_SOURCE_DIR) / "tests" / "tools";
    if (run_command("node --version").exit_code != 0 || !fs::exists(tools / "node_modules" / "gltf-validator"))
        return std::nullopt;
    const command_result r = run_command("node " + (tools / "validate_gltf.mjs").string() + " " + file.string());
    const auto report = nlohmann::json::parse(r.output, nullptr, false);
    if (report.is_discarded()) return nlohmann::json{{"unparsed", r.output}};
    return report;
}

}  // namespace sylva::test
