#include "models/cache/point_line_io.h"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>

#include "models/generate/plant_library.h"
#include "models/bake/point_line_bake.h"
#include "tests/models/bake/point_line_fixtures.h"

namespace sylva {
namespace {

using namespace sylva::testing;

// A small model with a point part and a line part: quads of leaves and one blade.
point_line_model small_model() {
    mesh_data mesh;
    const triangle_part leaf{0, 1, part_kind::leaf, 0};
    const triangle_part blade{1, 1, part_kind::blade, 1};
    for (int i = 0; i < 3; ++i)
        add_quad(mesh, {float(i), 0, 0}, {0.5f, 0, 0}, {0, 0, 0.5f}, {0, 0}, {1, 1}, &leaf);
    add_quad(mesh, {0, 0, 3}, {0.02f, 0, 0}, {0, 1, 0}, {0, 0}, {1, 1}, &blade);
    close_submesh(mesh, 0, material_kind::leaf);
    return bake_point_lines(model_of(std::move(mesh)));
}

TEST(point_line_io, a_model_round_trips_to_the_same_bytes_and_values) {
    const point_line_model model = bake_point_lines(generate_plant_model("flower", 4, 32));
    const std::vector<std::byte> bytes = serialize_point_line_model(model);
    const point_line_model back = deserialize_point_line_model(bytes);
    EXPECT_TRUE(serialize_point_line_model(back) == bytes);
    ASSERT_EQ(back.parts.size(), model.parts.size());
    for (std::size_t i = 0; i < model.parts.size(); ++i) {
        EXPECT_EQ(back.parts[i].first_index, model.parts[i].first_index);
        EXPECT_EQ(back.parts[i].importance, model.parts[i].importance);
        EXPECT_EQ(back.parts[i].stratified, model.parts[i].stratified);
        EXPECT_EQ(back.parts[i].line_error_m, model.parts[i].line_error_m);
    }
    EXPECT_EQ(back.points_after, model.points_after);
    EXPECT_EQ(back.cells.size(), model.cells.size());
    EXPECT_EQ(back.triangles.indices, model.triangles.indices);
}

TEST(point_line_io, every_truncation_throws) {
    const std::vector<std::byte> bytes = serialize_point_line_model(small_model());
    for (std::size_t size = 0; size < bytes.size(); ++size)
        EXPECT_THROW(deserialize_point_line_model(std::span(bytes.data(), size)),
                     std::runtime_error)
            << size;
    std::vector<std::byte> longer = bytes;
    longer.push_back(std::byte{0});
    EXPECT_THROW(deserialize_point_line_model(longer), std::runtime_error);
}

TEST(point_line_io, another_magic_or_version_throws) {
    std::vector<std::byte> bytes = serialize_point_line_model(small_model());
    std::vector<std::byte> version = bytes;
    const std::uint32_t next = k_point_line_format + 1;
    std::memcpy(version.data() + 4, &next, 4);
    EXPECT_THROW(deserialize_point_line_model(version), std::runtime_error);
    bytes[0] = std::byte{0};
    EXPECT_THROW(deserialize_point_line_model(bytes), std::runtime_error);
}

// Each corruption gives bytes the reader must refuse, naming the problem.
TEST(point_line_io, corrupted_ranges_and_counts_throw) {
    const point_line_model valid = small_model();
    ASSERT_NO_THROW(deserialize_point_line_model(serialize_point_line_model(valid)));
    ASSERT_EQ(valid.parts.size(), 2u);
    const std::size_t point_part = valid.parts[0].primitive == lod_primitive::points ? 0 : 1;
    const std::size_t line_part = 1 - point_part;
    const std::vector<std::pair<const char*, std::function<void(point_line_model&)>>> corruptions =
        {
            {"triangles outside", [&](point_line_model& m) { m.parts[0].triangle_count += 100; }},
            {"submesh does not match",
             [&](point_line_model& m) { m.triangles.submeshes[0].index_count -= 3; }},
            {"points outside", [&](point_line_model& m) { m.parts[point_part].first_point += 1; }},
            {"points_after outside",
             [&](point_line_model& m) { m.parts[point_part].first_after += 1000; }},
            {"points_after does not run",
             [&](point_line_model& m) { m.points_after[m.parts[point_part].first_after] += 1; }},
            {"lines outside", [&](point_line_model& m) { m.parts[line_part].line_count += 1; }},
            {"unknown primitive",
             [&](point_line_model& m) { m.parts[0].primitive = lod_primitive(7); }},
            {"unknown material",
             [&](point_line_model& m) { m.parts[0].material = material_kind(9); }},
            {"non-finite",
             [&](point_line_model& m) {
                 m.parts[0].area_m2 = std::numeric_limits<float>::quiet_NaN();
             }},
            {"cell", [&](point_line_model& m) { m.cells[0].part_count = 0; }},
            {"cells do not cover", [&](point_line_model& m) { m.cells.clear(); }},
            {"submesh count", [&](point_line_model& m) { m.triangles.submeshes.pop_back(); }},
            {"odd number", [&](point_line_model& m) { m.lines.pop_back(); }},
            {"mesh index", [&](point_line_model& m) { m.triangles.indices[0] = 1u << 30; }},
        };
    for (const auto& [expected, corrupt] : corruptions) {
        point_line_model broken = valid;
        corrupt(broken);
        try {
            deserialize_point_line_model(serialize_point_line_model(broken));
            ADD_FAILURE() << "accepted: " << expected;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
        }
    }
}

}  // namespace
}  // namespace sylva
