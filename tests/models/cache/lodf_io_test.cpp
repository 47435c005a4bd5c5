// LoDF models through the bake cache's bytes (models/cache/lodf_io.h): a round trip keeps every
// field, and damage anywhere is refused with a reason, never walked.
#include "models/cache/lodf_io.h"

#include <gtest/gtest.h>

#include "models/generate/plant_library.h"

namespace sylva {
namespace {

lodf_model small_model() {
    const plant_model plant = generate_plant_model("shrub", 2, 32);
    return bake_lodf(plant.lods[0], plant.has_hierarchy, {4});
}

TEST(lodf_io, a_round_trip_keeps_every_field) {
    const lodf_model m = small_model();
    ASSERT_GT(m.structure.leaf_count, 10u);
    const std::vector<std::byte> bytes = serialize_lodf_model(m);
    const lodf_model back = deserialize_lodf_model(bytes);
    EXPECT_EQ(back.indices, m.indices);
    EXPECT_EQ(back.vertex_count, m.vertex_count);
    EXPECT_EQ(back.structure.changed_group, m.structure.changed_group);
    EXPECT_EQ(back.structure.cluster_of_leaf, m.structure.cluster_of_leaf);
    EXPECT_EQ(back.structure.position_of_leaf, m.structure.position_of_leaf);
    ASSERT_EQ(back.structure.nodes.size(), m.structure.nodes.size());
    for (std::size_t i = 0; i < m.structure.nodes.size(); ++i) {
        EXPECT_EQ(back.structure.nodes[i].leaf, m.structure.nodes[i].leaf);
        EXPECT_EQ(back.structure.nodes[i].first_index, m.structure.nodes[i].first_index);
    }
    EXPECT_EQ(serialize_lodf_model(back), bytes) << "equal models give equal bytes";
}

TEST(lodf_io, a_damaged_entry_is_refused_with_a_reason) {
    const lodf_model m = small_model();
    std::vector<std::byte> bytes = serialize_lodf_model(m);
    EXPECT_THROW(deserialize_lodf_model(std::span(bytes).first(bytes.size() - 3)), std::runtime_error);
    std::vector<std::byte> version = bytes;
    version[4] = std::byte{99};
    EXPECT_THROW(deserialize_lodf_model(version), std::runtime_error);
    // A structure that no longer adds up: each kind of damage names itself.
    const auto refused = [](lodf_model damaged) {
        try {
            validate_lodf(damaged);
        } catch (const std::runtime_error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    lodf_model bad = m;
    bad.structure.changed_group[0] = 99;
    EXPECT_NE(refused(bad).find("Changed_group names cluster 99"), std::string::npos);
    bad = m;
    bad.indices.back() = m.vertex_count;
    EXPECT_NE(refused(bad).find("past the mesh"), std::string::npos);
    bad = m;
    std::swap(bad.structure.nodes[0].leaf, bad.structure.nodes[1].leaf);
    EXPECT_NE(refused(bad).find("placed elsewhere"), std::string::npos);
    bad = m;
    bad.structure.nodes[1].first_index += 3;
    EXPECT_FALSE(refused(bad).empty());
    EXPECT_TRUE(refused(m).empty()) << refused(m);
}

}  // namespace
}  // namespace sylva
