// Degenerate model input (issue 4, stress suite): NaN and infinite vertex positions reject the
// model with an error naming the file, mesh, primitive, vertex and value; zero-area triangles
// (repeated indices, coincident or collinear vertices) are dropped at import with a logged
// count, so they are never drawn; the generated presets contain none.
#include <gtest/gtest.h>
#include <spdlog/sinks/ringbuffer_sink.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "models/gltf/gltf_import.h"
#include "models/generate/plant_library.h"
#include "tests/models/gltf/gltf_fixtures.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;
constexpr std::uint32_t k_texture_size = 64;

class degenerate_input : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() / ("sylva_degenerate_" + std::string(info->name()) + "_" +
                                             std::to_string(::getpid()));
        fs::remove_all(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    fs::path m_dir;
};

std::string import_error(const fs::path& file) {
    try {
        import_gltf_plant(file, k_texture_size);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "(imported without an error)";
}

std::size_t zero_area_triangles(const mesh_data& mesh) {
    std::size_t n = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        n += is_zero_area_triangle(mesh.vertices[mesh.indices[t]].position,
                                   mesh.vertices[mesh.indices[t + 1]].position,
                                   mesh.vertices[mesh.indices[t + 2]].position);
    return n;
}

TEST(zero_area_rule, lines_and_points_have_none_thin_slivers_do) {
    const glm::vec3 o(0.0f), x(1.0f, 0.0f, 0.0f);
    EXPECT_TRUE(is_zero_area_triangle(o, o, o));                             // a point
    EXPECT_TRUE(is_zero_area_triangle(o, x, x));                             // repeated vertex
    EXPECT_TRUE(is_zero_area_triangle(o, x, glm::vec3(2.0f, 0.0f, 0.0f)));   // collinear
    EXPECT_TRUE(is_zero_area_triangle(o, x, glm::vec3(0.5f, 1e-7f, 0.0f)));  // height 1e-7 m
    // A grass blade 1 mm wide and 1 m long, and a 2e-6 height per metre sliver, are kept.
    EXPECT_FALSE(
        is_zero_area_triangle(o, glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(1e-3f, 0.0f, 0.0f)));
    EXPECT_FALSE(is_zero_area_triangle(o, x, glm::vec3(0.5f, 2e-6f, 0.0f)));
    // Scale-free: the same shapes 1000 times smaller or larger decide the same way.
    EXPECT_TRUE(is_zero_area_triangle(o, x * 1e-3f, glm::vec3(5e-4f, 1e-10f, 0.0f)));
    EXPECT_FALSE(is_zero_area_triangle(o, x * 1e3f, glm::vec3(500.0f, 2e-3f, 0.0f)));
}

TEST_F(degenerate_input, nan_position_is_rejected_naming_file_mesh_primitive_vertex_and_value) {
    const std::string error = import_error(test::write_nan_position(m_dir));
    EXPECT_NE(error.find("nan_position.glb: mesh 'trunk' primitive 0: vertex 5 has a non-finite "
                         "position ("),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("nan"), std::string::npos) << error;
}

TEST_F(degenerate_input, infinite_positions_are_rejected_naming_the_vertex_and_its_sign) {
    for (const bool negative : {false, true}) {
        const std::string error = import_error(test::write_infinite_position(m_dir, negative));
        const std::string expected = std::string(negative ? "minus_infinity" : "plus_infinity") +
                                     ".glb: mesh 'trunk' primitive 1: vertex " +
                                     std::to_string(test::k_fixture_infinite_vertex) +
                                     " has a non-finite position (" + (negative ? "-inf" : "+inf") +
                                     ", ";
        EXPECT_NE(error.find(expected), std::string::npos) << error;
    }
}

TEST_F(degenerate_input, finite_vertices_that_overflow_under_the_node_transform_are_rejected) {
    const std::string error = import_error(test::write_overflowing_scale(m_dir));
    EXPECT_NE(error.find("overflowing_scale.glb: mesh 'trunk' primitive 0: vertex "),
              std::string::npos)
        << error;
    EXPECT_NE(error.find("is not finite after its node transforms"), std::string::npos) << error;
}

TEST_F(degenerate_input, zero_area_triangles_are_dropped_counted_and_logged) {
    const auto sink = std::make_shared<spdlog::sinks::ringbuffer_sink_mt>(64);
    spdlog::default_logger()->sinks().push_back(sink);
    const gltf_import_result r = import_gltf_plant(test::write_zero_area_triangles(m_dir), 64);
    spdlog::default_logger()->sinks().pop_back();

    EXPECT_EQ(r.dropped_degenerate_triangles, test::k_fixture_zero_area_triangles);
    ASSERT_EQ(r.primitives.size(), 2u);
    EXPECT_EQ(r.primitives[0].triangles,
              8u * 12u * 2u);  // the fixture cylinder's rings x sides x 2
    EXPECT_EQ(r.primitives[1].triangles, test::k_fixture_leaf_cards * 2);
    const std::string expected = "zero_area.glb: mesh 'tree' primitive 0: dropped " +
                                 std::to_string(test::k_fixture_zero_area_triangles) +
                                 " zero-area triangles";
    bool logged = false;
    for (const std::string& line : sink->last_formatted())
        logged = logged || line.find(expected) != std::string::npos;
    EXPECT_TRUE(logged) << "no spdlog warning containing: " << expected;
    bool warned = false;
    for (const std::string& w : r.warnings)
        warned = warned || w.find(expected) != std::string::npos;
    EXPECT_TRUE(warned);
    for (const mesh_data& level : r.model.lods) EXPECT_EQ(zero_area_triangles(level), 0u);
}

TEST_F(degenerate_input, a_model_with_only_zero_area_triangles_is_rejected) {
    const std::string error = import_error(test::write_only_zero_area_triangles(m_dir));
    EXPECT_NE(error.find("only_zero_area.gltf: no triangles with area in the scene (2 zero-area "
                         "triangles dropped)"),
              std::string::npos)
        << error;
}

TEST(generated_presets, have_no_zero_area_triangles_at_any_level) {
    for (const std::string_view preset : k_plant_presets) {
        if (preset == "broadleaf_hd") continue;  // the same generator as broadleaf, 20x slower
        const plant_model m = generate_plant_model(preset, 1, 16);
        for (std::size_t lod = 0; lod < m.lods.size(); ++lod) {
            EXPECT_GT(m.lods[lod].triangle_count(), 0u) << preset << " level " << lod;
            EXPECT_EQ(zero_area_triangles(m.lods[lod]), 0u) << preset << " level " << lod;
        }
    }
}

}  // namespace
}  // namespace sylva
