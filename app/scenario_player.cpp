#include "app/scenario_player.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <iterator>
#include <string_view>
#include <thread>
#include <tuple>

#include "app/device_costs.h"
#include "app/rung_tables.h"
#include "components/camera.h"
#include "components/fade_alpha.h"
#include "components/lod_state.h"
#include "components/octree_cell.h"
#include "components/point_prefix.h"
#include "components/tile_visibility.h"
#include "models/cache/bake_cache.h"
#include "resources/frame_stats.h"
#include "resources/lodf_slots.h"
#include "resources/seen_pixels.h"
#include "scenarios/ladder_fields.h"
#include "setup/spawn_scenario.h"
#include "systems/adapt_plant_budget_system.h"
#include "systems/adapt_sample_distance_system.h"
#include "systems/aggregate_eco_tiles_system.h"
#include "systems/build_draw_list_system.h"
#include "systems/cull_system.h"
#include "systems/fit_shadow_cascades_system.h"
#include "systems/project_environment_system.h"
#include "systems/render/pass_timer.h"
#include "systems/render/submit_system.h"
#include "systems/select_ground_grid_system.h"
#include "systems/select_representation_system.h"
#include "systems/update_camera_system.h"
#include "systems/update_lodf_system.h"
#include "systems/update_point_prefix_system.h"
#include "systems/update_shells_system.h"
#include "systems/update_sun_system.h"
#include "systems/update_terrain_shadow_system.h"

namespace sylva {
namespace {

using clock_type = std::chrono::steady_clock;

double ms_since(clock_type::time_point start) {
    return std::chrono::duration<double, std::milli>(clock_type::now() - start).count();
}

int resolve_threads(int threads) {
    if (threads > 0) return threads;
    const unsigned hw = std::thread::hardware_concurrency();
    return hw ? int(hw) : 1;
}

// The frame (DESIGN.md §2): playback → cull (and the shadow cascades) → select → lighting → build → submit.
void register_frame_systems(ecs::schedule& schedule) {
    schedule.add<update_camera_system>();
    schedule.add<update_sun_system>();
    schedule.add<adapt_sample_distance_system>();
    schedule.add<adapt_plant_budget_system>();
    schedule.add<cull_system>();
    schedule.add<update_shells_system>();
    schedule.add<select_ground_grid_system>();
    schedule.add<fit_shadow_cascades_system>();
    schedule.add<select_representation_system>();
    schedule.add<aggregate_eco_tiles_system>();
    schedule.add<update_point_prefix_system>();
    schedule.add<update_lodf_system>();
    schedule.add<project_environment_system>();
    schedule.add<update_terrain_shadow_system>();
    schedule.add<build_draw_list_system>();
    schedule.add<submit_system>();
    schedule.build();
}

// What the auto ladder aims at: the player's options, else the scenario's lod section. None:
// the ladders switch by projected size.
struct ladder_aim {
    double plant_budget_ms = 0.0;
    double target_frame_ms = 0.0;
    double max_error = 0.0;
    double gain_per_ms = 0.0;
    bool any() const {
        return plant_budget_ms > 0.0 || target_frame_ms > 0.0 || max_error > 0.0 ||
               gain_per_ms > 0.0;
    }
};

ladder_aim aim_of(const scenario& s, const player_options& o) {
    const ladder_aim own{o.plant_budget_ms, o.target_frame_ms, o.max_error, o.gain_per_ms};
    if (own.any()) return own;
    if (o.scenario_lod)
        return {s.lod.plant_budget_ms, s.lod.target_frame_ms, s.lod.max_error, s.lod.gain_per_ms};
    return {};
}

render::renderer_settings renderer_settings_of(const scenario& s) {
    render::renderer_settings r;
    r.width = int(s.width);
    r.height = int(s.height);
    r.shadow_resolution = int(s.shadows.resolution);
    r.cascades = int(s.shadows.cascades);
    r.shadows = s.render.shadows;
    r.exposure = s.render.exposure;
    r.toon = s.render.style == "toon";
    r.lines = s.render.style == "lines";
    return r;
}

// The player's policy, or the scenario's own `lod` section when the player leaves the default.
lod_policy policy_of(const scenario& s, const player_options& options) {
    lod_policy policy = options.policy;
    if (options.scenario_lod && policy.mode == lod_policy::kind::distance_levels &&
        s.lod.representation == "points_lines") {
        policy.mode = lod_policy::kind::points_lines;
        policy.points = {s.lod.sample_distance_px, s.lod.splat_factor, true,
                         s.lod.splats == "opaque" ? splat_style::opaque : splat_style::soft,
                         s.lod.fog_weighted_samples};
    }
    if (options.scenario_lod && policy.mode == lod_policy::kind::distance_levels &&
        s.lod.representation == "billboard_clouds") {
        policy.mode = lod_policy::kind::billboard_clouds;
        policy.cloud_distance_m = s.lod.cloud_distance_m;
    }
    if (options.scenario_lod && policy.mode == lod_policy::kind::distance_levels && s.lod.representation == "ladder")
        policy.mode = lod_policy::kind::ladder;
    if (policy.mode == lod_policy::kind::ladder) {
        // DESIGN §1.5: a species' own ladder, else the lod section's, else the papers'. The
        // points rung draws with the scenario's point settings whenever the ladders are the
        // scenario's (the bench's ladder family too).
        if (options.scenario_lod || policy.ladders.empty())
            policy.points = {s.lod.sample_distance_px, s.lod.splat_factor, true,
                             s.lod.splats == "opaque" ? splat_style::opaque : splat_style::soft,
                             s.lod.fog_weighted_samples};
        if (policy.ladders.empty())
            for (const species_settings& species : s.species)
                policy.ladders.push_back(!species.ladder.empty() ? ladder_of(species.ladder)
                                         : !s.lod.ladder.empty() ? ladder_of(s.lod.ladder)
                                                                 : papers_ladder());
        if (policy.without_shells)
            for (ladder& l : policy.ladders)
                if (l.count > 1 && l.rungs[l.count - 1] == representation::shell) --l.count;
        if (policy.lodf_for_reduced)
            for (ladder& l : policy.ladders)
                for (std::size_t i = 0; i < l.count; ++i)
                    if (l.rungs[i] == representation::mesh_reduced) {
                        l.rungs[i] = representation::lodf;
                        if (i > 0 && seamless_step(l.rungs[i - 1], l.rungs[i])) l.band[i] = 0.0f;
                    }
        if (policy.ladders.size() != s.species.size())
            throw std::invalid_argument("a ladder policy needs one ladder per species: scenario '" + s.name +
                                        "' has " + std::to_string(s.species.size()) + " species, the policy " +
                                        std::to_string(policy.ladders.size()) + " ladders");
    }
    return policy;
}

// The scenario a player with `options` plays: options.lighting lights every species, and
// options.shell_slant, shell_blending, shell_lighting and shell_full_resolution draw the shells.
scenario as_asked(scenario s, const player_options& options) {
    if (!options.lighting.empty()) {
        s.lod.lighting = options.lighting;
        for (species_settings& species : s.species) species.lighting = "scenario";
    }
    if (options.shell_slant >= 0.0) s.shells.slant = options.shell_slant;
    if (!options.shell_blending.empty()) s.shells.blending = options.shell_blending;
    if (!options.shell_lighting.empty()) s.shells.lighting = options.shell_lighting;
    if (options.shell_full_resolution) s.shells.half_resolution = false;
    return s;
}

lod_policy player_policy(const scenario& s, const player_options& options) {
    return options.geometry == geometry_mode::full ? lod_policy{} : policy_of(s, options);
}

// Only what the policy can select is baked (DESIGN §2, "skip what a scene doesn't need").
scene_needs needs_of(const lod_policy& policy) {
    return {policy.uses_point_lines(), policy.uses_billboard_clouds(), policy.uses_lodf(), policy.uses_shells(),
            policy.uses_facing_billboards()};
}

}  // namespace

scene_assets build_player_assets(const scenario& s, const player_options& options, bake_cache* cache,
                                 const bake_progress& progress) {
    const scenario lit = as_asked(s, options);
    return build_scene_assets(lit, cache, needs_of(player_policy(lit, options)), progress);
}

std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t seed) {
    return hash_bytes(std::span(static_cast<const std::byte*>(data), bytes), seed);
}

scenario_player::scenario_player(scenario s, int threads, render::gl_context* context, bake_cache* cache,
                                 player_options options)
    : m_scenario(as_asked(std::move(s), options)), m_executor(resolve_threads(threads)) {
    const auto start = clock_type::now();
    const lod_policy policy = player_policy(m_scenario, options);
    m_assets = options.assets ? std::move(*options.assets) : build_scene_assets(m_scenario, cache, needs_of(policy));
    const spawn_report report = spawn_scenario(m_world, m_scenario, m_assets);
    m_built_meshes = m_assets.meshes.size();
    // Deussen 2002 §6.2: the eco tiles' aggregated point sets (only with points and lines, or a
    // ladder that reaches them).
    const bool tile_sets = (policy.mode == lod_policy::kind::points_lines && policy.tile_sets) ||
                           policy.any_ladder_reaches(representation::eco_tile);
    m_world.set_resource(tile_sets ? build_tile_point_sets(m_world, m_assets, m_scenario.seed) : tile_point_sets{});
    m_world.resource<species_library>().meshes = m_assets.library.meshes;  // with the tile sets' meshes
    m_world.set_resource(tile_point_draws{});
    m_world.set_resource(policy);
    m_world.set_resource(options.costs);
    sample_distance_budget budget = options.budget;
    if (options.scenario_lod && (m_scenario.lod.primitive_budget > 0.0 || m_scenario.lod.target_frame_ms > 0.0)) {
        budget.primitives = m_scenario.lod.primitive_budget;
        budget.frame_ms = m_scenario.lod.target_frame_ms;
    }
    m_world.set_resource(budget);
    if (options.geometry == geometry_mode::full) {
        camera& cam = m_world.single<camera>();
        cam.full_geometry = true;
        cam.lod_scale = 1e6f;  // no distance is far enough to switch or cull
    }
    m_world.set_chunk_size(options.chunk_size);
    register_frame_systems(m_schedule);

    render_device device;
    device.terrain_origin = m_scenario.world_offset;
    if (context) {
        // The renderer's GL objects live in this context: another one (a test's own, or a
        // window's) may have been made current since it was created.
        context->make_current();
        render::renderer_settings settings = renderer_settings_of(m_scenario);
        // The auto ladder weighs each plant by what the last frame showed of it
        // (resources/seen_pixels.h), counted in the instance-ID buffer.
        settings.id_buffer = options.id_buffer || (policy.mode == lod_policy::kind::ladder && aim_of(m_scenario, options).any());
        settings.fade_dissolve =
            policy.mode == lod_policy::kind::billboard_clouds || policy.mode == lod_policy::kind::ladder;
        m_renderer = std::make_unique<render::renderer>(settings, m_assets);
        device.renderer = m_renderer.get();
        // Measured once per device and setting, then read from the cache: without a cache the
        // paper's costs, so a run's images never depend on a timing taken during it.
        if (options.measure_costs && cache && policy.uses_point_lines())
            m_world.set_resource(device_cost_model(*m_renderer, *context, *cache, policy.points.splat_factor,
                                                   false, options.calibration)
                                     .costs_for(policy.points));
        m_world.set_resource(auto_ladder(policy, options, *context, cache));
        seen_pixels seen;
        seen.wanted = m_world.resource<rung_budget>().active();
        m_world.set_resource(std::move(seen));
        m_info.static_upload_bytes = m_renderer->static_upload_bytes();
        m_info.shell_bytes = m_renderer->shell_bytes();
        m_info.gl_renderer = context->renderer();
        m_info.gl_version = context->version();
        m_info.backend = context->backend_name();
    }
    m_world.set_resource(device);
    if (!m_world.has_resource<rung_budget>()) m_world.set_resource(rung_budget{});
    if (!m_world.has_resource<seen_pixels>()) m_world.set_resource(seen_pixels{});

    m_info.scenario = m_scenario.name;
    m_info.source = m_scenario.source;
    m_info.machine = describe_machine();
    m_info.host = host_name();
    m_info.threads = m_executor.threads();
    m_info.width = m_scenario.width;
    m_info.height = m_scenario.height;
    m_info.plants = report.plants;
    const auto& plants = m_world.table<plant_instance>();
    for (std::size_t i = 0; i < plants.size(); ++i)
        m_info.source_triangles +=
            m_assets.library.species[static_cast<std::size_t>(plants.data()[i].species)].triangles_full;
    m_info.setup_ms = ms_since(start);
}

scenario_player::~scenario_player() = default;

scene_assets scenario_player::assets_as_built() const {
    scene_assets copy = m_assets;
    copy.meshes.resize(m_built_meshes);  // setup/point_line_assets.h add_sample_mesh appends to both
    copy.library.meshes.resize(m_built_meshes);
    return copy;
}

void scenario_player::set_frame(std::uint64_t frame) { m_frame = frame; }

void scenario_player::forget_shown_frame() {
    m_world.resource<rung_budget>().cut = true;
    m_world.resource<seen_pixels>().measured = false;
}

frame_record scenario_player::step() {
    frame_record record;
    step(record);
    return record;
}

namespace {

// Sets `named` to these (name, value) pairs, assigning into the strings already there so that
// names that fit their old capacity allocate nothing.
template <typename Pairs>
void assign_named(std::vector<std::pair<std::string, double>>& named, const Pairs& pairs) {
    named.resize(std::size(pairs));
    std::size_t i = 0;
    for (const auto& [name, value] : pairs) {
        named[i].first.assign(name);
        named[i].second = value;
        ++i;
    }
}

}  // namespace

void scenario_player::step(frame_record& record) {
    m_world.resource<playback_clock>().frame = m_frame;
    m_world.set_frame_index(m_frame);
    rung_budget& budget = m_world.resource<rung_budget>();
    const seen_pixels& seen = m_world.resource<seen_pixels>();
    if (budget.cut && seen.wanted && !seen.measured && m_world.resource<render_device>().renderer) {
        // The rehearsal (step's comment in the header): drawn for its counts, never shown.
        m_executor.run([&] { m_schedule.run(m_world, m_executor); });
        budget.cut = true;
    }
    const auto start = clock_type::now();
    m_executor.run([&] { m_schedule.run(m_world, m_executor); });
    record.frame_ms = ms_since(start);
    record.frame = m_frame;
    record.time_s = m_world.resource<playback_clock>().time_s();

    const frame_stats& stats = m_world.resource<frame_stats>();
    assign_named(record.systems, m_schedule.last_timings());
    record.cpu_ms = 0.0;
    for (const auto& [name, ms] : m_schedule.last_timings())
        if (name != submit_system::k_name) record.cpu_ms += ms;
    record.cpu_ms += stats.submit_cpu_ms;
    constexpr std::size_t k_passes = std::tuple_size_v<decltype(stats.gpu_pass_ms)>;
    std::array<std::pair<std::string_view, double>, k_passes> passes;
    for (std::size_t p = 0; p < stats.gpu_pass_ms.size(); ++p)
        passes[p] = {render::k_gpu_pass_names[p], stats.gpu_pass_ms[p]};
    assign_named(record.passes, passes);
    record.gpu_ms = stats.gpu_ms;
    const draw_list& draws = m_world.resource<draw_list>();
    record.triangles = draws.triangles;
    record.shadow_triangles = draws.shadow_triangles;
    const cascade_set& cascades = m_world.resource<cascade_set>();
    record.shadow_texel_m.clear();
    record.shadow_split_m.clear();
    record.shadow_drawn.clear();
    for (int c = 0; c < cascades.count; ++c) {
        record.shadow_texel_m.push_back(cascades.texel_world_size[std::size_t(c)]);
        record.shadow_split_m.push_back(cascades.split_far[std::size_t(c)]);
        record.shadow_drawn.push_back(cascades.holds_receivers[std::size_t(c)] ? 1 : 0);
    }
    std::uint32_t cast_into = 0;  // bit c: a plant's shadow was drawn into cascade c
    for (const draw_batch& b : draws.batches)
        if (is_shadow_pass(b.pass) && b.instance_count > 0) cast_into |= 1u << unsigned(b.pass);
    for (const std::uint32_t mask : draws.lodf_pass_masks) cast_into |= mask & ((1u << unsigned(render_pass::opaque)) - 1u);
    record.caster_texel_m = 0.0;
    for (int c = 0; c < cascades.count; ++c)
        if (cast_into & (1u << unsigned(shadow_pass(c)))) {
            record.caster_texel_m = cascades.texel_world_size[std::size_t(c)];
            break;
        }
    record.points = draws.points;
    record.lines = draws.lines;
    record.work_counted = stats.work_counted;
    record.vertices = record.fragments = 0;
    for (std::size_t p = 0; p < stats.pass_vertices.size(); ++p) {
        if (p == std::size_t(render::gpu_pass::shadow)) continue;
        record.vertices += stats.pass_vertices[p];
        record.fragments += stats.pass_fragments[p];
    }
    record.shadow_vertices = stats.pass_vertices[std::size_t(render::gpu_pass::shadow)];
    record.shadow_fragments = stats.pass_fragments[std::size_t(render::gpu_pass::shadow)];
    record.instances = draws.instances_by_representation;
    record.upload_bytes = stats.upload_bytes;
    record.lodf_command_bytes = stats.lodf_command_bytes;
    record.lodf_changed_clusters = m_world.resource<lodf_slots>().changed_clusters;
    record.lodf_overflow = m_world.resource<lodf_slots>().overflow;
    record.submit_record_ms = stats.record_ms;
    record.submit_issue_ms = stats.submit_cpu_ms;
    record.draw_calls = stats.draw_calls;
    record.aggregated_tiles = m_world.resource<tile_point_draws>().tiles;
    record.aggregated_plants = m_world.resource<tile_point_draws>().plants;
    record.ladder_lambda = m_world.resource<rung_budget>().lambda;
    record.predicted_plant_ms = m_world.resource<rung_budget>().predicted_us / 1000.0;
    record.plant_budget_ms = m_world.resource<rung_budget>().plant_budget_us / 1000.0;
    record.image_hash = 0;
    record.state_hash = state_hash();
    ++m_frame;
}

image_rgba8 scenario_player::capture() const {
    return m_renderer ? m_renderer->read_color() : image_rgba8{};
}

std::vector<std::uint32_t> scenario_player::capture_plant_ids(std::uint32_t samples) const {
    if (!m_renderer) return {};
    const std::vector<std::uint32_t> instance_ids = m_renderer->read_ids();
    if (instance_ids.empty()) return {};
    const draw_list& draws = m_world.resource<draw_list>();
    const tile_point_sets& tile_sets = m_world.resource<tile_point_sets>();
    const auto& tiles = m_world.table<tile>();
    auto plant_of = [&](std::uint32_t instance) {
        if (!(instance & k_tile_item_bit)) return instance & ~k_partner_item_bit;
        return tiles.data()[tile_sets.parts[instance & ~k_tile_item_bit].tile].first_plant;
    };
    const std::size_t width = m_scenario.width / samples;
    const std::size_t height = m_scenario.height / samples;
    const std::size_t centre = samples / 2;
    std::vector<std::uint32_t> plants(width * height, 0);
    for (std::size_t y = 0; y < height; ++y)
        for (std::size_t x = 0; x < width; ++x) {
            const std::uint32_t id =
                instance_ids[(y * samples + centre) * m_scenario.width + x * samples + centre];
            // IDs are instance record index + 1 (resources/draw_list.h instance_of_id). A far eco
            // tile's samples count as its first plant's.
            const std::uint32_t instance = instance_of_id(id, draws);
            if (instance != k_no_draw_item) plants[y * width + x] = plant_of(instance) + 1;
            if (id == k_shell_id) plants[y * width + x] = k_shell_id;  // plants the shells show
        }
    return plants;
}

rung_budget scenario_player::auto_ladder(const lod_policy& policy, const player_options& options,
                                        render::gl_context& context, bake_cache* cache) {
    rung_budget budget;
    const ladder_aim aim = aim_of(m_scenario, options);
    budget.max_error = aim.max_error;
    budget.gain_per_us = aim.gain_per_ms / 1000.0;
    budget.target_frame_ms = aim.target_frame_ms;
    // Under a frame-time target alone the budget climbs from every plant on its cheapest rung
    // (systems/adapt_plant_budget_system.h).
    budget.plant_budget_us = aim.plant_budget_ms * 1000.0;
    if (!aim.any() || policy.mode != lod_policy::kind::ladder) return {};
    std::vector<representation> rungs;
    for (const ladder& l : policy.ladders)
        for (std::size_t r = 0; r < l.count; ++r)
            // The eco-tile rung is no rung of its own to the solver: a plant it puts on points
            // goes on to its tile by size; nor is the shell, which takes over by its own fade
            // (select_representation_system.cpp).
            if (l.rungs[r] != representation::eco_tile && l.rungs[r] != representation::shell &&
                std::find(rungs.begin(), rungs.end(), l.rungs[r]) == rungs.end())
                rungs.push_back(l.rungs[r]);
    const heightfield& terrain = m_assets.terrain;
    const double eye_height_m = typical_eye_height_m(
        m_scenario, [&](double x, double z) { return double(terrain.height_at(x, z)); });
    // Each rung is measured as its species' ladder draws it (LoDF's leaves, the shadow it casts).
    const auto measured = measure_rung_tables(m_scenario, rungs, policy.points, context, cache,
                                              [](const std::string& species) {
                                                  spdlog::info("measuring the rung tables of {} (once; kept in the bake cache)", species);
                                              },
                                              eye_height_m, policy.ladders, policy.ladder_size_scale);
    context.make_current();  // the measuring players drew in it
    std::optional<primitive_cost_model> model;
    if (cache && options.measure_costs)
        model = device_cost_model(*m_renderer, context, *cache, policy.points.splat_factor, false, options.calibration)
                    .model;
    std::optional<shader_work_costs> work;
    if (cache && options.measure_costs) work = device_work_costs(*m_renderer, context, *cache, false, options.calibration).costs;
    for (std::size_t i = 0; i < measured.size(); ++i)
        budget.tables.push_back(solver_tables(measured[i], policy.ladders[i], model, policy.points, work));
    return budget;
}

void scenario_player::present(int window_width, int window_height) const {
    if (m_renderer) m_renderer->present(window_width, window_height);
}

std::uint64_t scenario_player::state_hash() const {
    const auto& lod = m_world.table<lod_state>();
    std::uint64_t h = fnv1a(lod.data(), lod.size() * sizeof(lod_state));
    // Every component a parallel loop writes, not only what reaches the draw list: a wrong
    // write is then caught where it happens, even for a plant whose items it does not change
    // (a shadow-only plant's prefix, a fade that ends up drawn as nothing).
    const auto& prefixes = m_world.table<point_prefix>();
    h = fnv1a(prefixes.data(), prefixes.size() * sizeof(point_prefix), h);
    const auto& cells = m_world.table<cell_prefix>();
    h = fnv1a(cells.data(), cells.size() * sizeof(cell_prefix), h);
    const auto& tiles = m_world.table<tile_visibility>();
    h = fnv1a(tiles.data(), tiles.size() * sizeof(tile_visibility), h);
    const auto& fades = m_world.table<fade_alpha>();
    for (std::size_t i = 0; i < fades.size(); ++i) {  // field by field: fade_alpha has padding
        h = fnv1a(&fades.data()[i].value, sizeof(float), h);
        h = fnv1a(&fades.data()[i].partner, sizeof(representation), h);
    }
    const auto& clusters = m_world.table<cluster_changes>();
    h = lodf_state_hash(m_world.resource<lodf_slots>(), std::span(clusters.data(), clusters.size()), h);
    const draw_list& draws = m_world.resource<draw_list>();
    h = fnv1a(draws.items.data(), draws.items.size() * sizeof(draw_item), h);
    h = fnv1a(draws.instances.data(), draws.instances.size() * sizeof(instance_gpu), h);
    h = fnv1a(draws.lodf_instances.data(), draws.lodf_instances.size() * sizeof(instance_gpu), h);
    return h;
}

}  // namespace sylva
