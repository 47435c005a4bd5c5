#pragma once
// glTF 2.0 plants (.gltf and .glb) made by other tools, turned into a plant_model: the node
// hierarchy flattened with its transforms, every triangle primitive classified as leaf or bark
// by its own evidence (texture alpha, colour, connectivity), leaf textures merged into one
// atlas, the reduced and far levels built, centimetre models converted to metres. glTF is
// y-up like Sylva, so no axis change is needed.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "models/plant_model.h"

namespace sylva {

// What the importer decided about one source primitive, and why (printed by `sylva inspect`).
struct gltf_primitive_report {
    std::string label;     // "mesh 'leaves' primitive 2"
    std::string material;  // source material name, or "(default)"
    bool leaf = false;
    float alpha_ratio = 0;              // fraction of its base-colour texels with alpha < 0.5
    bool green = false;                 // the mean texture x factor colour reads as foliage
    std::uint32_t components = 0;       // connected pieces (welded by position)
    float largest_component_share = 0;  // of its triangles
    std::uint32_t triangles = 0;
};

struct gltf_import_result {
    plant_model model;
    std::vector<gltf_primitive_report> primitives;
    std::vector<std::string> materials;  // every source material name, in file order
    std::uint32_t mesh_nodes = 0;        // nodes that carry a mesh
    std::uint32_t hierarchy_depth = 0;   // longest chain of nested nodes with meshes
    std::vector<std::string> warnings;   // missing textures and the like (also logged)
};

// Throws std::runtime_error whose message names the file and the part for broken or
// unsupported files: bad JSON, missing buffers, non-triangle primitives, no meshes, non-finite
// positions. A missing texture file is only a warning: the base-colour factor is used instead.
// Every texture of the result is texture_size x texture_size.
gltf_import_result import_gltf_plant(const std::filesystem::path& file, std::uint32_t texture_size);

plant_model import_plant_model(const std::filesystem::path& file, std::uint32_t texture_size);

}  // namespace sylva
