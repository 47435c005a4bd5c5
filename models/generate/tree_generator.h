#pragma once
// Procedural trees after Weber & Penn 1995, "Creation and rendering of realistic trees",
// SIGGRAPH: a recursive hierarchy of tapered, curved stems with leaves on the last level,
// meshed at two detail levels from the same skeleton.
#include <cstdint>

#include "models/mesh.h"
#include "models/generate/tree_params.h"

namespace sylva {

enum class tree_detail : std::uint8_t {
    full,     // every stem level, full sides and segments, one card per leaf
    reduced,  // ~10% of the triangles: coarser stems, no last-level stems, fewer larger leaves
    far,      // ~4%: the trunk and a hundred or so large leaf cards, for trees hundreds of metres away
};

// A tree standing on the origin, growing up +y (trunk base at y = 0). parts names each
// triangle's stem (skeleton index), level and parent stem; leaves holds one record per card
// (part_kind::needle for needle_cluster leaves, else leaf). Two sub-meshes: bark
// (material_kind::bark) then leaves (material_kind::leaf), each a contiguous index range. Leaf
// cards are single-sided quads with uv 0..1 over the leaf texture: u across the leaf, v = 0 at
// the tip (the top row of the texture) and 1 at the base. Same params and seed give a
// byte-identical mesh.
mesh_data generate_tree(const tree_params& params, std::uint64_t seed, tree_detail detail);

}  // namespace sylva
