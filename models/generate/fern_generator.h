#pragma once
// A fern: a rosette of arching fronds, each a green rachis with many pinnae cards.
#include <cstdint>

#include "models/mesh.h"
#include "models/generate/tree_generator.h"

namespace sylva {

// Standing on the origin, up +y. Bark sub-mesh (the rachises, stem texture; none at reduced
// and far detail) then leaf sub-mesh (pinnae, part_kind::frond). Frond i is stem i: rachis
// triangles have branch = parent_branch = i, level 0; its pinnae branch = parent_branch = i,
// level 1. Reduced detail keeps 3 pairs of larger pinnae per frond, far detail one card per frond
// along its rachis, both at the full leaf area. Byte-identical for the same seed.
mesh_data generate_fern(std::uint64_t seed, tree_detail detail);

}  // namespace sylva
