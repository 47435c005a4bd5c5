#pragma once
// The paper's comparison (Rebollo 2006 §5, Figures 10-11): traverse every level of detail with a
// uniform step, from F_0 to the coarsest and back, and at each change measure what LoDF extracts
// and uploads against re-extracting and re-uploading the whole foliage (the update of VDF,
// Remolar 2003, which keeps no clusters).
//
//   LoDF: retarget_lodf over Changed_group, then one glMultiDrawElementsIndirect command per
//         changed cluster (20 bytes) rewritten: the foliage's indices never move.
//   whole: the collapses or splits applied to a flag per leaf of F^r, then every active leaf's
//         indices copied into a fresh index list, all of which is uploaded.
#include <cstdint>
#include <vector>

#include "lod/lodf.h"
#include "models/bake/lodf_bake.h"

namespace sylva {

struct traversal_change {
    std::uint32_t leaves = 0;          // drawn after the change
    std::uint32_t clusters_changed = 0;
    std::uint64_t lodf_bytes = 0;      // commands rewritten
    std::uint64_t whole_bytes = 0;     // indices re-extracted
    double lodf_ns = 0.0;
    double whole_ns = 0.0;
};

// The levels a traversal visits: `steps` uniform steps from 0 collapses to all of them, then
// back to 0 (2·steps changes).
std::vector<std::uint32_t> traversal_levels(const lodf_structure& lodf, std::uint32_t steps);

// One traversal through `levels` (starting at F_0), both ways, each change timed on its own.
// `verify`: also checks after each change, outside the timings, that both ways draw the same
// index multiset, and throws std::logic_error if not.
std::vector<traversal_change> traverse_lodf(const lodf_model& model, const std::vector<std::uint32_t>& levels,
                                            bool verify);

}  // namespace sylva
