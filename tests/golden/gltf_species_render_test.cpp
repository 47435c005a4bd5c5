// glTF trees made by other tools (the fixtures reproduce their traits: opaque leaf materials
// over alpha textures, centimetre units, many materials, missing textures) import and render in
// a scenario next to a generated species, headless.
#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

#include "../gl/gl_test_support.h"
#include "app/scenario_player.h"
#include "scenarios/scenario_loader.h"
#include "tests/models/gltf/gltf_fixtures.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

std::string scenario_with_model(const fs::path& model) {
    return R"({"name": "imported", "resolution": [160, 90], "frames": 1,
      "terrain": {"size_m": 60, "resolution": 17, "height_m": 1},
      "species": [{"name": "imported", "model": ")" + model.string() + R"(", "height_m": 8},
                  {"name": "oak", "generator": "broadleaf", "height_m": 8}],
      "populations": [{"species": "imported", "count": 4, "min_spacing_m": 6, "area": [-12, -12, 0, 12]},
                      {"species": "oak", "count": 2, "min_spacing_m": 6, "area": [2, -12, 12, 12]}],
      "camera": {"keyframes": [{"t": 0, "position": [0, 4, 28], "target": [0, 4, 0]}]}})";
}

class imported_species : public ::testing::TestWithParam<fs::path (*)(const fs::path&)> {
protected:
    // Writes the fixture and a scenario using it into a fresh folder (removed afterwards) and
    // makes a 160x90 headless context.
    scenario load(const std::string& folder) {
        m_dir = fs::temp_directory_path() / (folder + std::to_string(::getpid()));
        fs::create_directories(m_dir);
        const fs::path model = GetParam()(m_dir);
        const fs::path file = m_dir / "imported.json";
        std::ofstream(file) << scenario_with_model(model);
        render::context_options options;
        options.width = 160;
        options.height = 90;
        m_context = render::create_context(options);
        return load_scenario_file(file);
    }
    void TearDown() override {
        if (!m_dir.empty()) fs::remove_all(m_dir);
    }
    render::gl_context* context() { return m_context.get(); }

private:
    fs::path m_dir;
    std::unique_ptr<render::gl_context> m_context;
};

TEST_P(imported_species, renders_in_a_scenario_with_its_leaves_classified) {
    SYLVA_REQUIRE_GL();
    const scenario s = load("sylva_gltf_render_");
    scenario_player player(s, 2, context());
    const frame_record r = player.step();
    EXPECT_GT(r.triangles, 0u);
    // Every imported instance is drawn (4 of them) besides the 2 oaks.
    std::uint32_t drawn = 0;
    for (auto n : r.instances) drawn += n;
    EXPECT_EQ(drawn, 6u);
    // The imported species has both a bark and a leaf sub-mesh: its leaves were found.
    const auto& meshes = player.assets().meshes;
    const auto& imported = player.assets().library.species.at(0);
    bool has_leaf = false;
    for (const auto& sub : meshes.at(imported.mesh_full).submeshes) has_leaf |= sub.material == material_kind::leaf;
    EXPECT_TRUE(has_leaf);
    // Scaled to the scenario's 8 m whatever its source units.
    EXPECT_NEAR(meshes.at(imported.mesh_full).bounds_max.y, 8.0f, 0.01f);
}

// Issue 5, item 7: the point/line representation works on imported trees too. At 20 px
// between samples the imported species is drawn as points (or lines), its parts baked from a
// model without branch records.
TEST_P(imported_species, draws_as_points_and_lines) {
    SYLVA_REQUIRE_GL();
    const scenario s = load("sylva_gltf_points_");
    player_options points;
    points.policy.mode = lod_policy::kind::points_lines;
    points.policy.points = {20.0f, 1.3f};
    points.measure_costs = false;
    scenario_player player(s, 2, context(), nullptr, points);
    const frame_record r = player.step();
    const species_entry& imported = player.assets().library.species.at(0);
    ASSERT_GT(imported.lod_part_count, 0u);
    EXPECT_GT(r.points + r.lines, 0u);
    EXPECT_EQ(r.instances[std::size_t(representation::points)], 6u);
}

fs::path opaque_leaves_glb(const fs::path& dir) { return test::write_opaque_leaves(dir, true); }

INSTANTIATE_TEST_SUITE_P(fixtures, imported_species,
                         ::testing::Values(&opaque_leaves_glb, &test::write_centimetres_scaled,
                                           &test::write_many_materials, &test::write_missing_texture));

}  // namespace
}  // namespace sylva
