#pragma once
// Output files are written whole or not at all: a temporary file next to the target, then a
// rename over it, so a crash or a full disk never leaves a half-written metrics.json or bench.json.
#include <filesystem>
#include <string>

namespace sylva {

// Throws std::runtime_error naming `path` when the file cannot be written.
void write_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace sylva
