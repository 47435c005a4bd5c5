#pragma once
// A grass tuft: 15-40 long, thin, curved blades from one clump, each a narrow strip of a few
// quads (later drawn as lines by the representations that want them).
#include <cstdint>

#include "models/mesh.h"
#include "models/generate/tree_generator.h"

namespace sylva {

// Standing on the origin, up +y. Only a leaf sub-mesh: grass has no bark. Every blade is its
// own stem (parts: branch = parent_branch = blade index, level 0, part_kind::blade) and has one
// leaf record. Reduced and far detail keep every 4th / 8th blade, with fewer segments, widened
// so the blade area is unchanged. Byte-identical for the same seed.
mesh_data generate_grass(std::uint64_t seed, tree_detail detail);

}  // namespace sylva
