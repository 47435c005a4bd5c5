// The scenario loader: the shipped scenarios load with their documented contents, defaults
// survive a round trip, and every kind of bad document gives exactly one located error.
#include "scenarios/scenario_loader.h"

#include "scenarios/json_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numeric>
#include <string>
#include <unistd.h>

namespace sylva {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr std::string_view k_source = "test.json";

std::filesystem::path source_path(std::string_view relative) {
    return std::filesystem::path(SYLVA_SOURCE_DIR) / relative;
}

// The smallest valid scenario: one species, one population, everything else defaulted.
json minimal() {
    return json::parse(R"({"species": [{"name": "oak"}],
                           "populations": [{"species": "oak", "count": 10}]})");
}

// minimal() with the arrays stated (resolution, ground colour, one camera and one sun
// keyframe), so their elements can be varied by JSON Pointer.
json with_keyframes() {
    json j = minimal();
    j["resolution"] = {960, 540};
    j["terrain"]["ground_color"] = {0.3, 0.3, 0.2};
    j["camera"]["keyframes"] =
        json::parse(R"([{"t": 0, "position": [0, 10, 0], "target": [10, 10, 0]}])");
    j["sun"]["keyframes"] = json::parse(R"([{"t": 0, "elevation_deg": 40, "azimuth_deg": 100}])");
    return j;
}

json set(json j, const std::string& pointer, json value) {
    j[json::json_pointer(pointer)] = std::move(value);
    return j;
}

scenario load(const json& j) {
    return load_scenario_text(j.dump(), k_source);
}

struct expected_error {
    std::string json_path;
    std::string problem;
    std::string value;
};

void expect_error(const json& j, const expected_error& expected) {
    try {
        load(j);
        ADD_FAILURE() << "loaded without error: " << j.dump();
    } catch (const scenario_error& e) {
        EXPECT_EQ(e.file(), k_source);
        EXPECT_EQ(e.json_path(), expected.json_path);
        EXPECT_EQ(e.problem(), expected.problem);
        EXPECT_EQ(e.value(), expected.value);
    }
}

std::uint64_t total_count(const scenario& s) {
    return std::accumulate(
        s.populations.begin(), s.populations.end(), std::uint64_t{0},
        [](std::uint64_t sum, const population_settings& p) { return sum + p.count; });
}

// --- the shipped scenarios ------------------------------------------------------------------

TEST(scenario_loader, default_scenario_has_the_documented_contents) {
    const scenario s = load_default_scenario();
    EXPECT_EQ(s.name, "default");
    EXPECT_EQ(s.source, "embedded:scenarios/default.json");
    EXPECT_EQ(s.width, 960u);
    EXPECT_EQ(s.height, 540u);
    EXPECT_EQ(s.frames, 48u);
    EXPECT_EQ(s.fps, 24.0);
    EXPECT_EQ(s.terrain.size_m, 400.0);
    // Issue 3: every plant preset renders in the default scenario.
    ASSERT_EQ(s.species.size(), k_tree_generators.size());
    for (std::string_view preset : k_tree_generators)
        EXPECT_TRUE(std::any_of(s.species.begin(), s.species.end(),
                                [&](const species_settings& sp) { return sp.generator == preset; }))
            << preset;
    EXPECT_EQ(s.species[0].name, "oak");
    EXPECT_EQ(s.species[1].name, "spruce");
    EXPECT_EQ(total_count(s), 3000u + 6u + 300u + 4000u + 1200u + 400u);
    ASSERT_GE(s.camera.keyframes.size(), 2u);
    EXPECT_EQ(s.camera.keyframes.front().key.position, glm::dvec3(-160.0, 30.0, 150.0));
    EXPECT_EQ(s.camera.keyframes.back().key.position, glm::dvec3(-5.0, 26.0, -5.0));
    EXPECT_EQ(s.camera.keyframes.back().key.time_s, 2.0);
    ASSERT_EQ(s.sun.keyframes.size(), 2u);
    EXPECT_EQ(s.sun.keyframes[0].elevation_deg, 35.0f);
    EXPECT_EQ(s.sun.keyframes[1].elevation_deg, 38.0f);
}

TEST(scenario_loader, default_camera_stays_inside_the_terrain_just_above_the_canopy) {
    const scenario s = load_default_scenario();
    const double half = 0.5 * s.terrain.size_m;
    for (const auto& k : s.camera.keyframes) {
        EXPECT_TRUE(k.above_terrain);
        EXPECT_LT(std::abs(k.key.position.x), half);
        EXPECT_LT(std::abs(k.key.position.z), half);
        // Trees are up to ~20 m tall: the flight stays above them, low enough to see crowns.
        EXPECT_GE(k.key.position.y, 22.0);
        EXPECT_LE(k.key.position.y, 40.0);
    }
}

TEST(scenario_loader, default_file_on_disk_is_the_embedded_one) {
    scenario from_disk = load_scenario_file(source_path("scenarios/default.json"));
    from_disk.source = "embedded:scenarios/default.json";
    EXPECT_EQ(from_disk, load_default_scenario());
}

TEST(scenario_loader, tiny_scenario_is_small) {
    const scenario s = load_scenario_file(source_path("scenarios/tiny.json"));
    EXPECT_EQ(s.name, "tiny");
    EXPECT_EQ(s.width, 160u);
    EXPECT_EQ(s.height, 90u);
    EXPECT_EQ(s.frames, 4u);
    EXPECT_EQ(s.terrain.size_m, 120.0);
    EXPECT_EQ(s.terrain.resolution, 33u);
    EXPECT_EQ(s.species.size(), 2u);
    EXPECT_EQ(total_count(s), 60u);
    EXPECT_EQ(s.camera.keyframes.size(), 3u);
    EXPECT_EQ(s.shadows.resolution, 512u);
    EXPECT_EQ(s.shadows.cascades, 2u);
    // The path covers the whole playback (the last frame is at (frames - 1) / fps).
    EXPECT_GE(s.camera.keyframes.back().key.time_s, double(s.frames - 1) / s.fps);
}

// --- defaults -------------------------------------------------------------------------------

TEST(scenario_loader, minimal_scenario_gets_every_default) {
    const scenario s = load(minimal());
    const scenario defaults;
    EXPECT_EQ(s.name, "test");
    EXPECT_EQ(s.source, k_source);
    EXPECT_EQ(s.seed, defaults.seed);
    EXPECT_EQ(s.width, defaults.width);
    EXPECT_EQ(s.height, defaults.height);
    EXPECT_EQ(s.frames, defaults.frames);
    EXPECT_EQ(s.fps, defaults.fps);
    EXPECT_EQ(s.world_offset, defaults.world_offset);
    EXPECT_EQ(s.terrain, defaults.terrain);
    species_settings oak;
    oak.name = "oak";
    EXPECT_EQ(s.species, std::vector{oak});
    population_settings trees;
    trees.species = "oak";
    trees.count = 10;
    EXPECT_EQ(s.populations, std::vector{trees});  // area: the default terrain's extent
    EXPECT_EQ(s.camera.near_m, defaults.camera.near_m);
    EXPECT_EQ(s.camera.far_m, defaults.camera.far_m);
    EXPECT_EQ(s.camera.lod_scale, defaults.camera.lod_scale);
    EXPECT_EQ(s.camera.keyframes, default_camera_keyframes(s.terrain, 2.0));
    EXPECT_EQ(s.sun, defaults.sun);
    EXPECT_EQ(s.shadows, defaults.shadows);
    EXPECT_EQ(s.render, defaults.render);
}

TEST(scenario_loader, every_default_written_out_loads_the_same_as_none) {
    scenario stated = load_scenario_file(source_path("tests/scenarios/data/all_defaults.json"));
    scenario implied = load(minimal());
    stated.source = implied.source;
    implied.name = "minimal";
    EXPECT_EQ(stated, implied);
}

TEST(scenario_loader, population_area_defaults_to_the_scenario_terrain) {
    const scenario s = load(set(minimal(), "/terrain/size_m", 100));
    EXPECT_EQ(s.populations[0].area, (std::array<double, 4>{-50.0, -50.0, 50.0, 50.0}));
}

TEST(scenario_loader, default_camera_path_flies_within_the_terrain_over_the_playback) {
    terrain_settings terrain;
    terrain.size_m = 1000.0;
    const auto keys = default_camera_keyframes(terrain, 3.0);
    ASSERT_GE(keys.size(), 2u);
    EXPECT_EQ(keys.front().key.time_s, 0.0);
    EXPECT_EQ(keys.back().key.time_s, 3.0);
    for (const auto& k : keys) {
        EXPECT_LT(std::abs(k.key.position.x), 500.0);
        EXPECT_LT(std::abs(k.key.position.z), 500.0);
        EXPECT_NE(k.key.position, k.key.target);
    }
}

TEST(scenario_loader, round_trip_through_json_text_keeps_every_field) {
    for (scenario s : {load(minimal()), load_default_scenario(),
                       load_scenario_file(source_path("scenarios/tiny.json"))}) {
        SCOPED_TRACE(s.name);
        s.world_offset = {1e6 + 0.125, -3.5, 2e6};
        const scenario again = load_scenario_text(scenario_to_json_text(s), s.source);
        EXPECT_EQ(again, s);
    }
}

TEST(scenario_loader, relative_to_terrain_false_gives_absolute_heights) {
    const scenario s =
        load(set(with_keyframes(), "/camera/keyframes/0/relative_to_terrain", false));
    EXPECT_FALSE(s.camera.keyframes[0].above_terrain);
    EXPECT_EQ(s.camera.keyframes[0].key.fov_deg, 55.0f);
}

// --- errors: reading the document -----------------------------------------------------------

TEST(scenario_loader, missing_file_cannot_be_opened) {
    const auto path = source_path("tests/scenarios/data/no_such_file.json");
    try {
        load_scenario_file(path);
        ADD_FAILURE() << "loaded a missing file";
    } catch (const scenario_error& e) {
        EXPECT_EQ(e.file(), path.string());
        EXPECT_EQ(e.json_path(), "");
        EXPECT_EQ(e.value(), "");
        EXPECT_EQ(e.problem(), "cannot open file: No such file or directory");
        EXPECT_EQ(std::string(e.what()),
                  path.string() + ": cannot open file: No such file or directory");
    }
}

// --- errors: hostile documents (issue 19) ----------------------------------------------------

scenario_error error_of(const std::string& text) {
    try {
        load_scenario_text(text, k_source);
    } catch (const scenario_error& e) {
        return e;
    }
    ADD_FAILURE() << "loaded " << text.substr(0, 80);
    return scenario_error("", "", "", "");
}

std::string nested(std::size_t levels) { return std::string(levels, '[') + std::string(levels, ']'); }

// On main, nlohmann's out_of_range escaped the loader and aborted the process.
TEST(scenario_loader, a_number_beyond_a_double_is_a_located_error) {
    const scenario_error e = error_of(R"({"terrain": {"size_m": 1e400}, "species": []})");
    EXPECT_EQ(e.json_path(), "/terrain/size_m");
    EXPECT_EQ(e.value(), "1e400");
    EXPECT_THAT(e.problem(), HasSubstr("number out of range"));
    EXPECT_EQ(error_of(R"({"species": [{"name": "a", "height_m": -1e999}]})").json_path(),
              "/species/0/height_m");
    EXPECT_EQ(error_of("{\"frames\": " + std::string(400, '9') + "}").json_path(), "/frames");
}

// On main a million '[' parsed (nlohmann's parser is iterative) and then overflowed the stack in
// describe_value's recursive dump while the error message was built.
TEST(scenario_loader, nesting_beyond_64_levels_is_refused_before_parsing) {
    const scenario_error e = error_of(R"({"name": )" + nested(1000000) + "}");
    // The document's object is level 1, so the 64th '[' (column 10 + 63) opens level 65.
    EXPECT_THAT(e.problem(), HasSubstr("nested deeper than 64 levels at line 1, column 73"));
    EXPECT_THAT(error_of(std::string(1000000, '[')).problem(), HasSubstr("nested deeper than 64"));
    // Within the limit the value is described, cut to about 60 characters.
    const scenario_error within = error_of(R"({"name": )" + nested(60) + "}");
    EXPECT_EQ(within.json_path(), "/name");
    EXPECT_EQ(within.value(), std::string(57, '[') + "...");
}

TEST(scenario_loader, describe_value_never_dumps_more_than_it_shows) {
    json deep = json::array();
    for (int i = 0; i < 100000; ++i) {  // built, not parsed: the reader's depth check never saw it
        json outer = json::array();
        outer.push_back(std::move(deep));
        deep = std::move(outer);
    }
    EXPECT_EQ(describe_value(deep), std::string(57, '[') + "...");
    EXPECT_EQ(describe_value(json::parse(R"({"a": [1, 2], "b": "x"})")), R"({"a":[1,2],"b":"x"})");
    json wide = json::array();
    for (int i = 0; i < 1000000; ++i) wide.push_back(i);
    EXPECT_EQ(describe_value(wide).size(), 60u);
}

TEST(scenario_loader, a_megabyte_key_does_not_flood_the_message) {
    const scenario_error e = error_of("{\"" + std::string(1 << 20, 'k') + "\": 1}");
    EXPECT_THAT(e.problem(), HasSubstr("unknown field"));
    EXPECT_LT(std::string(e.what()).size(), 1000u);
}

// On main /dev/zero was read until memory ran out, and a FIFO blocked forever.
TEST(scenario_loader, refuses_files_that_are_not_regular_or_too_large) {
    try {
        load_scenario_file("/dev/zero");
        ADD_FAILURE() << "loaded /dev/zero";
    } catch (const scenario_error& e) {
        EXPECT_EQ(e.problem(), "is a character device, not a regular file");
    }
    const auto dir = std::filesystem::temp_directory_path() / ("sylva_loader_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "big.json") << std::string(17 << 20, ' ');
    try {
        load_scenario_file(dir / "big.json");
        ADD_FAILURE() << "loaded 17 MB";
    } catch (const scenario_error& e) {
        EXPECT_THAT(e.problem(), HasSubstr("16 MB limit"));
    }
    std::filesystem::remove_all(dir);
}

TEST(scenario_loader, malformed_json_reports_line_and_column) {
    const std::string text = "{\n  \"seed\": 1,\n  \"frames\": }\n";
    try {
        load_scenario_text(text, k_source);
        ADD_FAILURE() << "parsed malformed JSON";
    } catch (const scenario_error& e) {
        EXPECT_EQ(e.json_path(), "");
        EXPECT_EQ(e.value(), "");
        EXPECT_THAT(e.problem(), StartsWith("malformed JSON at line 3, column 13: "));
        EXPECT_THAT(e.problem(), HasSubstr("unexpected '}'"));
        EXPECT_THAT(std::string(e.what()), StartsWith("test.json: malformed JSON at line 3"));
    }
}

TEST(scenario_loader, truncated_json_reports_the_end) {
    try {
        load_scenario_text("{\"seed\": 1", k_source);
        ADD_FAILURE() << "parsed truncated JSON";
    } catch (const scenario_error& e) {
        EXPECT_THAT(e.problem(), StartsWith("malformed JSON at line 1, column 11: "));
    }
}

TEST(scenario_loader, duplicate_keys_are_rejected_where_they_repeat) {
    const std::string text = R"({"species": [{"name": "oak"}],
        "populations": [{"species": "oak", "count": 10}, {"species": "oak", "count": 5, "count": 6}]})";
    try {
        load_scenario_text(text, k_source);
        ADD_FAILURE() << "loaded a duplicate key";
    } catch (const scenario_error& e) {
        EXPECT_EQ(e.json_path(), "/populations/1/count");
        EXPECT_EQ(e.problem(), "duplicate key (each key may appear once)");
        EXPECT_EQ(e.value(), "");
    }
    // The same key in different objects is fine.
    EXPECT_NO_THROW(load_scenario_text(R"({"species": [{"name": "a"}, {"name": "b"}],
        "populations": [{"species": "a", "count": 1}]})",
                                       k_source));
}

TEST(scenario_loader, document_must_be_an_object) {
    expect_error(json::array({1, 2}), {"", "expected an object", "[1,2]"});
}

TEST(scenario_loader, error_message_names_file_pointer_problem_and_value) {
    const auto path = source_path("tests/scenarios/data/bad_keyframe.json");
    try {
        load_scenario_file(path);
        ADD_FAILURE() << "loaded a bad keyframe";
    } catch (const scenario_error& e) {
        EXPECT_EQ(std::string(e.what()), path.string() +
                                             ": /camera/keyframes/2/position: expected an array "
                                             "of 3 numbers (got \"abc\")");
    }
}

// --- errors: unknown fields -----------------------------------------------------------------

TEST(scenario_loader, unknown_top_level_field_lists_the_known_ones) {
    expect_error(set(minimal(), "/sead", 4),
                 {"/sead",
                  "unknown field; expected one of: name, seed, resolution, frames, fps, "
                  "world_offset, terrain, species, populations, camera, sun, environment, shadows, "
                  "render, wang_tiles, shells, eco_tiles, lod",
                  "4"});
}

TEST(scenario_loader, unknown_field_in_every_section_is_rejected) {
    const std::pair<std::string, std::string> cases[] = {
        {"/terrain/size",
         "size_m, resolution, height_m, octaves, frequency, seed, ground_color, heightmap, "
         "tiles_per_side, max_error_px"},
        {"/species/0/heigth_m",
         "name, generator, model, height_m, reduced_distance_m, far_distance_m, max_distance_m, "
         "importance, octree_depth, lighting, implicit, ladder"},
        {"/populations/0/spacing",
         "species, count, min_spacing_m, scale_min, scale_max, area, max_slope_deg, "
         "min_altitude_m, max_altitude_m, placement, density_map, density"},
        {"/populations/0/density/octaves", "frequency, coverage"},
        {"/eco_tiles/depth", "enabled, max_plants_per_tile"},
        {"/camera/fov", "near_m, far_m, lod_scale, keyframes"},
        {"/camera/keyframes/0/fov", "t, position, target, fov_deg, relative_to_terrain"},
        {"/sun/elevation", "keyframes, intensity, turbidity, sky_intensity"},
        {"/sun/keyframes/0/time", "t, elevation_deg, azimuth_deg"},
        {"/environment/rotation_deg", "map, map_rotation_deg"},
        {"/shadows/bias", "cascades, resolution, max_distance_m, split_lambda"},
        {"/render/msaa", "shadows, exposure, style"},
        {"/lod/d",
         "representation, sample_distance_px, splat_factor, splats, fog_weighted_samples, "
         "primitive_budget, "
         "target_frame_ms, "
         "cloud_distance_m, lighting, sh_bands, sh_interreflection, ladder, plant_budget_ms, "
         "max_error, gain_per_ms, lodf_slots"},
    };
    for (const auto& [pointer, known] : cases) {
        SCOPED_TRACE(pointer);
        expect_error(set(with_keyframes(), pointer, true),
                     {pointer, "unknown field; expected one of: " + known, "true"});
    }
}

TEST(scenario_loader, unknown_field_path_escapes_slash_and_tilde) {
    json j = minimal();
    j["terrain"]["a/b~c"] = 1;
    expect_error(j, {"/terrain/a~1b~0c",
                     "unknown field; expected one of: size_m, resolution, height_m, octaves, "
                     "frequency, seed, ground_color, heightmap, tiles_per_side, max_error_px",
                     "1"});
}

// --- errors: types --------------------------------------------------------------------------

TEST(scenario_loader, wrong_types_are_named) {
    const expected_error cases[] = {
        {"/camera/keyframes/0/position", "expected an array of 3 numbers", "\"abc\""},
        {"/terrain", "expected an object", "\"abc\""},
        {"/species", "expected an array", "\"abc\""},
        {"/frames", "expected an integer from 1 to 1000000", "\"abc\""},
        {"/fps", "expected a number", "\"abc\""},
        {"/render/shadows", "expected true or false", "\"abc\""},
        {"/render/style", "unknown value; expected one of: photo, toon, lines", "\"abc\""},
        {"/species/0/generator",
         "unknown value; expected one of: broadleaf, broadleaf_hd, conifer, shrub, grass, "
         "flower, fern",
         "\"abc\""},
        {"/name", "expected a string", "7"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.json_path);
        const json value = c.value == "7" ? json(7) : json("abc");
        expect_error(set(with_keyframes(), c.json_path, value), c);
    }
}

TEST(scenario_loader, integers_must_be_written_as_integers) {
    expect_error(set(minimal(), "/frames", 4.5),
                 {"/frames", "expected an integer from 1 to 1000000", "4.5"});
    expect_error(set(minimal(), "/frames", 4.0),
                 {"/frames", "expected an integer from 1 to 1000000", "4.0"});
}

TEST(scenario_loader, vector_with_a_wrong_element_is_rejected_as_a_whole) {
    expect_error(set(minimal(), "/world_offset", json::array({1, "2", 3})),
                 {"/world_offset", "expected an array of 3 numbers", "[1,\"2\",3]"});
    expect_error(set(minimal(), "/terrain/ground_color", json::array({0.5, 0.5})),
                 {"/terrain/ground_color", "expected an array of 3 numbers", "[0.5,0.5]"});
}

TEST(scenario_loader, long_values_are_cut_in_the_message) {
    const std::string long_name(200, 'x');
    try {
        load(set(minimal(), "/frames", long_name));
        ADD_FAILURE() << "loaded a string as frames";
    } catch (const scenario_error& e) {
        EXPECT_LE(e.value().size(), 60u);
        EXPECT_THAT(e.value(), StartsWith("\"xxxx"));
        EXPECT_THAT(e.value(), ::testing::EndsWith("..."));
    }
}

// --- errors: ranges -------------------------------------------------------------------------

struct range_case {
    std::string pointer;
    json min_ok, max_ok, below, above;
    std::string problem;
};

TEST(scenario_loader, values_at_the_limits_load_and_just_outside_are_rejected) {
    const range_case cases[] = {
        {"/resolution/0", 1, 16384, 0, 16385, "out of range; expected an integer from 1 to 16384"},
        {"/resolution/1", 1, 16384, -1, 16385, "out of range; expected an integer from 1 to 16384"},
        {"/frames", 1, 1000000, 0, 1000001, "out of range; expected an integer from 1 to 1000000"},
        {"/fps", 1, 1000, 0.99, 1000.5, "out of range; expected a number from 1 to 1000"},
        {"/terrain/size_m", 1, 1e5, 0.5, 100001,
         "out of range; expected a number from 1 to 100000"},
        {"/terrain/resolution", 2, 4097, 1, 4098,
         "out of range; expected an integer from 2 to 4097"},
        {"/terrain/octaves", 1, 16, 0, 17, "out of range; expected an integer from 1 to 16"},
        {"/terrain/max_error_px", 0, 64, -0.5, 64.5,
         "out of range; expected a number from 0 to 64"},
        {"/terrain/ground_color/1", 0, 1, -0.01, 1.01,
         "out of range; expected a number from 0 to 1"},
        {"/species/0/height_m", 0.1, 150, 0.09, 150.5,
         "out of range; expected a number from 0.1 to 150"},
        {"/populations/0/count", 1, 10000000, 0, 10000001,
         "out of range; expected an integer from 1 to 10000000"},
        {"/populations/0/max_slope_deg", 0, 90, -1, 91,
         "out of range; expected a number from 0 to 90"},
        {"/camera/lod_scale", 0.01, 100, 0.009, 101,
         "out of range; expected a number from 0.01 to 100"},
        {"/camera/keyframes/0/fov_deg", 5, 150, 4.9, 150.1,
         "out of range; expected a number from 5 to 150"},
        {"/camera/keyframes/0/t", 0, 1e6, -0.001, 1000001,
         "out of range; expected a number from 0 to 1000000"},
        {"/sun/keyframes/0/elevation_deg", -90, 90, -90.5, 90.5,
         "out of range; expected a number from -90 to 90"},
        {"/sun/keyframes/0/azimuth_deg", 0, 360, -0.5, 360.5,
         "out of range; expected a number from 0 to 360"},
        {"/sun/intensity", 0, 1e6, -1, 1e6 + 1,
         "out of range; expected a number from 0 to 1000000"},
        {"/sun/turbidity", 1.7, 10, 1.69, 10.01, "out of range; expected a number from 1.7 to 10"},
        {"/shadows/cascades", 1, 4, 0, 5, "out of range; expected an integer from 1 to 4"},
        {"/shadows/resolution", 256, 8192, 128, 16384,
         "out of range; expected an integer from 256 to 8192"},
        {"/shadows/split_lambda", 0, 1, -0.01, 1.01, "out of range; expected a number from 0 to 1"},
        {"/render/exposure", 0.001, 1000, 0.0009, 1001,
         "out of range; expected a number from 0.001 to 1000"},
        {"/eco_tiles/max_plants_per_tile", 1, 1000000, 0, 1000001,
         "out of range; expected an integer from 1 to 1000000"},
        {"/populations/0/density/coverage", 0, 1, -0.01, 1.01,
         "out of range; expected a number from 0 to 1"},
        {"/populations/0/density/frequency", 0.01, 1000, 0.009, 1001,
         "out of range; expected a number from 0.01 to 1000"},
        {"/populations/0/min_altitude_m", -1e9, 1e9, -1.5e9, 1.5e9,
         "out of range; expected a number from -1000000000 to 1000000000"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.pointer);
        EXPECT_NO_THROW(load(set(with_keyframes(), c.pointer, c.min_ok)));
        EXPECT_NO_THROW(load(set(with_keyframes(), c.pointer, c.max_ok)));
        expect_error(set(with_keyframes(), c.pointer, c.below),
                     {c.pointer, c.problem, c.below.dump()});
        expect_error(set(with_keyframes(), c.pointer, c.above),
                     {c.pointer, c.problem, c.above.dump()});
    }
}

TEST(scenario_loader, seeds_take_the_whole_64_bit_range) {
    const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
    EXPECT_EQ(load(set(minimal(), "/seed", max)).seed, max);
    EXPECT_EQ(load(set(minimal(), "/terrain/seed", 0)).terrain.seed, 0u);
    expect_error(
        set(minimal(), "/seed", -1),
        {"/seed", "out of range; expected an integer from 0 to 18446744073709551615", "-1"});
}

TEST(scenario_loader, resolution_must_be_two_integers) {
    expect_error(set(minimal(), "/resolution", json::array({960})),
                 {"/resolution", "expected an array of 2 integers [width, height]", "[960]"});
}

TEST(scenario_loader, shadow_resolution_must_be_a_power_of_two) {
    expect_error(set(minimal(), "/shadows/resolution", 1000),
                 {"/shadows/resolution", "expected a power of two (256, 512, ..., 8192)", "1000"});
    EXPECT_EQ(load(set(minimal(), "/shadows/resolution", 2048)).shadows.resolution, 2048u);
}

// --- errors: structure and references -------------------------------------------------------

TEST(scenario_loader, missing_required_items_are_named) {
    json no_species = minimal();
    no_species.erase("species");
    expect_error(no_species, {"/species", "missing required item \"species\"", "nothing"});
    json no_populations = minimal();
    no_populations.erase("populations");
    expect_error(no_populations,
                 {"/populations", "missing required item \"populations\"", "nothing"});
    json no_count = minimal();
    no_count["populations"][0].erase("count");
    expect_error(no_count, {"/populations/0/count", "missing required item \"count\"", "nothing"});
    json no_time = with_keyframes();
    no_time["camera"]["keyframes"][0].erase("t");
    expect_error(no_time, {"/camera/keyframes/0/t", "missing required item \"t\"", "nothing"});
    json no_name = minimal();
    no_name["species"][0].erase("name");
    expect_error(no_name, {"/species/0/name", "missing required item \"name\"", "nothing"});
}

TEST(scenario_loader, empty_lists_are_rejected) {
    for (const std::string pointer :
         {"/species", "/populations", "/camera/keyframes", "/sun/keyframes"}) {
        SCOPED_TRACE(pointer);
        expect_error(set(minimal(), pointer, json::array()),
                     {pointer, "expected at least 1 item", "[]"});
    }
}

TEST(scenario_loader, population_must_name_a_known_species) {
    json j = minimal();
    j["species"].push_back({{"name", "spruce"}, {"generator", "conifer"}});
    j["populations"][0]["species"] = "elm";
    expect_error(
        j, {"/populations/0/species", "unknown species; expected one of: oak, spruce", "\"elm\""});
}

TEST(scenario_loader, species_names_must_be_unique) {
    json j = minimal();
    j["species"].push_back({{"name", "oak"}, {"generator", "conifer"}});
    expect_error(
        j, {"/species/1/name", "duplicate species name (first at /species/0/name)", "\"oak\""});
}

TEST(scenario_loader, empty_species_name_is_rejected) {
    expect_error(set(minimal(), "/species/0/name", ""),
                 {"/species/0/name", "expected a non-empty string", "\"\""});
}

TEST(scenario_loader, camera_keyframe_times_must_increase_strictly) {
    json j = with_keyframes();
    j["camera"]["keyframes"].push_back(
        json::parse(R"({"t": 1, "position": [1, 10, 0], "target": [10, 10, 0]})"));
    j["camera"]["keyframes"].push_back(
        json::parse(R"({"t": 1, "position": [2, 10, 0], "target": [10, 10, 0]})"));
    expect_error(j, {"/camera/keyframes/2/t",
                     "keyframe times must be strictly increasing (previous: 1)", "1"});
}

TEST(scenario_loader, sun_keyframe_times_must_increase_strictly) {
    json j = with_keyframes();
    j["sun"]["keyframes"].push_back(
        json::parse(R"({"t": 2.5, "elevation_deg": 30, "azimuth_deg": 100})"));
    j["sun"]["keyframes"].push_back(
        json::parse(R"({"t": 0.5, "elevation_deg": 30, "azimuth_deg": 100})"));
    expect_error(j, {"/sun/keyframes/2/t",
                     "keyframe times must be strictly increasing (previous: 2.5)", "0.5"});
}

TEST(scenario_loader, camera_must_look_somewhere) {
    expect_error(
        set(with_keyframes(), "/camera/keyframes/0/target", json::array({0, 10, 0})),
        {"/camera/keyframes/0/target",
         "must differ from position (the camera looks along target - position)", "[0,10,0]"});
}

TEST(scenario_loader, area_must_not_be_empty) {
    expect_error(set(minimal(), "/populations/0/area", json::array({10, 0, 10, 5})),
                 {"/populations/0/area", "empty area: x0 must be less than x1", "[10,0,10,5]"});
    expect_error(set(minimal(), "/populations/0/area", json::array({0, 5, 10, 4})),
                 {"/populations/0/area", "empty area: z0 must be less than z1", "[0,5,10,4]"});
    expect_error(
        set(minimal(), "/populations/0/area", json::array({0, 5, 10})),
        {"/populations/0/area", "expected an array of 4 numbers [x0, z0, x1, z1]", "[0,5,10]"});
}

TEST(scenario_loader, ordered_pairs_are_checked_at_the_stated_key) {
    expect_error(set(minimal(), "/populations/0/scale_min", 1.5),
                 {"/populations/0/scale_min", "must be at most scale_max (1.2)", "1.5"});
    expect_error(set(minimal(), "/populations/0/scale_max", 0.5),
                 {"/populations/0/scale_max", "must be at least scale_min (0.8)", "0.5"});
    expect_error(set(minimal(), "/camera/far_m", 0.3),
                 {"/camera/far_m", "must be greater than near_m (0.3)", "0.3"});
    expect_error(
        set(minimal(), "/species/0/reduced_distance_m", 2000),
        {"/species/0/reduced_distance_m", "must be at most far_distance_m (200)", "2000"});
    expect_error(
        set(minimal(), "/species/0/far_distance_m", 2000),
        {"/species/0/far_distance_m", "must be at most max_distance_m (1500)", "2000"});
}

TEST(scenario_loader, only_the_first_problem_is_reported) {
    json j = set(minimal(), "/frames", 0);
    j["fps"] = 0;
    j["bogus"] = 1;
    // Unknown keys are checked before any field; fields in their documented order.
    expect_error(j, {"/bogus",
                     "unknown field; expected one of: name, seed, resolution, frames, fps, "
                     "world_offset, terrain, species, populations, camera, sun, environment, "
                     "shadows, render, wang_tiles, shells, eco_tiles, lod",
                     "1"});
    j.erase("bogus");
    expect_error(j, {"/frames", "out of range; expected an integer from 1 to 1000000", "0"});
}

// --- terrain, placement and eco tile fields ----------------------------------------------

// A scenario file in a fresh folder next to the (empty) files its paths name; only existence
// is checked at load time.
class scenario_folder {
public:
    explicit scenario_folder(std::string_view name)
        : m_root(std::filesystem::temp_directory_path() / ("sylva_scenario_" + std::string(name))) {
        std::filesystem::remove_all(m_root);
        std::filesystem::create_directories(m_root / "maps");
        for (const char* file : {"maps/hills.png", "maps/meadow.png", "oak.glb", "maps/sky.hdr"})
            std::ofstream(m_root / file) << "x";
    }
    ~scenario_folder() { std::filesystem::remove_all(m_root); }
    const std::filesystem::path& root() const { return m_root; }
    scenario load(const json& j) const {
        std::ofstream(m_root / "s.json") << j.dump();
        return load_scenario_file(m_root / "s.json");
    }

private:
    std::filesystem::path m_root;
};

TEST(scenario_loader, new_fields_default_to_todays_behaviour) {
    const scenario s = load(minimal());
    EXPECT_TRUE(s.terrain.heightmap.empty());
    EXPECT_EQ(s.terrain.tiles_per_side, 1u);
    EXPECT_TRUE(s.species[0].model.empty());
    const population_settings& p = s.populations[0];
    EXPECT_EQ(p.placement, "poisson");
    EXPECT_TRUE(p.density_map.empty());
    EXPECT_FALSE(p.density.enabled);
    EXPECT_EQ(p.min_altitude_m, -1e9f);
    EXPECT_EQ(p.max_altitude_m, 1e9f);
    EXPECT_TRUE(s.eco_tiles.enabled);
    EXPECT_EQ(s.eco_tiles.max_plants_per_tile, 256u);
    EXPECT_TRUE(s.environment.map.empty());
    EXPECT_EQ(s.environment.map_rotation_deg, 0.0f);
}

TEST(scenario_loader, paths_are_resolved_against_the_scenario_folder_and_stored_absolute) {
    const scenario_folder folder("paths");
    json j = set(minimal(), "/terrain/heightmap", "maps/hills.png");
    j["species"][0]["model"] = "./oak.glb";
    j["populations"][0]["density_map"] = "maps/../maps/meadow.png";
    j["environment"] = {{"map", "maps/sky.hdr"}, {"map_rotation_deg", -90}};
    const scenario s = folder.load(j);
    const auto root = std::filesystem::absolute(folder.root()).lexically_normal();
    EXPECT_EQ(s.terrain.heightmap, (root / "maps/hills.png").string());
    EXPECT_EQ(s.species[0].model, (root / "oak.glb").string());
    EXPECT_EQ(s.populations[0].density_map, (root / "maps/meadow.png").string());
    // Absolute paths load as they are, so the text written back loads the same scenario.
    const scenario again = load_scenario_text(scenario_to_json_text(s), "elsewhere/x.json");
    EXPECT_EQ(again.terrain, s.terrain);
    EXPECT_EQ(again.species, s.species);
    EXPECT_EQ(again.populations, s.populations);
    EXPECT_EQ(s.environment.map, (root / "maps/sky.hdr").string());
    EXPECT_EQ(s.environment.map_rotation_deg, -90.0f);
    EXPECT_EQ(again.environment, s.environment);
}

TEST(scenario_loader, environment_map_rotation_is_in_range_and_needs_a_map) {
    const scenario_folder folder("environment");
    const json with_map = set(minimal(), "/environment/map", "maps/sky.hdr");
    EXPECT_EQ(folder.load(set(with_map, "/environment/map_rotation_deg", 360))
                  .environment.map_rotation_deg,
              360.0f);
    EXPECT_EQ(folder.load(set(with_map, "/environment/map_rotation_deg", -360))
                  .environment.map_rotation_deg,
              -360.0f);
    for (double outside : {-360.5, 360.5}) {
        try {
            folder.load(set(with_map, "/environment/map_rotation_deg", outside));
            ADD_FAILURE() << "loaded " << outside;
        } catch (const scenario_error& e) {
            EXPECT_EQ(e.json_path(), "/environment/map_rotation_deg");
            EXPECT_EQ(e.problem(), "out of range; expected a number from -360 to 360");
        }
    }
    expect_error(
        set(minimal(), "/environment/map_rotation_deg", 45),
        {"/environment/map_rotation_deg", "turns the environment map; give map too", "45"});
}

TEST(scenario_loader, missing_files_are_named_at_their_json_path) {
    const scenario_folder folder("missing");
    for (const std::string pointer : {"/terrain/heightmap", "/species/0/model",
                                      "/populations/0/density_map", "/environment/map"}) {
        SCOPED_TRACE(pointer);
        try {
            folder.load(set(minimal(), pointer, "nope.glb"));
            ADD_FAILURE() << "loaded";
        } catch (const scenario_error& e) {
            EXPECT_EQ(e.json_path(), pointer);
            EXPECT_EQ(e.problem(),
                      "file not found: " +
                          (std::filesystem::absolute(folder.root()) / "nope.glb").string());
        }
    }
}

TEST(scenario_loader, placement_density_and_altitude_fields_load_and_round_trip) {
    json j = minimal();
    j["populations"][0]["placement"] = "jittered";
    j["populations"][0]["density"] = {{"frequency", 8}, {"coverage", 0.25}};
    j["populations"][0]["min_altitude_m"] = -5;
    j["populations"][0]["max_altitude_m"] = 12.5;
    j["terrain"]["tiles_per_side"] = 8;
    j["eco_tiles"] = {{"enabled", false}, {"max_plants_per_tile", 64}};
    const scenario s = load(j);
    const population_settings& p = s.populations[0];
    EXPECT_EQ(p.placement, "jittered");
    EXPECT_TRUE(p.density.enabled);
    EXPECT_EQ(p.density.frequency, 8.0f);
    EXPECT_EQ(p.density.coverage, 0.25f);
    EXPECT_EQ(p.min_altitude_m, -5.0f);
    EXPECT_EQ(p.max_altitude_m, 12.5f);
    EXPECT_EQ(s.terrain.tiles_per_side, 8u);
    EXPECT_FALSE(s.eco_tiles.enabled);
    EXPECT_EQ(s.eco_tiles.max_plants_per_tile, 64u);
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(s), k_source), s);
}

TEST(scenario_loader, lod_section_and_species_importance_load_and_round_trip) {
    json j = minimal();
    j["lod"] = {{"representation", "points_lines"}, {"sample_distance_px", 2.5}, {"splat_factor", 1.5},
                {"primitive_budget", 250000}};
    j["species"][0]["importance"] = 3;
    j["species"][0]["octree_depth"] = 1;
    const scenario s = load(j);
    EXPECT_EQ(s.lod.representation, "points_lines");
    EXPECT_EQ(s.lod.sample_distance_px, 2.5f);
    EXPECT_EQ(s.lod.splat_factor, 1.5f);
    EXPECT_EQ(s.lod.primitive_budget, 250000.0);
    EXPECT_EQ(s.species[0].importance, 3.0f);
    EXPECT_EQ(s.species[0].octree_depth, 1u);
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(s), k_source), s);
    EXPECT_EQ(load(minimal()).lod.representation, "mesh_levels");
}

TEST(scenario_loader, fog_weighted_samples_default_on_and_round_trip) {
    EXPECT_TRUE(load(minimal()).lod.fog_weighted_samples);
    json j = minimal();
    j["lod"] = {{"representation", "points_lines"}, {"fog_weighted_samples", false}};
    const scenario s = load(j);
    EXPECT_FALSE(s.lod.fog_weighted_samples);
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(s), k_source), s);
    j["lod"]["fog_weighted_samples"] = "yes";
    try {
        load(j);
        FAIL() << "a string is not a boolean";
    } catch (const scenario_error& e) {
        EXPECT_EQ(e.json_path(), "/lod/fog_weighted_samples");
    }
}

TEST(scenario_loader, splat_style_loads_defaults_to_soft_and_rejects_other_names) {
    EXPECT_EQ(load(minimal()).lod.splats, "soft");
    json j = minimal();
    j["lod"] = {{"representation", "points_lines"}, {"splats", "opaque"}};
    const scenario s = load(j);
    EXPECT_EQ(s.lod.splats, "opaque");
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(s), k_source), s);
    j["lod"]["splats"] = "fuzzy";
    try {
        load(j);
        FAIL() << "an unknown splat style must be rejected";
    } catch (const scenario_error& e) {
        EXPECT_EQ(e.json_path(), "/lod/splats");
        EXPECT_NE(std::string(e.what()).find("fuzzy"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("opaque"), std::string::npos) << e.what();
    }
}

TEST(scenario_loader, billboard_cloud_fields_load_default_and_round_trip) {
    json j = minimal();
    j["lod"] = {
        {"representation", "billboard_clouds"}, {"cloud_distance_m", 45}, {"lighting", "pre_lit"}};
    const scenario s = load(j);
    EXPECT_EQ(s.lod.representation, "billboard_clouds");
    EXPECT_EQ(s.lod.cloud_distance_m, 45.0f);
    EXPECT_EQ(s.lod.lighting, "pre_lit");
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(s), k_source), s);
    const scenario d = load(minimal());
    EXPECT_EQ(d.lod.cloud_distance_m, 30.0f);  // Behrendt 2005 §2.3: "closer than 30 meters"
    EXPECT_EQ(d.lod.lighting, "normal_mapped");
    EXPECT_EQ(d.lod.sh_bands, 3u);
    EXPECT_EQ(d.lod.lodf_slots, 32u);
    EXPECT_EQ(d.species[0].lighting, "scenario");
}

TEST(scenario_loader, species_lighting_overrides_and_round_trips) {
    json j = minimal();
    j["lod"] = {{"lighting", "sh"}, {"sh_bands", 2}, {"sh_interreflection", true}, {"lodf_slots", 1000}};
    j["species"][0]["lighting"] = "pre_lit";
    const scenario s = load(j);
    EXPECT_EQ(s.lod.lodf_slots, 1000u);
    EXPECT_EQ(s.lod.lighting, "sh");
    EXPECT_EQ(s.lod.sh_bands, 2u);
    EXPECT_TRUE(s.lod.sh_interreflection);
    EXPECT_EQ(s.species[0].lighting, "pre_lit");
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(s), k_source), s);
}

TEST(scenario_loader, implicit_lighting_parameters_load_and_round_trip) {
    json j = minimal();
    j["species"][0]["lighting"] = "implicit";
    j["species"][0]["implicit"] = {{"rho_m", 0.8},       {"tau", 2.5},
                                   {"ka_min", 0.2},      {"exponent", 3},
                                   {"blend", 0.5},       {"generator_fraction", 0.1},
                                   {"population", true}, {"depth_min_m", 1.5}};
    const scenario s = load(j);
    EXPECT_EQ(s.species[0].implicit.ambient_from, "depth");  // the default
    EXPECT_FLOAT_EQ(s.species[0].implicit.depth_min_m, 1.5f);
    EXPECT_TRUE(s.species[0].implicit.population);
    EXPECT_EQ(s.species[0].lighting, "implicit");
    EXPECT_FLOAT_EQ(s.species[0].implicit.rho_m, 0.8f);
    EXPECT_FLOAT_EQ(s.species[0].implicit.tau, 2.5f);
    EXPECT_FLOAT_EQ(s.species[0].implicit.ka_min, 0.2f);
    EXPECT_FLOAT_EQ(s.species[0].implicit.exponent, 3.0f);
    EXPECT_FLOAT_EQ(s.species[0].implicit.blend, 0.5f);
    EXPECT_FLOAT_EQ(s.species[0].implicit.generator_fraction, 0.1f);
    EXPECT_FLOAT_EQ(s.species[0].implicit.d_min, 0.0f);  // derived from the model
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(s), k_source), s);
    j["species"][0]["implicit"]["ambient_from"] = "density";
    const scenario paper = load(j);
    EXPECT_EQ(paper.species[0].implicit.ambient_from, "density");
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(paper), k_source), paper);
}

TEST(scenario_loader, lod_fields_name_the_bad_value) {
    expect_error(set(minimal(), "/lod/representation", "voxels"),
                 {"/lod/representation", "unknown value; expected one of: mesh_levels, points_lines, billboard_clouds, ladder",
                  "\"voxels\""});
    expect_error(set(minimal(), "/lod/cloud_distance_m", 0),
                 {"/lod/cloud_distance_m", "out of range; expected a number from 0.1 to 100000", "0"});
    expect_error(set(minimal(), "/lod/lighting", "shiny"),
                 {"/lod/lighting", "unknown value; expected one of: normal_mapped, pre_lit, sh, implicit, sh_implicit",
                  "\"shiny\""});
    expect_error(set(minimal(), "/lod/sh_bands", 4),
                 {"/lod/sh_bands", "out of range; expected an integer from 2 to 3", "4"});
    expect_error(set(minimal(), "/lod/lodf_slots", 0),
                 {"/lod/lodf_slots", "out of range; expected an integer from 1 to 65536", "0"});
    expect_error(
        set(minimal(), "/species/0/lighting", "sh3"),
        {"/species/0/lighting",
         "unknown value; expected one of: scenario, normal_mapped, pre_lit, sh, implicit, sh_implicit",
         "\"sh3\""});
    expect_error(set(set(minimal(), "/species/0/lighting", "implicit"), "/species/0/implicit", json{{"ka_min", 1.5}}),
                 {"/species/0/implicit/ka_min", "out of range; expected a number from 0 to 1", "1.5"});
    expect_error(set(minimal(), "/species/0/implicit", json{{"rho", 1}}),
                 {"/species/0/implicit/rho",
                  "unknown field; expected one of: generator_fraction, rho_m, tau, ka_min, "
                  "ambient_from, d_min, depth_min_m, exponent, blend, population",
                  "1"});
    expect_error(set(minimal(), "/species/0/implicit", json{{"ambient_from", "occlusion"}}),
                 {"/species/0/implicit/ambient_from",
                  "unknown value; expected one of: depth, density", "\"occlusion\""});
    expect_error(set(minimal(), "/species/0/implicit", json{{"population", 1}}),
                 {"/species/0/implicit/population", "expected true or false", "1"});
    expect_error(set(minimal(), "/lod/sample_distance_px", 0),
                 {"/lod/sample_distance_px", "out of range; expected a number from 0.05 to 64", "0"});
    expect_error(set(minimal(), "/lod/splat_factor", 0.5),
                 {"/lod/splat_factor", "out of range; expected a number from 1 to 4", "0.5"});
    expect_error(set(minimal(), "/species/0/importance", 0),
                 {"/species/0/importance", "out of range; expected a number from 0.01 to 100", "0"});
    json both = minimal();
    both["lod"] = {{"primitive_budget", 1000}, {"target_frame_ms", 30}};
    expect_error(both, {"/lod/target_frame_ms", "give either primitive_budget or target_frame_ms, not both", "30"});
}

TEST(scenario_loader, wang_tiled_populations_load_round_trip_and_refuse_rules_a_tile_cannot_keep) {
    json j = minimal();
    j["populations"][0]["placement"] = "wang_tiles";
    j["populations"][0]["min_spacing_m"] = 2;
    j["wang_tiles"] = {{"tile_size_m", 20}, {"colours", 3}};
    const scenario s = load(j);
    EXPECT_EQ(s.populations[0].placement, "wang_tiles");
    EXPECT_EQ(s.wang_tiles.tile_size_m, 20.0);
    EXPECT_EQ(s.wang_tiles.colours, 3u);
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(s), k_source), s);
    EXPECT_EQ(load(minimal()).wang_tiles, wang_tile_settings{});
    const std::string rules_refused = "a population with placement \"wang_tiles\" is its tiles' plants wherever a tile lies (so a shell of the tile shows exactly them): slope, altitude and density rules cannot apply to it";
    expect_error(set(j, "/populations/0/max_slope_deg", 20), {"/populations/0/max_slope_deg", rules_refused, "20"});
    expect_error(set(j, "/populations/0/density", json{{"coverage", 0.5}}),
                 {"/populations/0/density", rules_refused, "{\"coverage\":0.5}"});
    // 2 m of spacing needs 5.41 x 2 = 10.83 m tiles.
    expect_error(set(j, "/wang_tiles/tile_size_m", 10),
                 {"/populations/0/min_spacing_m",
                  "a tile of 10 m is too small for a spacing of 2 m: it needs at least 10.83 m (5.41 x the spacing: corner "
                  "squares and edge strips on both sides, and an interior) (wang_tiles.tile_size_m)",
                  "2"});
    json two = j;
    two["populations"].push_back({{"species", "oak"}, {"count", 5}, {"placement", "wang_tiles"}, {"area", {0, 0, 50, 50}}});
    expect_error(two, {"/populations/1/area",
                       "every population with placement \"wang_tiles\" must grow on the same area (its shells cover one area)",
                       "[0,0,50,50]"});
    expect_error(set(j, "/wang_tiles/colours", 5),
                 {"/wang_tiles/colours", "out of range; expected an integer from 2 to 4", "5"});
    // How the shells draw: Eq. 2's f and the half-resolution layer, both round trip.
    json shells = j;
    shells["shells"] = {{"slant", 0.25}, {"half_resolution", false}};
    const scenario with = load(shells);
    EXPECT_EQ(with.shells.slant, 0.25);
    EXPECT_FALSE(with.shells.half_resolution);
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(with), k_source), with);
    EXPECT_EQ(load(minimal()).shells, shell_settings{});
    expect_error(set(j, "/shells/slant", 5), {"/shells/slant", "out of range; expected a number from 0 to 4", "5"});
    EXPECT_EQ(load(set(j, "/shells/blending", "standard")).shells.blending, "standard");
    expect_error(set(j, "/shells/blending", "additive"),
                 {"/shells/blending", "unknown value; expected one of: premultiplied, standard", "\"additive\""});
}

TEST(scenario_loader, placement_mode_and_generator_presets_are_choices) {
    expect_error(set(minimal(), "/populations/0/placement", "grid"),
                 {"/populations/0/placement", "unknown value; expected one of: poisson, jittered, wang_tiles",
                  "\"grid\""});
    for (const auto generator : k_tree_generators)
        EXPECT_EQ(load(set(minimal(), "/species/0/generator", generator)).species[0].generator,
                  generator);
}

TEST(scenario_loader, density_map_and_procedural_density_exclude_each_other) {
    const scenario_folder folder("both");
    json j = set(minimal(), "/populations/0/density_map", "maps/meadow.png");
    j["populations"][0]["density"] = {{"coverage", 0.5}};
    try {
        folder.load(j);
        ADD_FAILURE() << "loaded";
    } catch (const scenario_error& e) {
        EXPECT_EQ(e.json_path(), "/populations/0/density");
        EXPECT_EQ(e.problem(), "give either density_map or density, not both");
    }
}

TEST(scenario_loader, altitudes_must_be_ordered_and_tiles_fit_the_grid) {
    json j = set(minimal(), "/populations/0/min_altitude_m", 10);
    j["populations"][0]["max_altitude_m"] = 5;
    expect_error(j, {"/populations/0/min_altitude_m", "must be at most max_altitude_m (5)", "10"});
    expect_error(set(set(minimal(), "/terrain/resolution", 9), "/terrain/tiles_per_side", 9),
                 {"/terrain/tiles_per_side",
                  "must be at most resolution - 1 (8): a tile holds at least one grid cell", "9"});
    EXPECT_EQ(load(set(set(minimal(), "/terrain/resolution", 4097), "/terrain/tiles_per_side", 256))
                  .terrain.tiles_per_side,
              256u);
    expect_error(
        set(set(minimal(), "/terrain/resolution", 4097), "/terrain/tiles_per_side", 257),
        {"/terrain/tiles_per_side", "out of range; expected an integer from 1 to 256", "257"});
}

}  // namespace
}  // namespace sylva
