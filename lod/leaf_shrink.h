#pragma once
// The simple rival LoDF is judged against at equal leaf count (issue 23): the leaves in one
// fixed random order, the first N drawn, each survivor scaled about its centre by √(L / N) so
// the foliage keeps its area, as engines thin a crown with distance (SpeedTree's leaf LOD;
// Weber & Penn 1995's "degradation at range", which models/generate/tree_generator.cpp's
// reduced levels follow). Unlike LoDF it moves vertices, so a change of detail re-uploads them.
#include <cstdint>

#include "models/mesh.h"

namespace sylva {

// `full` with its foliage (models/bake/lodf_leaves.h's leaves) cut to the first `leaves` of a
// random order drawn from `seed` (every leaf when `leaves` is 0 or at least their number),
// survivors enlarged to keep the foliage's area; other submeshes as they are, then one leaf
// submesh. Per-triangle parts and leaf records are dropped.
mesh_data leaf_shrink_mesh(const mesh_data& full, std::uint32_t leaves, std::uint64_t seed);

}  // namespace sylva
