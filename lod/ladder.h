#pragma once
// A species' representation ladder (DESIGN §1.5) as pure functions of projected size: its rungs
// nearest first, each taking over when the plant's projected size falls below the rung's switch
// size in pixels, so a ladder means the same at any resolution and field of view:
//
//   projected size:  large ..... rung 0 ..... | band 1 | ..... rung 1 ..... | band 2 | ... rung 2 ...
//                                          S1(1+h1)  S1(1-h1)           S2(1+h2)  S2(1-h2)
//
// S_i is rung i's `below_px`, h_i its band's half-width as a fraction of S_i (0: a hard switch).
// Across a band, at t in [0, 1] from its large edge, the nearer rung is drawn whole for t < 1/2
// and fades out over the second half while the farther one fades in over the first half and is
// drawn whole beyond (the overlap of Behrendt 2005 §2.3, lod/billboard_cloud_lod.h): the plant
// never thins out in the middle of a transition, and neither side is sorted or blended. How the
// faded side fades is its representation's own way: a billboard cloud by Behrendt's Gaussian
// alpha threshold (§2.3), points and lines by Deussen's prefix (§5.3: the first `fade` of the
// randomly ordered samples, so the thinning is uniform over the plant), a mesh or a crossed
// billboard by a stable screen-door dissolve (shaders/mesh.frag). Only the primary casts shadows,
// so a plant in a band casts once. The step from the full mesh into LoDF has no band
// (seamless_step below): LoDF whole is the full mesh's foliage, so the switch changes nothing.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "components/lod_state.h"

// The names, the struct and its validation are inline: the scenario loader (sylva_scenarios, which
// does not link the runtime) checks a scenario's ladders with them and names the JSON path.

namespace sylva {

inline constexpr std::size_t k_max_rungs = 8;
// Behrendt 2005 §2.3's band for the cloud (lod/billboard_cloud_lod.h k_cloud_band).
inline constexpr float k_default_band = 0.15f;
inline constexpr float k_max_band = 0.9f;

// The rungs a ladder may name, as scenarios name them: every representation a plant can be drawn
// with ("points_lines" is representation::points; "eco_tile_points" is the plant drawn by its eco
// tile's aggregated sets, Deussen 2002 §6.2, which can only follow points_lines as the last rung:
// a tile that cannot be drawn as its sets draws its plants as points).
inline constexpr std::array<std::string_view, 10> k_rung_names{
    "mesh_full",         "mesh_reduced",    "mesh_far", "billboard_cloud", "points_lines",
    "crossed_billboard", "eco_tile_points", "lodf",     "shell",           "facing_billboard"};
inline constexpr std::array<representation, k_rung_names.size()> k_rungs{
    representation::mesh_full,       representation::mesh_reduced, representation::mesh_far,
    representation::billboard_cloud, representation::points,       representation::crossed_billboard,
    representation::eco_tile,        representation::lodf,         representation::shell,
    representation::facing_billboard};

// "" when `r` is not a rung.
inline std::string_view rung_name(representation r) {
    for (std::size_t i = 0; i < k_rungs.size(); ++i)
        if (k_rungs[i] == r) return k_rung_names[i];
    return {};
}
inline std::optional<representation> rung_of_name(std::string_view name) {
    for (std::size_t i = 0; i < k_rungs.size(); ++i)
        if (k_rung_names[i] == name) return k_rungs[i];
    return std::nullopt;
}

struct ladder {
    std::array<representation, k_max_rungs> rungs{};
    // below_px[i], i >= 1: rung i takes over below this projected size (strictly decreasing);
    // below_px[0] is unused.
    std::array<float, k_max_rungs> below_px{};
    std::array<float, k_max_rungs> band{};  // band[i]: half-width of the step into rung i
    // shadow[i]: what a plant on rung i casts its shadow as, another of the ladder's mesh-drawn
    // rungs (a near tree's leaves cost more in its shadow cascade than in the view); none: itself.
    std::array<representation, k_max_rungs> shadow{};
    std::uint8_t count = 0;

    bool reaches(representation r) const {
        return std::find(rungs.begin(), rungs.begin() + count, r) != rungs.begin() + count;
    }
    // Whether some rung casts its shadow as `r` (so `r` is drawn, in shadow maps, at least).
    bool casts(representation r) const {
        return std::find(shadow.begin(), shadow.begin() + count, r) != shadow.begin() + count;
    }
    // What a plant drawn as `r` casts its shadow as. A facing billboard turns with the eye, so
    // unless its ladder names a caster it casts its crossed billboard (the same bake), whose
    // shadow stays put as the eye moves and is the same whichever of the two the plant shows.
    representation caster_of(representation r) const {
        for (std::size_t i = 0; i < count; ++i)
            if (rungs[i] == r && shadow[i] != representation::none) return shadow[i];
        return r == representation::facing_billboard ? representation::crossed_billboard : r;
    }
    bool operator==(const ladder&) const = default;
};

// The rungs drawn as one mesh per plant in every pass, which alone may cast another's shadow or
// be cast (points and lines draw prefixes, LoDF its slots, eco tiles and shells no plant).
inline bool casts_as_a_mesh(representation r) {
    return r == representation::mesh_full || r == representation::mesh_reduced || r == representation::mesh_far ||
           r == representation::billboard_cloud || r == representation::crossed_billboard ||
           r == representation::facing_billboard;
}

// Whether the step from `nearer` into `farther` is seamless without a band: LoDF whole draws
// exactly the full mesh's leaves (Rebollo 2006 §3: every leaf of the model is a leaf of the
// sequence's finest level) over the same bark, and it thins from there, so the switch at its top
// changes no pixel and a fade would only draw the plant twice.
inline bool seamless_step(representation nearer, representation farther) {
    return nearer == representation::mesh_full && farther == representation::lodf;
}

// Why a ladder cannot be used, and the rung at fault.
struct ladder_problem {
    std::size_t rung = 0;
    std::string_view field;  // "rung", "below_px", "band", or "" for the ladder itself
    std::string what;
};

// Its problem, or nothing when `l` is usable: at least one rung, each a rung named once, switch
// sizes positive and strictly decreasing, bands in [0, k_max_band] that do not overlap.
inline std::optional<ladder_problem> find_ladder_problem(const ladder& l) {
    if (l.count == 0) return ladder_problem{0, "", "a ladder needs at least one rung"};
    if (l.count > k_max_rungs) return ladder_problem{k_max_rungs, "", "a ladder has at most 8 rungs"};
    for (std::size_t i = 0; i < l.count; ++i) {
        if (rung_name(l.rungs[i]).empty()) return ladder_problem{i, "rung", "not a representation a ladder can draw"};
        for (std::size_t j = 0; j < i; ++j)
            if (l.rungs[j] == l.rungs[i])
                return ladder_problem{i, "rung", std::string(rung_name(l.rungs[i])) + " is already rung " + std::to_string(j)};
        if (i == 0) continue;
        if (!(l.below_px[i] > 0.0f) || !std::isfinite(l.below_px[i]))
            return ladder_problem{i, "below_px", "below_px must be a positive number of pixels"};
        if (!(l.band[i] >= 0.0f && l.band[i] <= k_max_band))
            return ladder_problem{i, "band", "band must lie in [0, 0.9]"};
        if (seamless_step(l.rungs[i - 1], l.rungs[i]) && l.band[i] != 0.0f)
            return ladder_problem{i, "band",
                                  "lodf after mesh_full takes no band: LoDF whole draws every leaf of the full mesh, so "
                                  "the switch is seamless and a fade would draw the plant twice"};
        if (i >= 2 && !(l.below_px[i] < l.below_px[i - 1]))
            return ladder_problem{i, "below_px", "below_px must be smaller than the rung before's (" +
                                         std::to_string(l.below_px[i - 1]) + ")"};
        if (i >= 2 && l.below_px[i] * (1.0f + l.band[i]) > l.below_px[i - 1] * (1.0f - l.band[i - 1]))
            return ladder_problem{i, "band", "its band (below_px x (1 +- band)) overlaps the band of the rung before"};
    }
    for (std::size_t i = 0; i < l.count; ++i) {
        if (l.shadow[i] == representation::none) continue;
        if (!casts_as_a_mesh(l.rungs[i]) || !casts_as_a_mesh(l.shadow[i]))
            return ladder_problem{i, "shadow",
                                  "only mesh_full, mesh_reduced, mesh_far, billboard_cloud and crossed_billboard "
                                  "cast their shadows as one another"};
        if (!l.reaches(l.shadow[i]))
            return ladder_problem{i, "shadow", "the shadow must be cast as one of this ladder's own rungs"};
    }
    for (std::size_t i = 0; i < l.count; ++i)
        if (l.rungs[i] == representation::shell && (i == 0 || i + 1 != l.count))
            return ladder_problem{i, "rung",
                                  "shell must be the last rung, after at least one other (the shell draws the "
                                  "far field; the plants nearer are drawn on their own)"};
    for (std::size_t i = 0; i < l.count; ++i)
        if (l.rungs[i] == representation::eco_tile && (i == 0 || i + 1 != l.count || l.rungs[i - 1] != representation::points))
            return ladder_problem{i, "rung",
                                  "eco_tile_points must be the last rung, right after points_lines (a tile that "
                                  "cannot be drawn as its sets draws its plants as points)"};
    return std::nullopt;
}

// What a plant is drawn as at one projected size: the primary rung whole, and inside a band a
// partner at partner_fade (0 none .. 1 whole). The billboard-cloud policy's choice by distance
// is the same (lod/billboard_cloud_lod.h cloud_lod_choice).
struct ladder_choice {
    representation primary = representation::none;
    representation partner = representation::none;
    float partner_fade = 0.0f;
    bool operator==(const ladder_choice&) const = default;
};

// The choice at `size_px` (a NaN size takes the farthest rung, as a NaN distance does elsewhere).
ladder_choice choose_rung(const ladder& l, float size_px);

// Behrendt 2005 §3.3 end: the shell is one layer over the terrain that fades in by distance
// (resources/shell_view.h shell_fade_at), the same for all its plants, so a ladder's step into
// its shell rung follows the shell's fade `shell_fade` (0 nearer than its band .. 1 beyond), not
// the plant's size: below ½ the plant keeps what the rest of its ladder chooses by size (the
// shell shows through by its own fade; nothing of the plant is drawn twice), from ½ it is on the
// shell, its nearer rung's partner fading out as 2(1 − shell_fade). A ladder without a shell
// rung: choose_rung.
ladder_choice choose_rung_with_shell(const ladder& l, float size_px, float shell_fade);

// How far a plant is into its ladder's last step, points_lines -> eco_tile_points, as the share
// its eco tile's sets may draw of it (0 .. 1), from what choose_rung chose (lod_state and
// fade_alpha after select_representation). Deussen 2002 §5.3's blend is complementary: the tile
// draws this share of its sets' prefixes and the plant the rest of its own, both random
// subsets, so the density stays that of one representation. Across the band, t from its large
// edge: t = fade / 2 while points are primary, 1 − fade / 2 once the tile is.
inline float eco_tile_share(representation primary, representation partner, float partner_fade) {
    if (primary == representation::eco_tile)
        return partner == representation::points ? 1.0f - 0.5f * partner_fade : 1.0f;
    if (primary == representation::points && partner == representation::eco_tile) return 0.5f * partner_fade;
    return 0.0f;
}

// The projected height in pixels of a sphere of `radius_m` at `distance_m` from the eye: its
// diameter on the image plane (2·radius / distance) over a pixel's size there
// (2·tan(fov_y / 2) / viewport height; lod/point_line_lod.h image_plane_units).
float projected_size_px(float radius_m, float distance_m, float fov_y, float viewport_height_px);
// The same with the pixel's size on the image plane already known (once per frame, not per plant).
inline float projected_size_px(float radius_m, float distance_m, double pixel_units) {
    return float(2.0 * double(radius_m) / (double(distance_m) * pixel_units));
}

// The ladder the papers draw when a scenario names none (docs/representations/ladder.md): the
// full mesh, the reduced mesh, the billboard cloud (Behrendt 2005 §2.3: polygonal "closer than
// 30 meters"), points and lines (Deussen 2002), the crossed billboard far away.
ladder papers_ladder();

}  // namespace sylva
