#pragma once
// glTF 2.0 plants (.gltf and .glb) made by other tools, turned into a plant_model: the node
// hierarchy flattened with its transforms, every triangle primitive classified as leaf or bark
// by its own evidence (texture alpha, colour, connectivity), leaf textures merged into one
// atlas, the reduced and far levels built, centimetre models converted to metres. glTF is
// y-up like Sylva, so no axis change is needed.
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
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
    // Zero-area triangles (repeated indices, coincident or collinear vertices) left out at
    // import, so they are never drawn; each primitive that lost some is named in `warnings`.
    std::uint32_t dropped_degenerate_triangles = 0;
};

// A triangle has zero area (a line or a point: nothing to rasterise, no normal) when twice its
// area is at most this fraction of its longest edge squared, i.e. its height is below a
// millionth of its longest edge. Repeated indices, coincident vertices and exactly collinear
// points give 0; the thinnest real foliage (a 1 mm grass blade 1 m long) is at 1e-3.
inline constexpr double k_zero_area_height_ratio = 1e-6;
bool is_zero_area_triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c);

// Throws std::runtime_error whose message names the file and the part for broken or
// unsupported files: bad JSON, missing buffers, non-triangle primitives, no meshes, NaN or
// infinite positions (the message names the mesh, primitive, vertex index and value), no
// triangle with area. A missing texture file is only a warning: the base-colour factor is
// used instead. Zero-area triangles (is_zero_area_triangle, after the node transforms) are
// dropped with a warning naming the file and primitive and counted in
// dropped_degenerate_triangles, so they are never drawn. Every texture of the result is
// texture_size x texture_size.
// Files are read as models/gltf/gltf_container.h says: bounded in size and nesting, external URIs
// confined to the model's folder, indices read exactly, every accessor checked against its
// buffer before anything is allocated for it, images bounded before they are decoded.
gltf_import_result import_gltf_plant(const std::filesystem::path& file, std::uint32_t texture_size);
// How far import_gltf_source goes: the whole plant, or only reading the file (container,
// JSON, accessors, indices, nodes, materials and images: everything the file's bytes decide)
// before the plant is built from its checked geometry. The fuzz target runs `read`: that is
// where hostile bytes are interpreted, at a hundred times the rate of a whole import.
enum class gltf_import_stage { plant, read };

// The same for a file already read (read_gltf_source); the fuzz target feeds bytes here. With
// gltf_import_stage::read the result's model is empty.
struct gltf_source;
gltf_import_result import_gltf_source(const gltf_source& source, std::uint32_t texture_size,
                                      gltf_import_stage stage = gltf_import_stage::plant);

plant_model import_plant_model(const std::filesystem::path& file, std::uint32_t texture_size);

}  // namespace sylva
