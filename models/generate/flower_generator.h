#pragma once
// A meadow flower, 0.4-0.8 m: a slender green stem, a few leaves and a blossom of coloured
// petals round a centre disc. Leaves and petals share one atlas (models/generate/plant_textures.h).
#include <cstdint>

#include "models/mesh.h"
#include "models/generate/tree_generator.h"

namespace sylva {

// Standing on the origin, up +y. Bark sub-mesh (the stem, stem texture) then leaf sub-mesh
// (leaves: part_kind::leaf; petals and centre disc: part_kind::petal). One stem: every part has
// branch = parent_branch = 0; foliage is level 1. Reduced and far detail coarsen the stem and
// use fewer, larger leaves and petals at the same area; the blossom keeps its outline, since
// petals are what a viewer notices. Byte-identical for the same seed.
mesh_data generate_flower(std::uint64_t seed, tree_detail detail);

}  // namespace sylva
