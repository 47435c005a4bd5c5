#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "models/cache/bake_cache.h"
#include "models/cache/radiance_transfer_io.h"
#include "setup/species_models.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

struct species_transfer : ::testing::Test {
    fs::path root =
        fs::temp_directory_path() / ("sylva_species_transfer_" + std::to_string(::getpid()));
    species_settings grass;
    transfer_settings settings;
    void SetUp() override {
        fs::remove_all(root);
        grass.name = grass.generator = "grass";
        settings.rays_per_receiver = 16;
        settings.seed = 3;
    }
    void TearDown() override { fs::remove_all(root); }
};

TEST_F(species_transfer, levels_have_one_vector_per_vertex_and_a_cache_hit_gives_identical_bytes) {
    const plant_model model = load_species_model(grass, 5, nullptr);
    bake_cache cache(root);
    const std::array<radiance_transfer, 3> baked =
        load_species_transfer(grass, 5, model, settings, &cache);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(baked[i].receiver_count(), model.lods[i].vertices.size()) << i;
    EXPECT_EQ(cache.misses(), 1u);

    const std::array<radiance_transfer, 3> loaded =
        load_species_transfer(grass, 5, model, settings, &cache);
    EXPECT_EQ(cache.hits(), 1u);
    // The entry's payload (after its size and checksum header, models/cache/bake_cache.h).
    const std::vector<std::byte> stored =
        *bake_cache(root).load("radiance_transfer", species_transfer_key(grass, 5, settings));
    EXPECT_EQ(serialize_radiance_transfers(loaded), stored);
    EXPECT_EQ(serialize_radiance_transfers(baked), stored);
}

TEST_F(species_transfer, every_setting_and_the_model_change_the_key) {
    const std::uint64_t key = species_transfer_key(grass, 5, settings);
    EXPECT_NE(key, species_transfer_key(grass, 6, settings));
    for (int change = 0; change < 4; ++change) {
        transfer_settings s = settings;
        if (change == 0) s.bands = 2;
        if (change == 1) s.rays_per_receiver = 17;
        if (change == 2) s.interreflection = true;
        if (change == 3) s.seed = 4;
        EXPECT_NE(key, species_transfer_key(grass, 5, s)) << change;
    }
    EXPECT_NE(key, species_point_line_transfer_key(grass, 5, settings));
}

TEST_F(species_transfer, points_and_line_vertices_get_one_vector_each_through_the_cache) {
    const plant_model model = load_species_model(grass, 5, nullptr);
    const point_line_model point_lines = load_species_point_lines(grass, 5, model, nullptr);
    bake_cache cache(root);
    const point_line_transfer baked =
        load_species_point_line_transfer(grass, 5, model, point_lines, settings, &cache);
    EXPECT_EQ(baked.points.receiver_count(), point_lines.points.size());
    EXPECT_EQ(baked.lines.receiver_count(), point_lines.lines.size());
    const point_line_transfer loaded =
        load_species_point_line_transfer(grass, 5, model, point_lines, settings, &cache);
    EXPECT_EQ(cache.hits(), 1u);
    EXPECT_EQ(loaded.points.front, baked.points.front);
    EXPECT_EQ(loaded.lines.back, baked.lines.back);
}

}  // namespace
}  // namespace sylva
