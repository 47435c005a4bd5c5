// A scenario naming an environment map: build_scene_assets reads and projects it, spawn_scenario
// hands it to the environment, and project_environment turns it with the sun's azimuth.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "components/environment.h"
#include "components/sun.h"
#include "lighting/sky_model.h"
#include "scenarios/scenario_loader.h"
#include "setup/spawn_scenario.h"
#include "systems/project_environment_system.h"
#include "tests/tiny_scene.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

// A 64 x 32 map lit only in columns 40..55: the lune of azimuths 45..135 degrees around east
// (lighting/environment_map.h orientation).
fs::path write_map(const std::string& name, int width, int height) {
    const fs::path dir =
        fs::temp_directory_path() / ("sylva_environment_scene_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path path = dir / name;
    std::vector<float> pixels;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            for (int c = 0; c < 3; ++c) pixels.push_back(i >= 40 && i < 56 ? 1.0f : 0.0f);
    auto out = OIIO::ImageOutput::create(path.string());
    EXPECT_TRUE(out &&
                out->open(path.string(), OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT)));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
    return path;
}

scenario tiny_with_map(const fs::path& map) {
    scenario s = testing::tiny_with_mesh_levels();
    s.species.resize(1);  // the map is what is tested; one species keeps the assets quick
    s.populations.resize(1);
    s.populations[0].species = s.species[0].name;
    s.environment.map = map.string();
    s.environment.map_rotation_deg = 90.0f;
    s.sun.keyframes = {{0.0, 40.0f, 100.0f}, {10.0, 40.0f, 190.0f}};
    return s;
}

TEST(environment_map_scene, map_reaches_the_environment_and_turns_with_the_sun) {
    const scenario s = tiny_with_map(write_map("east.exr", 64, 32));
    const scene_assets assets = build_scene_assets(s, nullptr);
    EXPECT_EQ(assets.environment_sky.width, k_environment_sky_width);
    EXPECT_EQ(assets.environment_sky.height, k_environment_sky_width / 2);
    ecs::world world;
    spawn_scenario(world, s, assets);
    environment env = world.single<environment>();
    EXPECT_TRUE(env.has_map);
    EXPECT_EQ(env.reference_azimuth_deg, 100.0f);  // the first sun keyframe's
    EXPECT_EQ(env.map_rotation_deg, 90.0f);
    // As the file lies the lune is around east: c3 ("x") = 1.0854019 (hand value in
    // tests/lighting/environment_map_test.cpp).
    EXPECT_NEAR(env.map_radiance_sh[3].x, 1.0854019f, 1e-5f);

    // The sun at the last keyframe has turned 90 degrees, the scenario another 90: the lune is
    // now around west (-x), c3 = -1.0854019, and nothing has leaked into z.
    sun light;
    light.elevation_deg = 40.0f;
    light.azimuth_deg = 190.0f;
    light.direction = sun_direction_from_angles(40.0f, 190.0f);
    project_environment(env, light);
    EXPECT_NEAR(env.radiance_sh[3].x, -1.0854019f, 1e-5f);
    EXPECT_NEAR(env.radiance_sh[2].x, 0.0f, 1e-5f);
    EXPECT_FALSE(env.sky_cache.valid);  // the Preetham sky was never integrated
}

TEST(environment_map_scene, a_map_that_is_not_two_to_one_fails_naming_the_file) {
    const scenario s = tiny_with_map(write_map("square.exr", 64, 64));
    try {
        build_scene_assets(s, nullptr);
        ADD_FAILURE() << "built";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("square.exr: is 64x64 pixels"), std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace sylva
