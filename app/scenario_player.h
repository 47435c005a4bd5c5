#pragma once
// Plays a scenario: builds its assets and ECS world, registers the frame's systems in their
// phases, and runs one frame per step() on the executor, submitting to the renderer when there
// is a GL context (without one, the same frame loop runs CPU-only for tests and benchmarks).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "app/metrics.h"
#include "ecs/executor.h"
#include "ecs/schedule.h"
#include "ecs/world.h"
#include "models/cache/bake_cache.h"
#include "models/image/image.h"
#include "scenarios/scenario.h"
#include "systems/render/gl_context.h"
#include "systems/render/primitive_cost_calibration.h"
#include "systems/render/renderer.h"
#include "systems/adapt_sample_distance_system.h"
#include "resources/lod_policy.h"
#include "resources/rung_budget.h"
#include "resources/scene_assets.h"
#include "setup/spawn_scenario.h"

namespace sylva {

// How plants are drawn: with the LOD systems' choices, or every plant at full geometry (the
// brute-force configuration; the reference is the same, supersampled by the caller).
enum class geometry_mode { lod, full };

// How a player draws: the geometry mode, the representation policy and whether the renderer
// keeps an ID buffer (measurement). Converts from a geometry_mode for the common case.
struct player_options {
    player_options() = default;
    player_options(geometry_mode g) : geometry(g) {}  // NOLINT: implicit on purpose
    geometry_mode geometry = geometry_mode::lod;
    lod_policy policy{};
    // When `policy` is the default (distance levels), follow the scenario's `lod` section
    // instead. The bench turns this off: its configurations say exactly what they draw.
    bool scenario_lod = true;
    // The budget d' is adapted to (Deussen 2002 §5.4; none by default). With scenario_lod the
    // scenario's lod.primitive_budget / target_frame_ms take its place when set.
    sample_distance_budget budget{};
    // What primitives cost on the device (the point/line representation's thresholds); the
    // paper's by default, measured ones from systems/render/primitive_cost_calibration.h.
    primitive_costs costs{};
    // With the point/line representation, a GL device and a bake cache: use the device's costs
    // (app/device_costs.h), calibrated once per device with `calibration` and cached.
    bool measure_costs = true;
    render::calibration_settings calibration{};
    bool id_buffer = false;
    // Entities per task of the frame's parallel loops (ecs::world::chunk_size). Chunking never
    // depends on the thread count, and no result depends on the chunk size: a smaller chunk only
    // exercises the same per-chunk paths (counts, prefix sums, merges) on a small scene, which
    // is what the chunk-boundary determinism test uses it for.
    std::size_t chunk_size = ecs::k_default_chunk;
    // Every species lit this way ("normal_mapped", "pre_lit" or "sh"; scenario `lighting`),
    // whatever the scenario says; empty: as the scenario says. The bench compares variants so.
    std::string lighting;
    // With a ladder policy: choose every plant's rung by measured rung tables (app/rung_tables.h)
    // so that the plants' predicted cost stays within this many ms a frame (the auto ladder,
    // resources/rung_budget.h); 0: with scenario_lod the scenario's lod.plant_budget_ms, else
    // the ladders switch by projected size.
    double plant_budget_ms = 0.0;
    // The same, with the budget adapted every frame to hold this GPU frame time (from
    // plant_budget_ms, or from every plant cheapest; not deterministic), or instead of a budget the cheapest
    // rung within this mean colour error per plant pixel. Any of the three set here replaces the
    // scenario's.
    double target_frame_ms = 0.0;
    double max_error = 0.0;
    // The least error a ms of a plant's cost must buy (resources/rung_budget.h gain_per_us), alone
    // or with a budget or target; set here it replaces the scenario's lod.gain_per_ms.
    double gain_per_ms = 0.0;
    // Behrendt 2005 Eq. 2's f for the shells (scenario shells.slant); negative: the scenario's.
    double shell_slant = -1.0;
    std::string shell_blending;  // scenario shells.blending; empty: the scenario's
    std::string shell_lighting;  // scenario shells.lighting; empty: the scenario's
    bool shell_full_resolution = false;  // true: shells.half_resolution false; else the scenario's
    // Assets already built for this scenario and these options (build_player_assets), moved
    // from: the viewer re-bakes a tuned species in the background and swaps the player.
    std::shared_ptr<scene_assets> assets;
};

// What a player with `options` builds for `s` (its meshes, textures and terrain, CPU only):
// the viewer runs it on a background thread. `cache` may be null.
scene_assets build_player_assets(const scenario& s, const player_options& options, bake_cache* cache,
                                 const bake_progress& progress = {});

// What reaching a shard's first frame cost (scenario_player::replay_to; issue 25).
struct replay_cost {
    std::uint64_t cpu_frames = 0;       // the frame's systems alone, nothing rendered
    std::uint64_t rendered_frames = 0;  // rendered too, the image discarded or given to the caller
    double ms = 0.0;
};

class scenario_player {
public:
    // `context` may be null: then nothing is rendered. `threads` 0 means every hardware thread.
    // `cache` may be null: species models are then built every time (tests do this).
    scenario_player(scenario s, int threads, render::gl_context* context, bake_cache* cache = nullptr,
                    player_options options = {});
    ~scenario_player();

    // Plays the current frame, then advances to the next. The auto ladder weighs each plant by
    // what the frame before showed of it (resources/seen_pixels.h); before a run's first frame
    // (or after forget_shown_frame) none did, and judged wholly seen, hidden plants were bought
    // dearer rungs that the next frame took back and dissolved over fade_frames frames (`default`
    // at 160x90: 2,010 of 6,997 plants changed rung from frame 0 to 1). So that frame is first
    // rehearsed: drawn, not shown, only for its counts (285 changed then; the auto sweep's first
    // 12 frames at 480x270 drew the same errors in 0.89-0.93x the time from 20 ms up).
    frame_record step();
    // The same into `record`, reusing its buffers: once a record has held a frame, stepping
    // into it again allocates nothing (the warm frame loop, STYLE habit 5).
    void step(frame_record& record);
    image_rgba8 capture() const;
    // The last frame's ID buffer as plant IDs, rows top to bottom: 0 for no plant (sky, terrain),
    // else the plant's dense index + 1. For a frame rendered at `samples` times the size along
    // each axis, the centre sample of each samples x samples block (the pixel's own centre for
    // odd counts). Empty without an ID buffer.
    std::vector<std::uint32_t> capture_plant_ids(std::uint32_t samples = 1) const;
    // Blits the last frame to the window's default framebuffer (view).
    void present(int window_width, int window_height) const;
    void set_frame(std::uint64_t frame);
    // The frames that follow do not continue the last one played (a rewind or a jump): no plant
    // dissolves from or holds the rung it had, and the auto ladder's next frame is rehearsed
    // first, as a run's first frame is (step()).
    void forget_shown_frame();

    // Plays the frames from the current one to `frame` - 1 so that the next step() is `frame` as
    // a run that played every frame before it plays it, bit for bit (a shard of a run, issue 25).
    // State that carries over frames (hysteresis, fades, point prefixes, LoDF counters, eco tile
    // sets) is a function of the frames' systems alone, so those frames run without rendering
    // (about 1/20 of a rendered frame's cost on the bench scenes), except:
    //  - the last one is rendered, so the renderer's own carried state (the LoDF commands' mirror,
    //    hence upload_bytes) is the whole run's, and a caller has the previous image (popping);
    //  - when the selection reads what the last frame showed (the auto ladder's seen pixels,
    //    counted in the ID buffer), every frame is rendered: that state is a function of images;
    //  - with full geometry (the reference) nothing carries over but the frame before's: only
    //    the last frame is played;
    //  - frames for which `render_frame` returns true are rendered (the bench's transition
    //    windows that began before the shard need the test's colours at their first frame).
    // `after` is called after every frame with its record and whether it was rendered (the image
    // is then capture()'s until the next step). Throws std::invalid_argument when a shard cannot
    // equal the whole run (unreproducible_reason), std::logic_error when `frame` is behind.
    // `stop` is asked before every frame: true leaves the player where it got to (an interrupt;
    // the caller must then play no frame of the shard).
    replay_cost replay_to(std::uint64_t frame, const std::function<bool(std::uint64_t)>& render_frame = {},
                          const std::function<void(const frame_record&, bool rendered)>& after = {},
                          const std::function<bool()>& stop = {});
    // Why no shard of this player's run can equal the whole run (the frame-time targets adapt
    // to the device's measured time, so no two whole runs are equal either); empty when it can.
    std::string unreproducible_reason() const;
    // FNV-1a of what the selection reads from the device: the primitive costs and the auto
    // ladder's measured tables. Measured per device (and cached by its description), so shards
    // on different kinds of node may select differently: sylva merge refuses them when this differs.
    std::uint64_t selection_inputs_hash() const;
    // Whether replay_to renders every frame (the selection reads the images).
    bool replay_renders_every_frame() const;
    std::uint64_t frame() const { return m_frame; }

    // FNV-1a over the state the frame's parallel loops write (every plant's LOD state, fade and
    // point prefix, every octree cell's prefix, every eco tile's visibility) and the sorted draw
    // list with its instance records: equal for any thread count and any chunk size.
    std::uint64_t state_hash() const;

    const scenario& settings() const { return m_scenario; }
    const scene_assets& assets() const { return m_assets; }
    // A copy of the assets as built, before the eco tiles' point sets added their meshes (what
    // player_options::assets takes for another player of this scenario).
    scene_assets assets_as_built() const;
    ecs::world& world() { return m_world; }
    const ecs::schedule& schedule() const { return m_schedule; }
    run_info info() const { return m_info; }
    // How often the shells' SH transfer was summed with a light that held still (0 without a
    // renderer or SH-lit shells; systems/render/passes/shell_pass.h).
    std::uint32_t shell_relights() const { return m_renderer ? m_renderer->shell_relights() : 0; }
    // What primitives cost where this player draws (measured, or as given in its options).
    const primitive_costs& costs() const { return m_world.resource<primitive_costs>(); }
    // The auto ladder's tables (error and cost of each rung by size) and its budget; empty tables
    // when the ladders switch by size.
    const rung_budget& ladder_budget() const { return m_world.resource<rung_budget>(); }

private:
    // The auto ladder's tables and budget (measured through `cache` on `context`), or an empty
    // rung_budget when the ladders switch by size.
    rung_budget auto_ladder(const lod_policy& policy, const player_options& options, render::gl_context& context,
                            bake_cache* cache);

    scenario m_scenario;
    scene_assets m_assets;
    ecs::world m_world;
    ecs::schedule m_schedule;
    ecs::executor m_executor;
    std::unique_ptr<render::renderer> m_renderer;
    run_info m_info;
    std::uint64_t m_frame = 0;
    std::size_t m_built_meshes = 0;  // meshes before the eco tiles' point sets
};

// FNV-1a 64 over bytes (image and state hashes): the bake cache's hash_bytes for a pointer and a size.
std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t seed = 0xcbf29ce484222325ULL);

}  // namespace sylva
