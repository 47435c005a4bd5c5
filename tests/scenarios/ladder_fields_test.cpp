// The `ladder` arrays of the lod section and of a species: read into the runtime's ladder, written
// back, and every bad ladder refused with the JSON path of the rung and field at fault.
#include "scenarios/ladder_fields.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

using nlohmann::json;

json with_ladder(json ladder, const std::string& where = "/lod/ladder") {
    json j = json::parse(R"({"species": [{"name": "oak"}], "populations": [{"species": "oak", "count": 10}],
                             "lod": {"representation": "ladder"}})");
    j[json::json_pointer(where)] = std::move(ladder);
    return j;
}

scenario load(const json& j) { return load_scenario_text(j.dump(), "test.json"); }

void expect_error(const json& j, const std::string& path, const std::string& problem_start) {
    try {
        load(j);
        ADD_FAILURE() << "loaded without error: " << j.dump();
    } catch (const scenario_error& e) {
        EXPECT_EQ(e.json_path(), path) << e.what();
        EXPECT_EQ(e.problem().substr(0, problem_start.size()), problem_start) << e.what();
    }
}

const json k_three = json::parse(R"([{"rung": "mesh_full"},
                                     {"rung": "billboard_cloud", "below_px": 200, "band": 0.1},
                                     {"rung": "points_lines", "below_px": 50}])");

TEST(ladder_fields, a_ladder_reads_into_the_runtime_ladder_with_the_default_band) {
    const scenario s = load(with_ladder(k_three));
    EXPECT_EQ(s.lod.representation, "ladder");
    const ladder l = ladder_of(s.lod.ladder);
    ASSERT_EQ(l.count, 3);
    EXPECT_EQ(l.rungs[0], representation::mesh_full);
    EXPECT_EQ(l.rungs[1], representation::billboard_cloud);
    EXPECT_EQ(l.rungs[2], representation::points);
    EXPECT_EQ(l.below_px[1], 200.0f);
    EXPECT_EQ(l.band[1], 0.1f);
    EXPECT_EQ(l.band[2], k_default_band);
    EXPECT_TRUE(s.species[0].ladder.empty()) << "a species without a ladder takes the lod section's";
}

TEST(ladder_fields, a_species_ladder_round_trips_and_an_empty_one_is_not_written) {
    const scenario s = load(with_ladder(k_three, "/species/0/ladder"));
    EXPECT_TRUE(s.lod.ladder.empty());
    EXPECT_EQ(ladder_of(s.species[0].ladder).count, 3);
    const std::string text = scenario_to_json_text(s);
    EXPECT_EQ(load_scenario_text(text, "round_trip.json").species[0].ladder, s.species[0].ladder);
    EXPECT_EQ(json::parse(text)["lod"].count("ladder"), 0u);
}

TEST(ladder_fields, bad_ladders_name_the_rung_and_the_field) {
    expect_error(with_ladder(json::array()), "/lod/ladder", "expected");
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full"}, {"rung": "points", "below_px": 9}])")),
                 "/lod/ladder/1/rung", "unknown value; expected one of");
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full", "below_px": 300}])")),
                 "/lod/ladder/0/below_px", "the first rung");
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full"}, {"rung": "points_lines"}])")),
                 "/lod/ladder/1/below_px", "missing required item");
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full"}, {"rung": "mesh_full", "below_px": 9}])")),
                 "/lod/ladder/1/rung", "mesh_full is already rung 0");
    // 100 px after 50 px: switch sizes must fall from rung to rung.
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full"}, {"rung": "billboard_cloud", "below_px": 50},
                                            {"rung": "crossed_billboard", "below_px": 100}])"),
                             "/species/0/ladder"),
                 "/species/0/ladder/2/below_px", "below_px must be smaller");
    // 45 x 1.15 = 51.75 px reaches into 50 x 0.85 = 42.5 px: the bands overlap. The band left at
    // its default is not in the file, so the rung stands for it.
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full"}, {"rung": "billboard_cloud", "below_px": 50},
                                            {"rung": "crossed_billboard", "below_px": 45}])")),
                 "/lod/ladder/2", "its band");
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full"}, {"rung": "billboard_cloud", "below_px": 50,
                                             "band": 0.95}])")),
                 "/lod/ladder/1/band", "out of range; expected a number from 0 to 0.9");
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full"}, {"rung": "billboard_cloud", "below_px": 50,
                                             "fade": 1}])")),
                 "/lod/ladder/1/fade", "unknown");
}

// Behrendt 2005 §3: the shell rung ends a ladder, for Wang-tiled species only, by size or under
// a budget (the shell takes over by its own fade either way).
TEST(ladder_fields, the_shell_rung_ends_a_ladder_of_a_wang_tiled_species) {
    const json shell_last = json::parse(R"([{"rung": "mesh_full"}, {"rung": "crossed_billboard", "below_px": 40},
                                            {"rung": "shell", "below_px": 12}])");
    json tiled = with_ladder(shell_last);
    tiled["populations"][0]["placement"] = "wang_tiles";
    EXPECT_EQ(load(tiled).lod.ladder.back().rung, "shell");
    expect_error(with_ladder(shell_last), "/lod/ladder/2/rung",
                 "species oak has a population not placed by \"wang_tiles\"");
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full"}, {"rung": "shell", "below_px": 40},
                                             {"rung": "crossed_billboard", "below_px": 12}])")),
                 "/lod/ladder/1/rung", "shell must be the last rung");
    json budget = tiled;
    budget["lod"]["plant_budget_ms"] = 5;
    EXPECT_EQ(load(budget).lod.plant_budget_ms, 5.0);
}

TEST(ladder_fields, a_plant_budget_needs_a_ladder_to_choose_from) {
    json j = with_ladder(k_three);
    j["lod"]["plant_budget_ms"] = 40;
    EXPECT_EQ(load(j).lod.plant_budget_ms, 40.0);
    j["lod"]["representation"] = "mesh_levels";
    expect_error(j, "/lod/plant_budget_ms", "chooses the rungs of a ladder");
}

TEST(ladder_fields, an_error_threshold_needs_a_ladder_and_no_budget) {
    json j = with_ladder(k_three);
    j["lod"]["max_error"] = 0.04;
    EXPECT_EQ(load(j).lod.max_error, 0.04);
    j["lod"]["max_error"] = 1.5;
    expect_error(j, "/lod/max_error", "");
    j["lod"]["max_error"] = 0.04;
    j["lod"]["representation"] = "mesh_levels";
    expect_error(j, "/lod/max_error", "chooses the rungs of a ladder");
    j["lod"]["representation"] = "ladder";
    j["lod"]["plant_budget_ms"] = 40;
    expect_error(j, "/lod/max_error", "an error threshold chooses the rungs without a budget");
    j["lod"].erase("plant_budget_ms");
    j["lod"]["target_frame_ms"] = 30;
    expect_error(j, "/lod/max_error", "an error threshold chooses the rungs without a budget");
    j["lod"].erase("max_error");
    EXPECT_EQ(load(j).lod.target_frame_ms, 30.0) << "a frame-time target drives a ladder's budget";
}

TEST(ladder_fields, a_gain_needs_a_ladder_and_no_error_threshold) {
    json j = with_ladder(k_three);
    j["lod"]["gain_per_ms"] = 40;
    EXPECT_EQ(load(j).lod.gain_per_ms, 40.0);
    j["lod"]["plant_budget_ms"] = 60;
    EXPECT_EQ(load(j).lod.gain_per_ms, 40.0) << "a budget caps what a gain spends";
    j["lod"].erase("plant_budget_ms");
    j["lod"]["gain_per_ms"] = -1;
    expect_error(j, "/lod/gain_per_ms", "");
    j["lod"]["gain_per_ms"] = 40;
    j["lod"]["representation"] = "mesh_levels";
    expect_error(j, "/lod/gain_per_ms", "chooses the rungs of a ladder");
    j["lod"]["representation"] = "ladder";
    j["lod"]["max_error"] = 0.04;
    expect_error(j, "/lod/gain_per_ms", "an error threshold chooses each plant's rung on its own");
}

// LoDF whole is the full mesh's foliage (lod/ladder.h seamless_step): the step from mesh_full into
// it is a hard switch, its band 0 when left out and refused when given; after another rung, or
// into the rung after LoDF, the band is the usual fade.
TEST(ladder_fields, lodf_after_the_full_mesh_takes_no_band) {
    const json lodf = json::parse(R"([{"rung": "mesh_full"}, {"rung": "lodf", "below_px": 300},
                                      {"rung": "billboard_cloud", "below_px": 100}])");
    const scenario s = load(with_ladder(lodf));
    const ladder l = ladder_of(s.lod.ladder);
    EXPECT_EQ(l.band[1], 0.0f);
    EXPECT_EQ(l.band[2], k_default_band);
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(s), "round_trip.json").lod.ladder, s.lod.ladder);
    json banded = lodf;
    banded[1]["band"] = 0.1;
    expect_error(with_ladder(banded), "/lod/ladder/1/band", "lodf after mesh_full takes no band");
    banded[1]["band"] = 0.0;
    EXPECT_EQ(ladder_of(load(with_ladder(banded)).lod.ladder).band[1], 0.0f) << "an explicit 0 is what it is";
    const json after_reduced = json::parse(R"([{"rung": "mesh_reduced"}, {"rung": "lodf", "below_px": 300}])");
    EXPECT_EQ(ladder_of(load(with_ladder(after_reduced)).lod.ladder).band[1], k_default_band)
        << "from another rung LoDF is not the same leaves: the step fades";
}

// A rung may cast its shadow as another of its ladder's rungs drawn as one mesh (ladder::shadow):
// read into the runtime's ladder, written back, and refused naming the field otherwise.
TEST(ladder_fields, a_rung_casts_its_shadow_as_another_of_its_ladder_s_mesh_rungs) {
    const json cast = json::parse(R"([{"rung": "mesh_full", "shadow": "billboard_cloud"},
                                      {"rung": "billboard_cloud", "below_px": 200},
                                      {"rung": "points_lines", "below_px": 50}])");
    const scenario s = load(with_ladder(cast));
    const ladder l = ladder_of(s.lod.ladder);
    EXPECT_EQ(l.shadow[0], representation::billboard_cloud);
    EXPECT_EQ(l.shadow[1], representation::none);
    EXPECT_EQ(l.caster_of(representation::mesh_full), representation::billboard_cloud);
    EXPECT_EQ(l.caster_of(representation::billboard_cloud), representation::billboard_cloud);
    EXPECT_EQ(l.caster_of(representation::points), representation::points);
    EXPECT_EQ(load_scenario_text(scenario_to_json_text(s), "round_trip.json").lod.ladder, s.lod.ladder);
    // Not a rung of this ladder: its mesh may not be baked.
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full", "shadow": "crossed_billboard"},
                                            {"rung": "billboard_cloud", "below_px": 200}])")),
                 "/lod/ladder/0/shadow", "the shadow must be cast as one of this ladder's own rungs");
    // Points draw prefixes, not one mesh: they neither cast as another nor are cast.
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full", "shadow": "points_lines"},
                                            {"rung": "points_lines", "below_px": 50}])")),
                 "/lod/ladder/0/shadow", "only mesh_full, mesh_reduced");
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full"},
                                            {"rung": "points_lines", "below_px": 50, "shadow": "mesh_full"}])")),
                 "/lod/ladder/1/shadow", "only mesh_full, mesh_reduced");
    expect_error(with_ladder(json::parse(R"([{"rung": "mesh_full", "shadow": "cloud"}])")),
                 "/lod/ladder/0/shadow", "unknown value; expected one of");
}

}  // namespace
}  // namespace sylva
