#pragma once
// The bytes of a glTF file on their way to tinygltf, checked first: the file is a regular file
// of bounded size, a .glb's header and chunks agree with its size, the JSON nests no deeper than
// k_max_gltf_depth (tinygltf parses nested values recursively), and every external buffer or
// image URI names a file inside the model's folder (io/confined_path.h). tinygltf then reads
// those files through callbacks that enforce the same confinement and size limits.
#include <filesystem>
#include <string>
#include <string_view>

#include "models/gltf/gltf_tinygltf.h"

namespace sylva {

// Real models nest about 6 levels (meshes/0/primitives/0/attributes); extras from modelling
// tools add a few. 256 keeps tinygltf's recursion far from the end of the stack.
inline constexpr std::size_t k_max_gltf_depth = 256;

struct gltf_source {
    std::string name;                  // for messages: the file's name
    std::filesystem::path folder;      // external files must be inside it (absolute)
    bool binary = false;               // .glb
    std::string bytes;
};

// Reads `file` (.gltf or .glb by extension). Throws std::runtime_error (input_error for an
// unreadable or oversized file) naming the file.
gltf_source read_gltf_source(const std::filesystem::path& file);

// Parses the source into `model` with tinygltf, images decoded (OpenImageIO, dimensions
// bounded). Throws std::runtime_error("<name>: <problem>").
void parse_gltf(const gltf_source& source, tinygltf::Model& model);

}  // namespace sylva
