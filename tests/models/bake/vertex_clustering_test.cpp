// Clustering for billboard clouds (Behrendt 2005 §2.1): k-means on hand-placed blobs, the
// hierarchy on a hand-built stem tree with hand-counted clusters per level, the level steering
// and its merge/split refinements on generated plants, leaves kept apart from bark, and
// determinism across seeds runs and thread counts.
#include "models/bake/vertex_clustering.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <map>
#include <set>
#include <stdexcept>

#include "models/generate/plant_library.h"
#include "models/random.h"

namespace sylva {
namespace {

std::vector<glm::vec3> blobs(const std::vector<glm::vec3>& centres, int per_blob, std::uint64_t seed) {
    rng random(seed);
    std::vector<glm::vec3> points;
    for (int i = 0; i < per_blob; ++i)
        for (const glm::vec3& c : centres)
            points.push_back(c + glm::vec3(random.uniform(-0.5f, 0.5f), random.uniform(-0.5f, 0.5f), random.uniform(-0.5f, 0.5f)));
    return points;
}

TEST(kmeans, separates_well_separated_blobs_and_numbers_labels_by_first_appearance) {
    const std::vector<glm::vec3> centres{{0, 0, 0}, {10, 0, 0}, {0, 10, 0}};
    const std::vector<glm::vec3> points = blobs(centres, 50, 1);  // interleaved: blob = i % 3
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        const std::vector<std::uint32_t> labels = kmeans(points, 3, seed, 30);
        ASSERT_EQ(labels.size(), points.size());
        for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(labels[i], i % 3) << "seed " << seed << " point " << i;
    }
}

TEST(kmeans, never_makes_more_clusters_than_distinct_points) {
    const std::vector<glm::vec3> same(20, glm::vec3(1, 2, 3));
    EXPECT_EQ(kmeans(same, 5, 1, 10), std::vector<std::uint32_t>(20, 0));
    const std::vector<glm::vec3> two{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}};
    EXPECT_EQ(kmeans(two, 8, 1, 10), (std::vector<std::uint32_t>{0, 1, 0}));
    EXPECT_TRUE(kmeans({}, 3, 1, 10).empty());
    EXPECT_THROW(kmeans(two, 0, 1, 10), std::invalid_argument);
}

TEST(kmeans, does_not_depend_on_the_thread_count) {
    const std::vector<glm::vec3> points = blobs({{0, 0, 0}, {3, 1, 0}, {1, 4, 2}, {5, 5, 5}}, 5000, 2);
    const std::vector<std::uint32_t> many = kmeans(points, 40, 7, 20);
    std::vector<std::uint32_t> one;
    tbb::task_arena single(1);
    single.execute([&] { one = kmeans(points, 40, 7, 20); });
    EXPECT_EQ(one, many);
}

// A hand-built plant: stem 0 the trunk; stems 1 and 2 branch from it (level 1); twigs 3 and 5
// grow on stem 1 and twig 4 on stem 2 (level 2) and have no bark, only leaves. Each stem is one
// bark triangle, each twig one leaf triangle, placed apart so k-means is never in doubt.
//
//   stem:     0      1      2      3      4      5
//   bark:     t0     t1     t2     -      -      -
//   leaves:   -      -      -      t3     t4     t5
struct stem_plant {
    mesh_data mesh;
    stem_plant() {
        const std::uint32_t parents[6] = {0, 0, 0, 1, 2, 1};
        for (std::uint32_t s = 0; s < 6; ++s) {
            const bool leaf = s >= 3;
            const glm::vec3 at(float(s) * 10.0f, 0.0f, 0.0f);
            const auto base = std::uint32_t(mesh.vertices.size());
            mesh.vertices.push_back({at, {0, 0, 1}, {0, 0}});
            mesh.vertices.push_back({at + glm::vec3(1, 0, 0), {0, 0, 1}, {1, 0}});
            mesh.vertices.push_back({at + glm::vec3(0, 1, 0), {0, 0, 1}, {0, 1}});
            mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
            const std::uint8_t level = s == 0 ? 0 : s < 3 ? 1 : 3;  // foliage: twig level + 1
            mesh.parts.push_back({s, level, leaf ? part_kind::leaf : part_kind::bark, parents[s]});
        }
        mesh.submeshes = {{0, 9, material_kind::bark}, {9, 9, material_kind::leaf}};
    }
};

TEST(hierarchy_clustering, every_sub_branch_at_the_chosen_level_is_one_cluster) {
    const stem_plant plant;
    clustering_settings s;
    s.method = clustering_method::hierarchy;
    // Level 0: all bark under the trunk, all leaves under the trunk.
    s.branching_level = 0;
    triangle_clusters c = cluster_triangles(plant.mesh, true, s);
    EXPECT_EQ(c.count, 2u);
    EXPECT_EQ(c.cluster_of, (std::vector<std::uint32_t>{0, 0, 0, 1, 1, 1}));
    EXPECT_EQ(c.branching_level, 0);
    // Level 1: trunk bark; stem 1 bark; stem 2 bark; stem 1's leaves (twigs 3 and 5); stem 2's.
    s.branching_level = 1;
    c = cluster_triangles(plant.mesh, true, s);
    EXPECT_EQ(c.count, 5u);
    EXPECT_EQ(c.cluster_of, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 3}));
    // Level 2: every twig's leaves apart.
    s.branching_level = 2;
    c = cluster_triangles(plant.mesh, true, s);
    EXPECT_EQ(c.count, 6u);
    EXPECT_EQ(c.cluster_of, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(c.triangles()[3], (std::vector<std::uint32_t>{3}));
}

TEST(hierarchy_clustering, steers_the_level_by_the_target_count) {
    const stem_plant plant;
    clustering_settings s;
    s.method = clustering_method::hierarchy;
    s.target_clusters = 2;  // level 0 has exactly 2
    EXPECT_EQ(cluster_triangles(plant.mesh, true, s).branching_level, 0);
    s.target_clusters = 4;  // |ln(2/4)| = 0.69 > |ln(5/4)| = 0.22
    const triangle_clusters c = cluster_triangles(plant.mesh, true, s);
    EXPECT_EQ(c.branching_level, 1);
    EXPECT_EQ(c.count, 5u);
}

TEST(hierarchy_clustering, bad_requests_are_named) {
    stem_plant plant;
    clustering_settings s;
    s.method = clustering_method::hierarchy;
    EXPECT_THROW(cluster_triangles(plant.mesh, false, s), std::invalid_argument);
    s.branching_level = -2;
    EXPECT_THROW(cluster_triangles(plant.mesh, true, s), std::invalid_argument);
    s = {};
    s.target_clusters = 0;
    EXPECT_THROW(cluster_triangles(plant.mesh, true, s), std::invalid_argument);
    // Automatic without a hierarchy falls back to the geometric clustering.
    plant.mesh.parts.clear();
    EXPECT_EQ(cluster_triangles(plant.mesh, true, clustering_settings{}).method, clustering_method::geometric);
}

const plant_model& model(std::string_view preset) {
    static std::map<std::string_view, plant_model> models;
    auto it = models.find(preset);
    if (it == models.end()) it = models.emplace(preset, generate_plant_model(preset, 3, 16)).first;
    return it->second;
}

// Does any cluster hold both leaf and bark triangles?
bool mixes_leaves_and_bark(const mesh_data& mesh, const triangle_clusters& c) {
    std::vector<int> seen(c.count, 0);
    for (std::size_t t = 0; t < c.cluster_of.size(); ++t)
        if (c.cluster_of[t] != k_no_cluster) seen[c.cluster_of[t]] |= mesh.parts[t].kind == part_kind::bark ? 1 : 2;
    return std::count(seen.begin(), seen.end(), 3) > 0;
}

// Broadleaf at the default target lands on level 1: the trunk's bark, and bark and foliage of
// each first-level branch, counted here independently from the parts.
TEST(hierarchy_clustering, broadleaf_clusters_are_its_first_level_branches) {
    const mesh_data& mesh = model("broadleaf").lods[0];
    std::map<std::uint32_t, std::uint32_t> parent;
    std::set<std::uint32_t> level_one;
    for (const triangle_part& p : mesh.parts)
        if (p.kind == part_kind::bark) {
            parent[p.branch] = p.parent_branch;
            if (p.level == 1) level_one.insert(p.branch);
        } else {
            parent.emplace(p.branch, p.parent_branch);
        }
    const triangle_clusters c = cluster_triangles(mesh, true, clustering_settings{});
    EXPECT_EQ(c.method, clustering_method::hierarchy);
    EXPECT_EQ(c.branching_level, 1);
    EXPECT_EQ(c.count, 2 * level_one.size() + 1);
    EXPECT_FALSE(mixes_leaves_and_bark(mesh, c));
    // Every cluster's triangles share one first-level ancestor (or are the trunk's bark).
    std::vector<std::set<std::uint32_t>> ancestors(c.count);
    for (std::size_t t = 0; t < mesh.parts.size(); ++t) {
        std::uint32_t stem = mesh.parts[t].branch;
        while (stem != 0 && !level_one.count(stem)) stem = parent.at(stem);
        ancestors[c.cluster_of[t]].insert(stem);
    }
    for (std::uint32_t i = 0; i < c.count; ++i) EXPECT_EQ(ancestors[i].size(), 1u) << "cluster " << i;
}

TEST(hierarchy_clustering, too_many_sub_branches_are_merged_whole) {
    const mesh_data& mesh = model("conifer").lods[0];  // 64 first-level branches: 129 clusters
    clustering_settings s;
    s.target_clusters = 30;
    const triangle_clusters c = cluster_triangles(mesh, true, s);
    EXPECT_GE(c.count, 15u);
    EXPECT_LE(c.count, 60u);
    EXPECT_FALSE(mixes_leaves_and_bark(mesh, c));
    // Whole sub-branches: all triangles of one level-1 stem (bark or foliage) in one cluster.
    s.target_clusters = 1000;
    s.branching_level = 1;
    const triangle_clusters unmerged = cluster_triangles(mesh, true, s);
    std::vector<std::set<std::uint32_t>> into(unmerged.count);
    for (std::size_t t = 0; t < mesh.parts.size(); ++t) into[unmerged.cluster_of[t]].insert(c.cluster_of[t]);
    for (const auto& targets : into) EXPECT_EQ(targets.size(), 1u);
}

TEST(hierarchy_clustering, shallow_small_plants_are_split_toward_the_target) {
    for (const std::string_view preset : {"grass", "flower", "fern"}) {
        const mesh_data& mesh = model(preset).lods[0];
        clustering_settings s;
        s.target_clusters = 30;
        const triangle_clusters c = cluster_triangles(mesh, true, s);
        EXPECT_GE(c.count, 15u) << preset;
        EXPECT_LE(c.count, 60u) << preset;
        EXPECT_FALSE(mixes_leaves_and_bark(mesh, c)) << preset;
    }
}

// The paper's baseline mixes trunk and foliage; the geometric clustering for imports does not.
TEST(geometric_clustering, keeps_leaves_and_bark_apart_where_plain_kmeans_mixes_them) {
    const mesh_data& mesh = model("broadleaf").lods[0];
    clustering_settings s;
    s.method = clustering_method::kmeans;
    const triangle_clusters plain = cluster_triangles(mesh, false, s);
    EXPECT_EQ(plain.method, clustering_method::kmeans);
    EXPECT_TRUE(mixes_leaves_and_bark(mesh, plain));
    EXPECT_LE(plain.count, s.target_clusters);
    EXPECT_GE(plain.count, s.target_clusters * 9 / 10);
    const triangle_clusters geometric = cluster_triangles(mesh, false, clustering_settings{});
    EXPECT_EQ(geometric.method, clustering_method::geometric);
    EXPECT_FALSE(mixes_leaves_and_bark(mesh, geometric));
    EXPECT_GE(geometric.count, s.target_clusters * 9 / 10);
    EXPECT_LE(geometric.count, s.target_clusters + 1);
    for (std::uint32_t cluster : geometric.cluster_of) EXPECT_NE(cluster, k_no_cluster);
}

TEST(clustering, is_deterministic_and_independent_of_the_thread_count) {
    const mesh_data& mesh = model("shrub").lods[0];
    for (const clustering_method m : {clustering_method::kmeans, clustering_method::hierarchy, clustering_method::geometric}) {
        clustering_settings s;
        s.method = m;
        s.target_clusters = 40;
        const triangle_clusters a = cluster_triangles(mesh, true, s);
        triangle_clusters b;
        tbb::task_arena single(1);
        single.execute([&] { b = cluster_triangles(mesh, true, s); });
        EXPECT_EQ(a.cluster_of, b.cluster_of) << name_of(m);
        EXPECT_EQ(a.count, b.count) << name_of(m);
    }
}

}  // namespace
}  // namespace sylva
