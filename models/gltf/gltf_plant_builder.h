#pragma once
// The glTF importer's second half, independent of the file format: source primitives already
// flattened into metres go in, a plant_model with one bark and one leaf sub-mesh per level
// comes out (models/gltf/gltf_import.cpp does the reading).
#include <cstdint>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

#include "models/gltf/gltf_import.h"

namespace sylva {

enum class gltf_alpha_mode : std::uint8_t { opaque, mask, blend };

struct gltf_source_material {
    std::string name;
    image_rgba8 texture;  // base-colour texture x factor; empty when it has none (or it is missing)
    glm::vec4 factor{1.0f};
    gltf_alpha_mode alpha_mode = gltf_alpha_mode::opaque;
    bool double_sided = false;
};

struct gltf_source_primitive {
    std::string label;
    std::vector<vertex> vertices;        // in metres, y-up
    std::vector<std::uint32_t> indices;  // triangle list
    int material = -1;                   // into the material list; -1: glTF's default material
    // The node that carries it, as a branch: its index, how many mesh nodes deep it sits (0 at
    // the top) and the nearest ancestor node with a mesh (itself at the top).
    std::uint32_t branch = 0;
    std::uint8_t level = 0;
    std::uint32_t parent_branch = 0;
};

// Connected components of a triangle list, vertices welded by position (cards and trunks are
// often split at uv seams). Returns each triangle's component id; `count` receives the total.
std::vector<std::uint32_t> triangle_components(const std::vector<vertex>& vertices,
                                               const std::vector<std::uint32_t>& indices,
                                               std::uint32_t& count);

// Classifies, merges textures, builds lods[0..2]. Fills model, primitives (the reports). When
// result.model.has_hierarchy is already set, lods[0].parts gets every triangle's node branch.
void build_gltf_plant(const std::vector<gltf_source_material>& materials,
                      const std::vector<gltf_source_primitive>& primitives,
                      std::uint32_t texture_size, gltf_import_result& result);

}  // namespace sylva
