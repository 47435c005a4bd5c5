#include "models/generate/plant_library.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <map>
#include <stdexcept>
#include <string>

namespace sylva {
namespace {

// FNV-1a over every field of every lod (field by field: structs with padding are not hashed
// as raw bytes) and both textures.
std::uint64_t model_hash(const plant_model& m) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    auto feed = [&](const void* data, std::size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 0x100000001b3ULL;
    };
    for (const mesh_data& lod : m.lods) {
        feed(lod.vertices.data(), lod.vertices.size() * sizeof(vertex));
        feed(lod.indices.data(), lod.indices.size() * sizeof(std::uint32_t));
        for (const triangle_part& p : lod.parts) {
            feed(&p.branch, sizeof p.branch);
            feed(&p.level, sizeof p.level);
            feed(&p.kind, sizeof p.kind);
            feed(&p.parent_branch, sizeof p.parent_branch);
        }
        for (const leaf_record& l : lod.leaves) {
            feed(&l.center, sizeof l.center);
            feed(&l.normal, sizeof l.normal);
            feed(&l.size, sizeof l.size);
            feed(&l.parent_branch, sizeof l.parent_branch);
            feed(&l.kind, sizeof l.kind);
        }
    }
    feed(m.leaf_texture.texels.data(), m.leaf_texture.texels.size());
    feed(m.bark_texture.texels.data(), m.bark_texture.texels.size());
    return h;
}

const submesh* find_submesh(const mesh_data& m, material_kind kind) {
    for (const submesh& s : m.submeshes)
        if (s.material == kind) return &s;
    return nullptr;
}

double leaf_area(const mesh_data& m) {
    const submesh* leaves = find_submesh(m, material_kind::leaf);
    double area = 0.0;
    for (std::uint32_t i = leaves->first_index; i < leaves->first_index + leaves->index_count; i += 3) {
        const glm::vec3 a = m.vertices[m.indices[i]].position;
        area += 0.5 * glm::length(glm::cross(m.vertices[m.indices[i + 1]].position - a,
                                             m.vertices[m.indices[i + 2]].position - a));
    }
    return area;
}

// Which lods have no bark by design (see k_plant_presets).
bool bark_expected(const std::string& preset, std::size_t lod) {
    if (preset == "grass") return false;
    if (preset == "fern") return lod == 0;
    return true;
}

// Reduced and far triangle ratios: ~10% and ~3-5% for the trees; the small plants keep a few
// dozen triangles, so their ratios are looser.
struct ratio_bounds {
    double reduced_lo, reduced_hi, far_lo, far_hi;
};
ratio_bounds ratios_for(const std::string& preset) {
    if (preset == "grass" || preset == "flower" || preset == "fern") return {0.06, 0.16, 0.02, 0.07};
    return {0.07, 0.15, 0.025, 0.055};
}

class plant_library_test : public testing::TestWithParam<std::string> {};

TEST_P(plant_library_test, every_lod_has_the_expected_submeshes_and_textures) {
    const plant_model m = generate_plant_model(GetParam(), 1, 64);
    EXPECT_EQ(m.name, GetParam());
    EXPECT_TRUE(m.has_hierarchy);
    for (std::size_t i = 0; i < 3; ++i) {
        const mesh_data& lod = m.lods[i];
        const submesh* bark = find_submesh(lod, material_kind::bark);
        const submesh* leaf = find_submesh(lod, material_kind::leaf);
        ASSERT_NE(leaf, nullptr) << "lod " << i;
        EXPECT_GT(leaf->index_count, 0u) << "lod " << i;
        if (bark_expected(GetParam(), i)) {
            ASSERT_NE(bark, nullptr) << "lod " << i;
            EXPECT_GT(bark->index_count, 0u);
        } else {
            EXPECT_EQ(bark, nullptr) << "lod " << i << ": an empty bark sub-mesh is left out";
        }
        std::uint32_t covered = 0;
        for (const submesh& s : lod.submeshes) covered += s.index_count;
        EXPECT_EQ(covered, lod.indices.size());
        for (const std::uint32_t index : lod.indices) ASSERT_LT(index, lod.vertices.size());
    }
    ASSERT_EQ(m.leaf_texture.width, 64u);
    ASSERT_EQ(m.bark_texture.width, 64u);
    std::size_t transparent = 0;
    for (std::size_t i = 3; i < m.leaf_texture.texels.size(); i += 4) transparent += m.leaf_texture.texels[i] == 0;
    EXPECT_GT(transparent, m.leaf_texture.texels.size() / 4 / 10) << "the leaf texture is alpha-tested";
}

TEST_P(plant_library_test, every_triangle_has_a_part_and_every_foliage_element_a_record) {
    const plant_model m = generate_plant_model(GetParam(), 2, 16);
    for (std::size_t i = 0; i < 3; ++i) {
        const mesh_data& lod = m.lods[i];
        ASSERT_EQ(lod.parts.size(), lod.triangle_count()) << "lod " << i;
        EXPECT_GT(lod.leaves.size(), 0u);
        const submesh* leaf = find_submesh(lod, material_kind::leaf);
        const std::uint32_t first_leaf_triangle = leaf->first_index / 3;
        std::uint32_t max_branch = 0;
        for (std::uint32_t t = 0; t < lod.parts.size(); ++t) {
            const triangle_part& p = lod.parts[t];
            // Bark triangles say bark, foliage triangles a foliage kind.
            ASSERT_EQ(p.kind == part_kind::bark, t < first_leaf_triangle) << "lod " << i << " triangle " << t;
            ASSERT_LE(p.parent_branch, p.branch);  // parents come before their children
            max_branch = std::max(max_branch, p.branch);
        }
        for (const leaf_record& l : lod.leaves) {
            EXPECT_LE(l.parent_branch, max_branch);
            EXPECT_GT(l.size, 0.0f);
            EXPECT_NEAR(glm::length(l.normal), 1.0f, 1e-3f);
            EXPECT_NE(l.kind, part_kind::bark);
        }
    }
}

// Foliage names its stem (branch) and that stem's parent (parent_branch), as the stem's own bark
// does; where the finest twigs have no bark, that is the only link from their leaves to the
// branch they grow on, and it must name a stem with bark one level up.
TEST_P(plant_library_test, foliage_records_its_stem_and_that_stem_s_parent) {
    const plant_model m = generate_plant_model(GetParam(), 4, 4);
    const mesh_data& full = m.lods[0];
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint8_t>> bark;  // stem -> parent, level
    for (const triangle_part& p : full.parts)
        if (p.kind == part_kind::bark) bark[p.branch] = {p.parent_branch, p.level};
    std::size_t linked_through_barkless_stems = 0;
    for (const triangle_part& p : full.parts) {
        if (p.kind == part_kind::bark) continue;
        if (const auto stem = bark.find(p.branch); stem != bark.end()) {
            EXPECT_EQ(p.parent_branch, stem->second.first) << "branch " << p.branch;
        } else if (p.parent_branch != p.branch) {
            const auto parent = bark.find(p.parent_branch);
            ASSERT_NE(parent, bark.end()) << "foliage of stem " << p.branch << " names " << p.parent_branch;
            EXPECT_EQ(parent->second.second + 2, p.level) << "branch " << p.branch;
            ++linked_through_barkless_stems;
        }
    }
    const std::string preset = GetParam();
    if (preset == "broadleaf" || preset == "conifer" || preset == "shrub") {
        EXPECT_GT(linked_through_barkless_stems, 0u) << "these presets carry their leaves on barkless twigs";
    }
}

TEST_P(plant_library_test, reduced_and_far_keep_their_triangle_ratio_and_leaf_area) {
    const ratio_bounds bounds = ratios_for(GetParam());
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const plant_model m = generate_plant_model(GetParam(), seed, 8);
        const double full = double(m.lods[0].triangle_count());
        const double reduced = double(m.lods[1].triangle_count()) / full;
        const double far = double(m.lods[2].triangle_count()) / full;
        EXPECT_GE(reduced, bounds.reduced_lo) << "seed " << seed;
        EXPECT_LE(reduced, bounds.reduced_hi) << "seed " << seed;
        EXPECT_GE(far, bounds.far_lo) << "seed " << seed;
        EXPECT_LE(far, bounds.far_hi) << "seed " << seed;
        const double area = leaf_area(m.lods[0]);
        EXPECT_NEAR(leaf_area(m.lods[1]) / area, 1.0, 0.25) << "seed " << seed;
        EXPECT_NEAR(leaf_area(m.lods[2]) / area, 1.0, 0.35) << "seed " << seed;
    }
}

TEST_P(plant_library_test, same_seed_is_byte_identical_and_seeds_differ) {
    EXPECT_EQ(model_hash(generate_plant_model(GetParam(), 9, 16)), model_hash(generate_plant_model(GetParam(), 9, 16)));
    EXPECT_NE(model_hash(generate_plant_model(GetParam(), 9, 16)), model_hash(generate_plant_model(GetParam(), 10, 16)));
}

INSTANTIATE_TEST_SUITE_P(presets, plant_library_test,
                         testing::Values("broadleaf", "broadleaf_hd", "conifer", "shrub", "grass", "flower", "fern"));

TEST(plant_library, lists_every_preset_once) {
    EXPECT_EQ(k_plant_presets.size(), 7u);
    for (const std::string_view name : k_plant_presets) EXPECT_NO_THROW(generate_plant_model(name, 0, 4));
}

TEST(plant_library, broadleaf_hd_is_film_detail_and_broadleaf_game_ready) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const plant_model hd = generate_plant_model("broadleaf_hd", seed, 4);
        EXPECT_GE(hd.lods[0].triangle_count(), 100'000u) << "seed " << seed;
        EXPECT_LE(hd.lods[0].triangle_count(), 200'000u) << "seed " << seed;
        EXPECT_LE(generate_plant_model("broadleaf", seed, 4).lods[0].triangle_count(), 8'000u);
    }
}

TEST(plant_library, sizes_and_part_counts_fit_the_species) {
    const plant_model shrub = generate_plant_model("shrub", 3, 4);
    EXPECT_GT(shrub.lods[0].bounds_max.y, 1.5f);
    EXPECT_LT(shrub.lods[0].bounds_max.y, 3.2f);
    std::uint32_t ground_stems = 0;  // several stems rise from the ground: their own parents
    for (const triangle_part& p : shrub.lods[0].parts)
        if (p.kind == part_kind::bark && p.branch == p.parent_branch) ground_stems = std::max(ground_stems, p.branch + 1);
    EXPECT_GE(ground_stems, 3u);

    const plant_model grass = generate_plant_model("grass", 3, 4);
    EXPECT_GE(grass.lods[0].leaves.size(), 15u);
    EXPECT_LE(grass.lods[0].leaves.size(), 40u);
    EXPECT_GE(grass.lods[0].triangle_count(), 100u);
    EXPECT_LE(grass.lods[0].triangle_count(), 400u);

    const plant_model flower = generate_plant_model("flower", 3, 4);
    EXPECT_GT(flower.lods[0].bounds_max.y, 0.4f);
    EXPECT_LT(flower.lods[0].bounds_max.y, 0.8f);
    for (const plant_model* m : {&flower}) {
        for (const mesh_data& lod : m->lods) {
            std::size_t petals = 0;
            for (const leaf_record& l : lod.leaves) petals += l.kind == part_kind::petal;
            EXPECT_GE(petals, 4u);  // the blossom survives every level
        }
    }

    const plant_model conifer = generate_plant_model("conifer", 3, 4);
    EXPECT_EQ(conifer.lods[0].leaves.front().kind, part_kind::needle);
}

TEST(plant_library, flower_leaves_and_petals_use_their_atlas_regions) {
    const plant_model flower = generate_plant_model("flower", 4, 4);
    const mesh_data& m = flower.lods[0];
    for (std::uint32_t t = 0; t < m.parts.size(); ++t) {
        if (m.parts[t].kind == part_kind::bark) continue;
        for (int k = 0; k < 3; ++k) {
            const float u = m.vertices[m.indices[3 * t + std::uint32_t(k)]].uv.x;
            if (m.parts[t].kind == part_kind::leaf) {
                ASSERT_LE(u, 0.5f);
            } else {
                ASSERT_GE(u, 0.5f);
            }
        }
    }
}

TEST(plant_library, unknown_preset_names_it_and_the_valid_list) {
    try {
        generate_plant_model("palm", 1, 16);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("palm"), std::string::npos);
        for (const std::string_view name : k_plant_presets) EXPECT_NE(what.find(name), std::string::npos) << name;
    }
}

}  // namespace
}  // namespace sylva
