#pragma once
// The plant library: every species preset Sylva can generate, as a complete plant_model (three
// mesh levels, leaf and bark textures, per-triangle structure). Trees and the shrub come from
// the Weber & Penn generator (models/generate/tree_generator.h), grass, flower and fern from their own
// small generators.
#include <array>
#include <cstdint>
#include <string_view>

#include "models/plant_model.h"

namespace sylva {

// Every preset generate_plant_model accepts.
//   broadleaf     game-ready oak-like tree, <= 8,000 triangles at full detail
//   broadleaf_hd  the same species at film detail, 100,000-200,000 triangles at full detail
//   conifer       spruce-like tree with needle-shoot cards (part_kind::needle)
//   shrub         multi-stemmed bush ~2.5 m, stems from the ground
//   grass         tuft of 24-36 blade strips (part_kind::blade); no bark sub-mesh at any level
//   flower        meadow flower ~0.5 m; petals (part_kind::petal) and leaves share an atlas
//   fern          arching fronds of pinnae cards (part_kind::frond); no bark at reduced and far
inline constexpr std::array<std::string_view, 7> k_plant_presets = {"broadleaf", "broadleaf_hd", "conifer", "shrub",
                                                                    "grass",     "flower",       "fern"};

// All three levels (full, reduced ~10 %, far ~3-5 % of the triangles for the trees; the small
// plants keep a few dozen triangles at least) and both textures at texture_size x texture_size.
// lods[i].parts and lods[i].leaves are filled, has_hierarchy is true. Same preset and seed give
// a byte-identical model. Throws std::invalid_argument naming an unknown preset and the valid
// ones.
plant_model generate_plant_model(std::string_view preset, std::uint64_t seed, std::uint32_t texture_size);

}  // namespace sylva
