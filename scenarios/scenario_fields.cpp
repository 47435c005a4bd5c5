#include "scenarios/scenario_fields.h"

#include <algorithm>
#include <bit>
#include <limits>

#include "models/terrain/wang_tile_rules.h"
#include "scenarios/ladder_fields.h"

namespace sylva {
namespace {

constexpr std::uint64_t k_max_u64 = std::numeric_limits<std::uint64_t>::max();
constexpr number_range k_coordinate_m{-1e9, 1e9};
constexpr number_range k_distance_m{0.0, 1e6};
constexpr number_range k_time_s{0.0, 1e6};
constexpr number_range k_intensity{0.0, 1e6};
constexpr integer_range k_seed{0, k_max_u64};
constexpr integer_range k_image_side_px{1, 16384};

// --- checks across fields -------------------------------------------------------------------

// low must be below (strict) or at most high. The defaults are always ordered, so at least one
// of the two keys is in the document; the problem is reported at the one stated first.
void expect_ordered(const json_node& node, std::string_view low_key, float low,
                    std::string_view high_key, float high, bool strict) {
    if (strict ? low < high : low <= high) return;
    if (const auto n = node.find(low_key))
        n->fail(std::string("must be ") + (strict ? "less than " : "at most ") +
                std::string(high_key) + " (" + format_float(high) + ")");
    if (const auto n = node.find(high_key))
        n->fail(std::string("must be ") + (strict ? "greater than " : "at least ") +
                std::string(low_key) + " (" + format_float(low) + ")");
    node.fail(std::string(low_key) + " and " + std::string(high_key) + " are out of order");
}

template <class Key, class TimeOf>
void expect_increasing_times(const json_node& array, const std::vector<Key>& keys, TimeOf time_of) {
    for (std::size_t i = 1; i < keys.size(); ++i) {
        const double previous = time_of(keys[i - 1]);
        if (!(time_of(keys[i]) > previous))
            array.at(i).find("t")->fail("keyframe times must be strictly increasing (previous: " +
                                        format_number(previous) + ")");
    }
}

void expect_unique_species(const json_node& array, const scenario& s) {
    for (std::size_t i = 0; i < s.species.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (s.species[i].name == s.species[j].name)
                array.at(i).find("name")->fail("duplicate species name (first at /species/" +
                                               std::to_string(j) + "/name)");
        }
    }
}

void expect_known_species(const json_node& array, const scenario& s) {
    std::vector<std::string_view> names;
    for (const auto& sp : s.species) names.push_back(sp.name);
    for (std::size_t i = 0; i < s.populations.size(); ++i) {
        if (std::find(names.begin(), names.end(), s.populations[i].species) == names.end())
            array.at(i).find("species")->fail("unknown species; expected one of: " + join(names));
    }
}

// --- fields that are not one JSON scalar per struct field ---------------------------------

void read_resolution(const json_node& n, scenario& s) {
    const auto& v = n.value();
    if (!v.is_array() || v.size() != 2) n.fail("expected an array of 2 integers [width, height]");
    s.width = static_cast<std::uint32_t>(read_integer(n.at(0), k_image_side_px));
    s.height = static_cast<std::uint32_t>(read_integer(n.at(1), k_image_side_px));
}

void write_resolution(const scenario& s, nlohmann::json& j) {
    j["resolution"] = {s.width, s.height};
}

void read_area(const json_node& n, population_settings& p) {
    const auto& v = n.value();
    if (!v.is_array() || v.size() != 4 ||
        !std::all_of(v.begin(), v.end(), [](const auto& e) { return e.is_number(); }))
        n.fail("expected an array of 4 numbers [x0, z0, x1, z1]");
    for (std::size_t i = 0; i < 4; ++i) p.area[i] = read_number(n.at(i), k_coordinate_m);
    if (!(p.area[0] < p.area[2])) n.fail("empty area: x0 must be less than x1");
    if (!(p.area[1] < p.area[3])) n.fail("empty area: z0 must be less than z1");
}

void write_area(const population_settings& p, nlohmann::json& j) {
    j["area"] = {p.area[0], p.area[1], p.area[2], p.area[3]};
}

std::array<double, 4> whole_terrain(const terrain_settings& t) {
    const double half = 0.5 * t.size_m;
    return {-half, -half, half, half};
}

// --- one table per struct ------------------------------------------------------------------

const field_table<terrain_settings>& terrain_fields() {
    using t = terrain_settings;
    static const auto table =
        field_table<t>()
            .number("size_m", &t::size_m, {1.0, 1e5})
            .integer("resolution", &t::resolution, {2, 4097})
            .number("height_m", &t::height_m, {0.0, 1e4})
            .integer("octaves", &t::octaves, {1, 16})
            .number("frequency", &t::frequency, {0.0, 10.0})
            .integer("seed", &t::seed, k_seed)
            .vec3("ground_color", &t::ground_color, {0.0, 1.0})
            .file_path("heightmap", &t::heightmap)
            .integer("tiles_per_side", &t::tiles_per_side, {1, 256})
            .number("max_error_px", &t::max_error_px, {0.0, 64.0})
            .check([](const json_node& n, const t& s) {
                // A heightmap's resolution is only known when it is read;
                // terrain_tile_meshes clamps then.
                if (s.heightmap.empty() && s.tiles_per_side > s.resolution - 1)
                    n.find("tiles_per_side")
                        ->fail("must be at most resolution - 1 (" +
                               std::to_string(s.resolution - 1) +
                               "): a tile holds at least one grid cell");
            });
    return table;
}

const field_table<implicit_lighting_settings>& implicit_fields() {
    using t = implicit_lighting_settings;
    static const auto table =
        field_table<t>()
            .number("generator_fraction", &t::generator_fraction, {0.001, 1.0})
            .number("rho_m", &t::rho_m, {0.0, 1000.0})
            .number("tau", &t::tau, {0.0, 1000.0})
            .number("ka_min", &t::ka_min, {0.0, 1.0})
            .choice("ambient_from", &t::ambient_from, k_ambient_sources)
            .number("d_min", &t::d_min, {0.0, 1000.0})
            .number("depth_min_m", &t::depth_min_m, {0.0, 1000.0})
            .number("exponent", &t::exponent, {0.05, 20.0})
            .number("blend", &t::blend, {0.0, 1.0})
            .boolean("population", &t::population);
    return table;
}

const field_table<species_settings>& species_fields() {
    using t = species_settings;
    static const auto table =
        field_table<t>()
            .text("name", &t::name)
            .required()
            .choice("generator", &t::generator, k_tree_generators)
            .file_path("model", &t::model)
            .number("height_m", &t::height_m, {0.1, 150.0})
            .number("reduced_distance_m", &t::reduced_distance_m, k_distance_m)
            .number("far_distance_m", &t::far_distance_m, k_distance_m)
            .number("max_distance_m", &t::max_distance_m, k_distance_m)
            .number("importance", &t::importance, {0.01, 100.0})
            .integer("octree_depth", &t::octree_depth, {0, 3})
            .choice("lighting", &t::lighting, k_species_lightings)
            .object("implicit", &t::implicit, implicit_fields())
            .add(
                "ladder", [](const json_node& n, t& s) { read_ladder(n, s.ladder); },
                [](const t& s, nlohmann::json& j) { write_ladder(s.ladder, j); })
            .check([](const json_node& n, const t& s) {
                expect_ordered(n, "reduced_distance_m", s.reduced_distance_m, "far_distance_m",
                               s.far_distance_m, false);
                expect_ordered(n, "far_distance_m", s.far_distance_m, "max_distance_m",
                               s.max_distance_m, false);
            });
    return table;
}

const field_table<procedural_density_settings>& density_fields() {
    using t = procedural_density_settings;
    static const auto table = field_table<t>()
                                  .number("frequency", &t::frequency, {0.01, 1000.0})
                                  .number("coverage", &t::coverage, {0.0, 1.0});
    return table;
}

// "density" present means procedural density is on; absent, it is off and not written.
void read_density(const json_node& n, population_settings& p) {
    density_fields().read(n, p.density);
    p.density.enabled = true;
}

void write_density(const population_settings& p, nlohmann::json& j) {
    if (p.density.enabled) j["density"] = density_fields().write(p.density);
}

const field_table<population_settings>& population_fields() {
    using t = population_settings;
    static const auto table =
        field_table<t>()
            .text("species", &t::species)
            .required()
            .integer("count", &t::count, {1, 10'000'000})
            .required()
            .number("min_spacing_m", &t::min_spacing_m, {0.0, 1000.0})
            .number("scale_min", &t::scale_min, {0.01, 100.0})
            .number("scale_max", &t::scale_max, {0.01, 100.0})
            .add("area", read_area, write_area)
            .number("max_slope_deg", &t::max_slope_deg, {0.0, 90.0})
            .number("min_altitude_m", &t::min_altitude_m, k_coordinate_m)
            .number("max_altitude_m", &t::max_altitude_m, k_coordinate_m)
            .choice("placement", &t::placement, k_placement_modes)
            .file_path("density_map", &t::density_map)
            .add("density", read_density, write_density)
            .check([](const json_node& n, const t& p) {
                expect_ordered(n, "scale_min", p.scale_min, "scale_max", p.scale_max, false);
                expect_ordered(n, "min_altitude_m", p.min_altitude_m, "max_altitude_m",
                               p.max_altitude_m, false);
                if (p.density.enabled && !p.density_map.empty())
                    n.find("density")->fail("give either density_map or density, not both");
                // A rule at its default value is no rule (and is what the writer writes back).
                static const population_settings no_rules;
                const bool ruled[] = {p.max_slope_deg != no_rules.max_slope_deg,
                                      p.min_altitude_m != no_rules.min_altitude_m,
                                      p.max_altitude_m != no_rules.max_altitude_m,
                                      !p.density_map.empty(), p.density.enabled};
                const char* const keys[] = {"max_slope_deg", "min_altitude_m", "max_altitude_m",
                                            "density_map", "density"};
                if (p.placement == "wang_tiles")
                    for (std::size_t k = 0; k < std::size(keys); ++k)
                        if (ruled[k])
                            n.find(keys[k])->fail(
                                "a population with placement \"wang_tiles\" is its tiles' plants "
                                "wherever a tile lies (so a shell of the tile shows exactly them): "
                                "slope, altitude and density rules cannot apply to it");
            });
    return table;
}

// scenario_camera_key wraps the camera path's own keyframe; these reach into it (const or not).
constexpr auto key_time = [](auto& k) -> auto& {
    return k.key.time_s;
};
constexpr auto key_position = [](auto& k) -> auto& {
    return k.key.position;
};
constexpr auto key_target = [](auto& k) -> auto& {
    return k.key.target;
};
constexpr auto key_fov = [](auto& k) -> auto& {
    return k.key.fov_deg;
};

const field_table<scenario_camera_key>& camera_key_fields() {
    using t = scenario_camera_key;
    static const auto table = field_table<t>()
                                  .number("t", key_time, k_time_s)
                                  .required()
                                  .vec3("position", key_position, k_coordinate_m)
                                  .required()
                                  .vec3("target", key_target, k_coordinate_m)
                                  .required()
                                  .number("fov_deg", key_fov, {5.0, 150.0})
                                  .boolean("relative_to_terrain", &t::above_terrain)
                                  .check([](const json_node& n, const t& k) {
                                      if (k.key.position == k.key.target)
                                          n.find("target")->fail(
                                              "must differ from position (the camera looks along "
                                              "target - position)");
                                  });
    return table;
}

const field_table<camera_settings>& camera_fields() {
    using t = camera_settings;
    static const auto table = field_table<t>()
                                  .number("near_m", &t::near_m, {0.001, 1000.0})
                                  .number("far_m", &t::far_m, {0.01, 1e7})
                                  .number("lod_scale", &t::lod_scale, {0.01, 100.0})
                                  .array("keyframes", &t::keyframes, camera_key_fields(),
                                         {.check_items =
                                              [](const json_node& n, const t& c) {
                                                  expect_increasing_times(n, c.keyframes, key_time);
                                              }})
                                  .check([](const json_node& n, const t& c) {
                                      expect_ordered(n, "near_m", c.near_m, "far_m", c.far_m, true);
                                  });
    return table;
}

const field_table<sun_keyframe>& sun_key_fields() {
    using t = sun_keyframe;
    static const auto table = field_table<t>()
                                  .number("t", &t::t, k_time_s)
                                  .required()
                                  .number("elevation_deg", &t::elevation_deg, {-90.0, 90.0})
                                  .required()
                                  .number("azimuth_deg", &t::azimuth_deg, {0.0, 360.0})
                                  .required();
    return table;
}

const field_table<sun_settings>& sun_fields() {
    using t = sun_settings;
    static const auto table =
        field_table<t>()
            .array("keyframes", &t::keyframes, sun_key_fields(),
                   {.check_items =
                        [](const json_node& n, const t& sun) {
                            expect_increasing_times(n, sun.keyframes,
                                                    [](const sun_keyframe& k) { return k.t; });
                        }})
            .number("intensity", &t::intensity, k_intensity)
            .number("turbidity", &t::turbidity, {1.7, 10.0})
            .number("sky_intensity", &t::sky_intensity, k_intensity);
    return table;
}

const field_table<environment_settings>& environment_fields() {
    using t = environment_settings;
    static const auto table =
        field_table<t>()
            .file_path("map", &t::map)
            .number("map_rotation_deg", &t::map_rotation_deg, {-360.0, 360.0})
            .check([](const json_node& n, const t& e) {
                // A rotation of nothing is a mistake worth hearing about, not a silent no-op.
                if (e.map.empty() && e.map_rotation_deg != 0.0f)
                    n.find("map_rotation_deg")->fail("turns the environment map; give map too");
            });
    return table;
}

const field_table<shadow_settings>& shadow_fields() {
    using t = shadow_settings;
    static const auto table =
        field_table<t>()
            .integer("cascades", &t::cascades, {1, 4})
            .integer("resolution", &t::resolution, {256, 8192})
            .number("max_distance_m", &t::max_distance_m, {1.0, 1e5})
            .number("split_lambda", &t::split_lambda, {0.0, 1.0})
            .check([](const json_node& n, const t& s) {
                if (!std::has_single_bit(s.resolution))
                    n.find("resolution")->fail("expected a power of two (256, 512, ..., 8192)");
            });
    return table;
}

const field_table<render_settings>& render_fields() {
    using t = render_settings;
    static const auto table = field_table<t>()
                                  .boolean("shadows", &t::shadows)
                                  .number("exposure", &t::exposure, {0.001, 1000.0})
                                  .choice("style", &t::style, k_styles);
    return table;
}

const field_table<wang_tile_settings>& wang_tile_fields() {
    using t = wang_tile_settings;
    static const auto table = field_table<t>()
                                  .number("tile_size_m", &t::tile_size_m, {1.0, 10000.0})
                                  .integer("colours", &t::colours, {2, 4});
    return table;
}

const field_table<shell_settings>& shell_fields() {
    using t = shell_settings;
    static const auto table = field_table<t>()
                                  .number("slant", &t::slant, {0.0, 4.0})
                                  .boolean("half_resolution", &t::half_resolution)
                                  .choice("blending", &t::blending, k_shell_blendings)
                                  .choice("lighting", &t::lighting, k_shell_lightings);
    return table;
}

// Every population with placement "wang_tiles" fits the scenario's tiles (its spacing leaves the
// tile an interior; models/terrain/wang_tiles.h wang_rules_problem).
void expect_wang_tiles_fit(const json_node& n, const scenario& s) {
    for (std::size_t i = 0; i < s.populations.size(); ++i) {
        const population_settings& p = s.populations[i];
        if (p.placement != "wang_tiles") continue;
        wang_tile_rules rules;
        rules.tile_size_m = s.wang_tiles.tile_size_m;
        rules.colours = s.wang_tiles.colours;
        rules.min_spacing_m = p.min_spacing_m;
        if (const std::string problem = wang_rules_problem(rules); !problem.empty()) {
            const json_node population = n.find("populations")->at(i);
            const auto spacing = population.find("min_spacing_m");
            (spacing ? *spacing : population).fail(problem + " (wang_tiles.tile_size_m)");
        }
    }
    // The shells are cut to one area: every tiled population grows on the same.
    const population_settings* first_tiled = nullptr;
    for (std::size_t i = 0; i < s.populations.size(); ++i) {
        const population_settings& p = s.populations[i];
        if (p.placement != "wang_tiles") continue;
        if (!first_tiled)
            first_tiled = &p;
        else if (p.area != first_tiled->area) {
            const json_node population = n.find("populations")->at(i);
            const auto area = population.find("area");
            (area ? *area : population)
                .fail(
                    "every population with placement \"wang_tiles\" must grow on the same area "
                    "(its shells cover one area)");
        }
    }
    // Behrendt 2005 §3: the shell rung draws the Wang tiling's plants; a species drawn by it must
    // be placed by the tiling everywhere. Under `auto` the shell still takes over by its own fade
    // (the shell is the terrain's; systems/select_representation_system.cpp).
    for (std::size_t sp = 0; sp < s.species.size(); ++sp) {
        const bool own = !s.species[sp].ladder.empty();
        const auto& steps = own ? s.species[sp].ladder : s.lod.ladder;
        const auto shell =
            std::find_if(steps.begin(), steps.end(),
                         [](const ladder_step_settings& st) { return st.rung == "shell"; });
        if (shell == steps.end() || s.lod.representation != "ladder") continue;
        const json_node ladder =
            own ? *n.find("species")->at(sp).find("ladder") : *n.find("lod")->find("ladder");
        const json_node rung = *ladder.at(std::size_t(shell - steps.begin())).find("rung");
        for (const population_settings& p : s.populations)
            if (p.species == s.species[sp].name && p.placement != "wang_tiles")
                rung.fail("species " + s.species[sp].name +
                          " has a population not placed by \"wang_tiles\": the shell "
                          "shows the Wang tiling's plants, and would lose the others");
    }
}

const field_table<eco_tile_settings>& eco_tile_fields() {
    using t = eco_tile_settings;
    static const auto table =
        field_table<t>()
            .boolean("enabled", &t::enabled)
            .integer("max_plants_per_tile", &t::max_plants_per_tile, {1, 1'000'000});
    return table;
}

const field_table<lod_settings>& lod_fields() {
    using t = lod_settings;
    static const auto table =
        field_table<t>()
            .choice("representation", &t::representation, k_lod_representations)
            .number("sample_distance_px", &t::sample_distance_px, {0.05, 64.0})
            .number("splat_factor", &t::splat_factor, {1.0, 4.0})
            .choice("splats", &t::splats, k_splat_styles)
            .boolean("fog_weighted_samples", &t::fog_weighted_samples)
            .number("primitive_budget", &t::primitive_budget, {0.0, 1e9})
            .number("target_frame_ms", &t::target_frame_ms, {0.0, 1e5})
            .number("cloud_distance_m", &t::cloud_distance_m, {0.1, 1e5})
            .choice("lighting", &t::lighting, k_lightings)
            .integer("sh_bands", &t::sh_bands, {2, 3})
            .boolean("sh_interreflection", &t::sh_interreflection)
            .add(
                "ladder", [](const json_node& n, t& s) { read_ladder(n, s.ladder); },
                [](const t& s, nlohmann::json& j) { write_ladder(s.ladder, j); })
            .number("plant_budget_ms", &t::plant_budget_ms, {0.0, 1e5})
            .number("max_error", &t::max_error, {0.0, 1.0})
            .number("gain_per_ms", &t::gain_per_ms, {0.0, 1e6})
            .integer("lodf_slots", &t::lodf_slots, {1, 65536})
            .check([](const json_node& n, const t& s) {
                if (s.primitive_budget > 0.0 && s.target_frame_ms > 0.0)
                    n.find("target_frame_ms")
                        ->fail("give either primitive_budget or target_frame_ms, not both");
                const char* const needs_ladder =
                    "chooses the rungs of a ladder: it needs representation \"ladder\"";
                if (s.plant_budget_ms > 0.0 && s.representation != "ladder")
                    n.find("plant_budget_ms")->fail(needs_ladder);
                if (s.max_error > 0.0 && s.representation != "ladder")
                    n.find("max_error")->fail(needs_ladder);
                if (s.gain_per_ms > 0.0 && s.representation != "ladder")
                    n.find("gain_per_ms")->fail(needs_ladder);
                if (s.gain_per_ms > 0.0 && s.max_error > 0.0)
                    n.find("gain_per_ms")
                        ->fail(
                            "an error threshold chooses each plant's rung on its own: give "
                            "max_error or gain_per_ms, not both");
                if (s.max_error > 0.0 && (s.plant_budget_ms > 0.0 || s.target_frame_ms > 0.0))
                    n.find("max_error")
                        ->fail(
                            "an error threshold chooses the rungs without a budget: give "
                            "max_error or plant_budget_ms/target_frame_ms, not both");
            });
    return table;
}

}  // namespace

const field_table<scenario>& scenario_fields() {
    using t = scenario;
    static const auto table =
        field_table<t>()
            .text("name", &t::name)
            .integer("seed", &t::seed, k_seed)
            .add("resolution", read_resolution, write_resolution)
            .integer("frames", &t::frames, {1, 1'000'000})
            .number("fps", &t::fps, {1.0, 1000.0})
            .vec3("world_offset", &t::world_offset, k_coordinate_m)
            .object("terrain", &t::terrain, terrain_fields())
            .array("species", &t::species, species_fields(), {.check_items = expect_unique_species})
            .required()
            .array("populations", &t::populations, population_fields(),
                   {.make =
                        [](const t& s) {
                            population_settings p;
                            p.area = whole_terrain(s.terrain);
                            return p;
                        },
                    .check_items = expect_known_species})
            .required()
            .object("camera", &t::camera, camera_fields())
            .object("sun", &t::sun, sun_fields())
            .object("environment", &t::environment, environment_fields())
            .object("shadows", &t::shadows, shadow_fields())
            .object("render", &t::render, render_fields())
            .object("wang_tiles", &t::wang_tiles, wang_tile_fields())
            .object("shells", &t::shells, shell_fields())
            .object("eco_tiles", &t::eco_tiles, eco_tile_fields())
            .object("lod", &t::lod, lod_fields())
            .check(expect_wang_tiles_fit);
    return table;
}

}  // namespace sylva
