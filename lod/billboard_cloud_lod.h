#pragma once
// The billboard-cloud level of detail (Behrendt 2005 §2.3) as pure functions of distance, used by
// select_representation and mirrored by the cloud's fragment shader:
//
//   distance:   0 ...... mesh levels ...... | cloud band | ..... cloud ..... | far band | ... crossed
//                                          C(1-h)     C(1+h)             F(1-h)     F(1+h)
//
// C is lod_policy::cloud_distance_m ("we have to blend to the complex representation, if a
// typical tree is closer than 30 meters"), F the species' far_distance_m (beyond which the paper
// shows "only the simple representations": two crossed billboards), both times the plant's scale
// and the camera's lod_scale, and h = k_cloud_band. Across a band at parameter t in [0, 1] the
// nearer representation is drawn whole for t < 1/2 and fades out over the second half, the
// farther one fades in over the first half and is drawn whole beyond: the two overlap, so the
// plant never thins out in the middle of a transition, and neither is sorted or blended.
#include "components/lod_state.h"
#include "lod/ladder.h"
#include "resources/scene_assets.h"

namespace sylva {

// Half-width of each transition band as a fraction of its switch distance.
inline constexpr float k_cloud_band = 0.15f;

// What a plant is drawn as at one distance: the primary representation whole, and during a band
// a partner at partner_fade (0 none .. 1 whole); the same choice a ladder makes by size.
using cloud_lod_choice = ladder_choice;

// The cloud's switch distance for a species at scale 1 and lod_scale 1: cloud_distance_m, but
// never so close to the far distance that the two bands overlap (a small plant with a short far
// distance goes from the cloud band straight on to the far band).
float cloud_switch_distance(const species_entry& species, float cloud_distance_m);

// The choice at `distance_m` (a NaN distance takes the far side, like choose_representation).
cloud_lod_choice choose_cloud_lod(const species_entry& species, float cloud_distance_m, float distance_m,
                                  float scale, float lod_scale);

// Behrendt 2005 §2.3's modified alpha test: a cloud fragment is discarded when its colour page's
// alpha (coverage x gaussian, models/bake/billboard_cloud.h) is below this threshold, a piecewise-
// linear function of the cloud's fade, itself piecewise-linear in distance (choose_cloud_lod):
//
//   threshold  1.02 +.                        fade 0: above any alpha, nothing left
//                   |   `--.__
//              0.90 +         `--.__          the knots: coverage of broadleaf_hd's cloud at
//              0.75 +               `.        30 m falls about linearly with fade (measured:
//                   |                 `.      1, 0.82, 0.51, 0.25, 0 at fade 1, 3/4, 1/2,
//              0.18 +                   `.    1/4, 0); billboards overlap, so their gaussian
//                   +----+----+----+----+     edges go first without opening holes
//                   0   1/4  1/2  3/4   1 fade
//
// At fade 1 the threshold is the least colour alpha a covered texel can have (coverage 0.5,
// the normal page's alpha test, times the gaussian's e^-1 at a corner for σ = 1), so only
// coverage decides. Mirrored in shaders/cloud.frag; keep both in sync.
inline constexpr float k_cloud_threshold_shown = 0.18f;
inline constexpr float k_cloud_threshold_gone = 1.02f;
float cloud_alpha_threshold(float fade);

}  // namespace sylva
