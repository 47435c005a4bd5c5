#pragma once
// What each rung of a species draws and how far it is from the species' full geometry, as a
// function of projected size: the measured tables the auto ladder chooses from (DESIGN §1.5,
// issue 21 item 3; the choice itself is lod/rung_solver.h).
//
// For each species of a scenario, the species is planted alone on flat ground and seen from
// k_rung_table_directions azimuths at every size of k_rung_table_sizes_px (its bounding sphere
// that many pixels high in a k_rung_table_view_px-square view, a camera moved as
// select_representation measures size), from the height above the ground the scenario's camera
// holds (typical_eye_height_m): near plants from above, far ones nearly level, as a frame sees
// them. Each rung is drawn on its own and compared with the
// full geometry at 3x3 samples per pixel, lit the same way: the error is the mean absolute colour
// difference (of 1, over RGB) between 2x2 block means over the blocks either covers, per pixel
// the reference's plant covers. Beside it the table keeps what the rung drew (view and shadow triangles, points, lines,
// covered pixels), so its cost follows from the device's calibration (lod/primitive_cost_model.h)
// on any machine, while the table itself is the same everywhere. Tables are stored in the bake
// cache (kind "rung_tables"), keyed by the one-plant scenario and the rungs.
#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "components/lod_state.h"
#include "lod/primitive_cost_model.h"
#include "lod/shader_work_costs.h"
#include "lod/rung_solver.h"
#include "models/cache/bake_cache.h"
#include "resources/lod_policy.h"
#include "scenarios/scenario.h"

namespace sylva {
namespace render {
class gl_context;
}

inline constexpr std::uint32_t k_rung_table_view_px = 256;
inline constexpr std::array<float, 3> k_rung_table_directions{0.0f, 120.0f, 240.0f};  // azimuth, degrees

// One rung of one species, per table size (means over the directions).
struct rung_measurement {
    representation rung = representation::none;
    std::array<float, k_rung_table_size_count> error_per_pixel{};
    std::array<float, k_rung_table_size_count> structure_error_per_pixel{};  // 1 − SSIM over its windows, per pixel
    std::array<float, k_rung_table_size_count> plant_pixels{};  // the reference's, in the view
    std::array<float, k_rung_table_size_count> drawn_pixels{};  // the rung's
    std::array<float, k_rung_table_size_count> triangles{};
    std::array<float, k_rung_table_size_count> shadow_triangles{};
    std::array<float, k_rung_table_size_count> points{};
    std::array<float, k_rung_table_size_count> lines{};
    // The shader work the plant added to the frame (render::pass_timer::read_work; the frame with
    // the plant less the same view without it): view passes, and the shadow pass apart. All 0
    // where the device cannot count.
    std::array<float, k_rung_table_size_count> vertices{};
    std::array<float, k_rung_table_size_count> fragments{};
    std::array<float, k_rung_table_size_count> shadow_vertices{};
    std::array<float, k_rung_table_size_count> shadow_fragments{};
    // Metres per texel of the cascade those shadow fragments were shaded at (frame_record::
    // caster_texel_m, the mean over the views that cast; 0: none did). A frame's cascades may be
    // coarser or finer where the plant stands: the solver scales the fragments by the texel area.
    std::array<float, k_rung_table_size_count> shadow_texel_m{};
};

struct species_rung_measurements {
    std::string species;
    bool work_counted = false;  // the device counted shader invocations (rung_measurement::vertices...)
    std::vector<rung_measurement> rungs;  // in the order asked for
};

// Measures `rungs` of every species of `s` (drawn with `points` for the points rung), through
// `cache` when it is not null, seen from `eye_height_m` above the ground (k_rung_table_level_eye:
// level with the plant's centre). `progress` hears each species' name as its measuring starts
// (not when its tables come from the cache). `ladders[i]`, species i's ladder (its sizes seen
// x `ladder_size_scale`), says how its rungs are drawn: the LoDF rung with the leaves a plant of
// each size keeps below where the ladder starts it (update_lodf_system.h), a rung whose shadow
// the ladder casts as another (ladder::shadow) so; a species without one: every leaf, own shadows.
inline constexpr double k_rung_table_level_eye = -1.0;
std::vector<species_rung_measurements> measure_rung_tables(
    const scenario& s, const std::vector<representation>& rungs, const point_line_quality& points,
    render::gl_context& context, bake_cache* cache, const std::function<void(const std::string&)>& progress = {},
    double eye_height_m = k_rung_table_level_eye, std::span<const ladder> ladders = {},
    float ladder_size_scale = 1.0f);

// The height above the ground the scenario's camera keys see from (their median, to 0.5 m, at
// least 0.5 m): where the rung tables are measured from, so a fern the camera looks down on is
// judged from above, as it is seen, and a far tree nearly level. `terrain_height(x, z)` is the
// ground under a key whose height is absolute.
double typical_eye_height_m(const scenario& s, const std::function<double(double, double)>& terrain_height);

// What the solver chooses from: for the rungs of `ladder` (in its order; each must have been
// measured), the error summed over the plant's pixels (error per pixel x the pixels the plant
// covers, those beyond the view grown with the size's square) and the cost in microseconds of
// what the rung drew in the view (triangles and covered pixels on the device's triangle path,
// points and lines at quality `q` on theirs, lod/primitive_cost_model.h) and apart from it what
// its shadow cost (shadow triangles; at a size where the measuring scene cast no shadow, as at
// the next size where it did), so a plant only casting pays only its shadow. Without a
// calibration (`model` empty) a triangle costs 1 µs (about what llvmpipe draws, 1 M a second),
// points and lines the paper's share of it (Deussen 2002 §4.1), pixels nothing.
species_rung_tables solver_tables(const species_rung_measurements& m, const ladder& ladder,
                                  const std::optional<primitive_cost_model>& model, const point_line_quality& q,
                                  const std::optional<shader_work_costs>& work = std::nullopt);

// The bytes the cache keeps, and back (throws std::runtime_error on anything malformed).
std::vector<std::byte> encode_rung_measurements(const species_rung_measurements& m);
species_rung_measurements decode_rung_measurements(std::span<const std::byte> bytes);

}  // namespace sylva
