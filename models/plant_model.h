#pragma once
// A plant species as the renderer and the later LOD bakes consume it, whichever way it was
// made: generated from a preset (models/generate/plant_library.h) or imported from glTF
// (models/gltf/gltf_import.h). Three mesh levels of the same plant, its textures, and what is known
// about its structure.
#include <array>
#include <cstdint>
#include <string>

#include "models/image/image.h"
#include "models/mesh.h"

namespace sylva {

// Index into plant_model::lods; the same order as tree_detail.
enum class plant_lod : std::uint8_t { full = 0, reduced = 1, far = 2 };

struct plant_model {
    std::string name;
    std::array<mesh_data, 3> lods;  // full, reduced (~10 %), far (~3-5 %) triangles
    image_rgba8 leaf_texture;       // alpha-tested foliage; may be an atlas the leaf uvs select from
    image_rgba8 bark_texture;       // opaque, repeats
    // True when every triangle of lods[full] knows its branch (generated plants, or imports
    // whose node hierarchy gave one); representations that need a hierarchy fall back to
    // geometry-only clustering when false.
    bool has_hierarchy = false;
    float source_unit_scale = 1.0f;  // 0.01 for a model authored in centimetres
};

}  // namespace sylva
