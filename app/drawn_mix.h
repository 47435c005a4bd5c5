#pragma once
// What each plant is drawn as in the frame just played, read from the ECS state the frame's
// systems wrote, as the codes measure/transition_windows.h compares frame to frame:
//
//   how the plant is drawn                         primary            partner   share / detail
//   culled                                         k_not_drawn        -         -
//   one representation whole                       its representation -         -
//   in a fade or dissolve band (fade_alpha)        the whole one      the faded one, its fade
//   points and lines (Deussen 2002 §5)             points             -         triangles drawn
//                                                                               as triangles, of
//                                                                               all its parts';
//                                                                               line parts drawn
//                                                                               as splats
//   in an eco tile's aggregated set (§6.2)         k_mix_eco_tile_set points in  group = the tile;
//                                                                     the tile's  the share its
//                                                                     band        own points draw
//
// So a hard switch changes the mix in one frame, a band changes it every frame of the band,
// §5.3's blend every frame until each part has settled on triangles or points, and the
// aggregation of a tile changes the group its plants are drawn in. A representation's own
// level of detail that is no handover (how many points a far plant draws) is not in the mix.
#include <vector>

#include "ecs/world.h"
#include "measure/transition_windows.h"

namespace sylva {

// The primary code of a plant drawn by its eco tile's aggregated point set (lod_state's eco_tile;
// apart from the representations so that a tile's plants share one group).
inline constexpr std::uint8_t k_mix_eco_tile_set = 0xE0;

// One mix per plant (dense index), in `out` (resized).
void read_drawn_mixes(const ecs::world& world, std::vector<drawn_mix>& out);

// Which kind of transition a window is: a handover to or from an eco tile's set, a fade or
// dissolve band, a hard switch between representations, or a blend within one (§5.3).
const char* transition_kind(const transition_window& w);

}  // namespace sylva
