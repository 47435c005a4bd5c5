#include "models/cache/plant_model_io.h"

#include <gtest/gtest.h>

#include <cstring>

#include "models/generate/plant_library.h"

namespace sylva {
namespace {

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// Field by field: records have padding, which serialisation zeroes.
bool same_parts(const std::vector<triangle_part>& a, const std::vector<triangle_part>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].branch != b[i].branch || a[i].level != b[i].level || a[i].kind != b[i].kind ||
            a[i].parent_branch != b[i].parent_branch)
            return false;
    return true;
}

bool same_leaves(const std::vector<leaf_record>& a, const std::vector<leaf_record>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].center != b[i].center || a[i].normal != b[i].normal || a[i].size != b[i].size ||
            a[i].parent_branch != b[i].parent_branch || a[i].kind != b[i].kind)
            return false;
    return true;
}

TEST(plant_model_io, the_same_plant_generated_twice_serialises_to_the_same_bytes) {
    // Padding inside the stored records used to carry whatever the stack held.
    EXPECT_EQ(serialize_plant_model(generate_plant_model("broadleaf", 5, 32)),
              serialize_plant_model(generate_plant_model("broadleaf", 5, 32)));
}

TEST(plant_model_io, a_generated_plant_survives_the_round_trip_exactly) {
    const plant_model model = generate_plant_model("flower", 3, 32);
    const plant_model back = deserialize_plant_model(serialize_plant_model(model));
    EXPECT_EQ(back.name, model.name);
    for (std::size_t l = 0; l < 3; ++l) {
        EXPECT_TRUE(same_bytes(back.lods[l].vertices, model.lods[l].vertices)) << l;
        EXPECT_EQ(back.lods[l].indices, model.lods[l].indices) << l;
        EXPECT_TRUE(same_parts(back.lods[l].parts, model.lods[l].parts)) << l;
        EXPECT_TRUE(same_leaves(back.lods[l].leaves, model.lods[l].leaves)) << l;
        EXPECT_EQ(back.lods[l].submeshes.size(), model.lods[l].submeshes.size()) << l;
        EXPECT_EQ(back.lods[l].bounds_max, model.lods[l].bounds_max) << l;
    }
    EXPECT_EQ(back.leaf_texture.texels, model.leaf_texture.texels);
    EXPECT_EQ(back.bark_texture.width, model.bark_texture.width);
    EXPECT_EQ(back.has_hierarchy, model.has_hierarchy);
}

TEST(plant_model_io, other_versions_and_damaged_entries_are_rejected) {
    std::vector<std::byte> bytes = serialize_plant_model(generate_plant_model("grass", 1, 16));
    std::vector<std::byte> other_version = bytes;
    other_version[4] = std::byte{99};  // the format version follows the 4-byte magic
    EXPECT_THROW(deserialize_plant_model(other_version), std::runtime_error);
    std::vector<std::byte> truncated(bytes.begin(), bytes.end() - 9);
    EXPECT_THROW(deserialize_plant_model(truncated), std::runtime_error);
    std::vector<std::byte> not_a_model(bytes.size(), std::byte{0});
    EXPECT_THROW(deserialize_plant_model(not_a_model), std::runtime_error);
}

}  // namespace
}  // namespace sylva
