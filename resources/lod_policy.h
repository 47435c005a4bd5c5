#pragma once
// How select_representation chooses, as a world resource: the runtime's own distance levels, the
// point/line representation (Deussen 2002), each species' representation ladder (DESIGN §1.5),
// or one of the fixed policies the bench compares them with (issue 4: "each representation on
// its own", and the typical engine baseline "full mesh near, one crossed-quad billboard beyond a
// distance, hard switch").
#include <algorithm>
#include <cstdint>
#include <vector>

#include "components/lod_state.h"
#include "lod/ladder.h"
#include "lod/point_line_lod.h"

namespace sylva {

struct lod_policy {
    enum class kind : std::uint8_t {
        distance_levels,  // the species' mesh levels by distance (select_representation_system.h)
        single,           // every drawn plant as `near`
        hard_switch,      // `near` closer than switch_distance_m times the plant's scale, else `far`
        points_lines,     // every plant as prefixes of its triangles, points and lines (§5)
        // Behrendt 2005 §2.3: the mesh levels near, the billboard cloud beyond cloud_distance_m,
        // the crossed billboard beyond the species' far distance, cross-faded over bands
        // (lod/billboard_cloud_lod.h).
        billboard_clouds,
        // DESIGN §1.5: each species' ladder of rungs by projected size, with bands between them
        // (lod/ladder.h); `ladders` holds one per species.
        ladder,
    };
    kind mode = kind::distance_levels;
    representation near = representation::mesh_full;
    representation far = representation::mesh_far;
    float switch_distance_m = 50.0f;
    // The point/line representation's d' and c_p (points_lines only). d' is the starting value
    // when a frame-time or primitive budget controls it (Deussen 2002 §5.4).
    point_line_quality points{};
    // Deussen 2002 §6.2: far eco tiles drawn as their aggregated sets (points_lines only).
    bool tile_sets = true;
    // Behrendt 2005 §2.3, "we have to blend to the complex representation, if a typical tree is
    // closer than 30 meters" (billboard_clouds only; times plant scale and lod_scale).
    float cloud_distance_m = 30.0f;
    // The ladder of each species, by species index (ladder only; the player fills it from the
    // scenario, the papers' ladder where the scenario names none).
    std::vector<ladder> ladders{};
    // Every ladder's mesh_reduced rung drawn as LoDF (Rebollo 2006) instead: the bench's
    // ladder_lodf, the scenario's own ladders with the foliage thinned continuously there.
    bool lodf_for_reduced = false;
    // Every ladder's shell rung dropped, so the rung before it draws the far field: the bench's
    // ladder_no_shells, what the same plants cost without Behrendt 2005's shells.
    bool without_shells = false;
    // Multiplies every projected size the ladders see (ladder only): below 1 every rung switches
    // nearer, so the bench sweeps a ladder's cost without moving the draw distances, which
    // lod_scale would.
    float ladder_size_scale = 1.0f;

    bool any_ladder_reaches(representation r) const {
        return mode == kind::ladder &&
               std::any_of(ladders.begin(), ladders.end(), [r](const ladder& l) { return l.reaches(r); });
    }

    // True when select_representation can choose `r`: a ladder reaches it, or a single or
    // hard-switch policy names it (as the rung tables' one-rung players do).
    bool selects(representation r) const {
        return any_ladder_reaches(r) ||
               ((mode == kind::single || mode == kind::hard_switch) && (near == r || far == r));
    }
    // The point/line representation: the scene then bakes and uploads it (and does not otherwise).
    bool uses_point_lines() const { return mode == kind::points_lines || selects(representation::points); }
    // The same for LoDF foliage (Rebollo 2006): the scene then bakes it and keeps cluster slots.
    bool uses_lodf() const { return selects(representation::lodf); }
    // The same for the facing billboard: the scene then uploads its mesh and builds its programs.
    bool uses_facing_billboards() const { return selects(representation::facing_billboard); }
    // The same for shells (Behrendt 2005 §3): the scene then bakes the Wang tiles' shell textures.
    bool uses_shells() const { return any_ladder_reaches(representation::shell); }
    // The same for billboard clouds: the scene then bakes them and uploads their atlases.
    bool uses_billboard_clouds() const {
        // A ladder's caster counts whatever the mode: the rung tables measure a rung casting as
        // the cloud on a one-rung player (app/rung_tables.cpp).
        const bool cast = std::any_of(ladders.begin(), ladders.end(),
                                      [](const ladder& l) { return l.casts(representation::billboard_cloud); });
        return cast || mode == kind::billboard_clouds || any_ladder_reaches(representation::billboard_cloud) ||
               ((mode == kind::single || mode == kind::hard_switch) &&
                (near == representation::billboard_cloud || far == representation::billboard_cloud));
    }
};

}  // namespace sylva
