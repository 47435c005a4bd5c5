#pragma once
// Reading what users hand us. Every input file is checked to be a regular file no larger than
// a limit before a byte of it is trusted, so /dev/zero, a FIFO or a directory gets a clear error
// instead of an endless read, a hang or a crash, and nothing is allocated for a size the file
// does not have.
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace sylva {

// An input that cannot be used as it is; what() names the file and the problem.
class input_error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Limits on what one input may weigh. Generous for real data, far below what would exhaust
// memory: a scenario is a few kilobytes, the largest real tree models a few hundred megabytes.
inline constexpr std::uint64_t k_max_scenario_bytes = 16ull << 20;
inline constexpr std::uint64_t k_max_model_bytes = 1ull << 30;  // a .glb, .gltf or one of its files
inline constexpr std::uint64_t k_max_image_bytes = 512ull << 20;

// Images are decoded only when their header's dimensions are within these: a 100-byte PNG can
// claim 30000 x 30000 pixels. 8192 x 8192 (64 M pixels) holds every texture, heightmap and
// environment map Sylva is meant for.
inline constexpr std::uint64_t k_max_image_side = 16384;
inline constexpr std::uint64_t k_max_image_pixels = 8192ull * 8192ull;

// Throws input_error("<path>: <problem>") unless `path` names a readable regular file of at most
// `max_bytes` bytes (symbolic links are followed). Returns its size.
std::uint64_t check_input_file(const std::filesystem::path& path, std::uint64_t max_bytes);

// The whole file, after the same checks; reads at most max_bytes (a file that grows while it is
// read is refused too).
std::string read_input_file(const std::filesystem::path& path, std::uint64_t max_bytes);

// Throws input_error("<what>: <w>x<h> pixels ...") when an image header's dimensions are zero,
// negative or beyond k_max_image_side / k_max_image_pixels.
void check_image_dimensions(const std::string& what, long long width, long long height);

}  // namespace sylva
