// The population patch the rung tables judge a rung's error in (app/one_plant_view.h
// species_patch): k_patch_plants plants at the density of the species' densest population, in a
// square no wider than k_patch_max_side_m around the origin.
#include <gtest/gtest.h>

#include "app/one_plant_view.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

population_settings population(const std::string& species, std::uint32_t count, double half_side, float spacing) {
    population_settings p;
    p.species = species;
    p.count = count;
    p.min_spacing_m = spacing;
    p.scale_min = 0.9f;
    p.scale_max = 1.1f;
    p.area = {-half_side, -half_side, half_side, half_side};
    return p;
}

scenario two_species() {
    scenario s;
    s.species.resize(2);
    s.species[0].name = "oak";
    s.species[1].name = "grass";
    // oak: 100 in 100 m x 100 m (0.01 per m²) and 400 in 100 m x 100 m elsewhere (0.04 per m²,
    // the densest); grass: 20 in 200 m x 200 m.
    s.populations = {population("oak", 100, 50.0, 4.0f), population("grass", 20, 100.0, 25.0f),
                     population("oak", 400, 50.0, 3.0f)};
    return s;
}

TEST(species_patch, holds_49_plants_at_the_densest_population_s_density) {
    const scenario patch = species_patch(two_species(), 0, 256, "test");
    ASSERT_EQ(patch.populations.size(), 1u);
    const population_settings& p = patch.populations[0];
    EXPECT_EQ(p.species, "oak");
    // 0.04 per m²: side √(49 / 0.04) = 35 m, 35² · 0.04 = 49 plants.
    EXPECT_EQ(p.count, 49u);
    EXPECT_DOUBLE_EQ(p.area[0], -17.5);
    EXPECT_DOUBLE_EQ(p.area[3], 17.5);
    EXPECT_FLOAT_EQ(p.min_spacing_m, 3.0f);  // the densest population's
    EXPECT_FLOAT_EQ(p.scale_min, 0.9f);
    EXPECT_EQ(patch.species.size(), 1u);
    EXPECT_GE(patch.terrain.size_m, 2.0 * 35.0);  // the patch stands on the ground
}

TEST(species_patch, is_no_wider_than_its_limit) {
    const scenario patch = species_patch(two_species(), 1, 256, "test");
    const population_settings& p = patch.populations[0];
    // 20 / 200² = 5e-4 per m²: its 20 plants (fewer than 49) need √(20 / 5e-4) = 200 m, held
    // at 120 m, which holds 120² · 5e-4 = 7.2 → 7 plants.
    EXPECT_EQ(p.count, 7u);
    EXPECT_DOUBLE_EQ(p.area[2], 60.0);
    EXPECT_GE(patch.terrain.size_m, 240.0);
}

TEST(species_patch, of_a_lone_plant_is_that_plant_alone) {
    scenario s = two_species();
    s.populations = {population("oak", 1, 1.0, 1.0f)};  // one oak in 2 m x 2 m, 0.9 to 1.1 high
    const scenario patch = species_patch(s, 0, 256, "test");
    ASSERT_EQ(patch.populations.size(), 1u);
    EXPECT_EQ(patch.populations[0].count, 1u);
    EXPECT_FLOAT_EQ(patch.populations[0].scale_min, 0.9f);  // at the population's sizes
    EXPECT_FLOAT_EQ(patch.populations[0].scale_max, 1.1f);
    // single_tree's oak is always its model's size: species_alone's scenario to the letter, so
    // the rung tables measure it once.
    s.populations[0].scale_min = s.populations[0].scale_max = 1.0f;
    EXPECT_EQ(scenario_to_json_text(species_patch(s, 0, 256, "test")),
              scenario_to_json_text(species_alone(s, 0, 256, "test")));
}

TEST(species_patch, without_a_population_is_the_plant_alone) {
    scenario s = two_species();
    s.populations.erase(s.populations.begin() + 1);  // no grass planted
    const scenario patch = species_patch(s, 1, 256, "test"), alone = species_alone(s, 1, 256, "test");
    EXPECT_EQ(patch.populations, alone.populations);
}

}  // namespace
}  // namespace sylva
