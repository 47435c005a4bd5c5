#pragma once
// Output files are written whole or not at all: the bytes go to a temporary file next to the
// target, every write and the close are checked, then the temporary file is renamed over the
// target. A crash, an interrupt or a full disk never leaves a half-written frame, metrics.json,
// glTF file or cache entry, and a failure is an error naming the path, never a silent loss.
#include <cstddef>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string_view>

namespace sylva {

// An output that could not be written; what() names the path and the reason.
class output_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws output_error naming `path` when the file cannot be written: its folder is missing or
// read-only, the disk is full, or `path` is something other than a regular file (a directory, a
// device such as /dev/full): those are refused rather than replaced.
void write_atomically(const std::filesystem::path& path, std::string_view content);
void write_atomically(const std::filesystem::path& path, std::span<const std::byte> content);

}  // namespace sylva
