#pragma once
// The transfer of a plant's coarser mesh levels taken from its full mesh's (Behrendt 2005 §4:
// "Using the same spherical harmonic coefficients for all levels, overcomes this problem and
// results in a coherent solution").
//
// Why not ray-cast the coarse levels' own vertices: a reduced or far level draws fewer, larger
// leaf cards whose corners reach out of the crown, so their own transfer is much brighter than
// the full crown's. Measured on broadleaf_hd at 40 m, lit by SH: the far level's crown was
// visibly lighter than the full mesh's, which made every level switch a lighting jump (the
// time_of_day bench: 7.3 against 4.2 normal-lit). Each coarse receiver instead averages the
// transfer of the full-mesh vertices nearest to it, so a level shows the full plant's light.
#include <cstdint>
#include <span>

#include "models/mesh.h"
#include "models/bake/radiance_transfer.h"

namespace sylva {

// Each receiver's transfer is the mean over the k vertices of `full` nearest to its position
// (a kd-tree, nanoflann) of their transfer, each turned to the receiver's side: a full vertex
// whose normal faces away from the receiver's (negative dot product) gives its back as the
// front and its front as the back. Deterministic (each receiver on its own). Throws
// std::invalid_argument when `full_transfer` is not one receiver per vertex of `full` or k is 0.
radiance_transfer resample_transfer(const mesh_data& full, const radiance_transfer& full_transfer,
                                    std::span<const vertex> receivers, std::uint32_t k = 8);

}  // namespace sylva
