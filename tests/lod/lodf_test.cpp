// LoDF's structure and retrieval (lod/lodf.h, Rebollo 2006 §3): the paper's worked example of
// Figures 4–9 (9 leaves, 6 collapses, 3 groups), then properties over random structures.
#include "lod/lodf.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "models/bake/lodf_bake.h"
#include "models/generate/plant_library.h"

namespace sylva {
namespace {

using leaves = std::vector<std::uint32_t>;

// Figure 6's groups and Figure 8's Changed_group. Each cluster's originals in the order its
// collapses take them: group 0 collapses l1 and l2 first, group 1 l5 and l6.
lodf_structure paper_example() {
    const std::vector<leaves> queues{{1, 2, 0}, {5, 6, 4, 3}, {7, 8}};
    const std::vector<std::uint32_t> changed_group{0, 1, 0, 1, 2, 1};
    return lay_out_lodf(9, queues, changed_group);
}

leaves sorted(leaves v) {
    std::sort(v.begin(), v.end());
    return v;
}

TEST(lodf, the_papers_example_groups_and_collapses_figures_6_and_8) {
    const lodf_structure f = paper_example();
    ASSERT_EQ(f.clusters.size(), 3u);
    EXPECT_EQ(f.nodes.size(), 2u * 9 - 3);  // |L^r| = 2L − G
    EXPECT_EQ(f.changed_group, (leaves{0, 1, 0, 1, 2, 1}));
    // Figure 6: every original leaf's group.
    EXPECT_EQ(leaves(f.cluster_of_leaf.begin(), f.cluster_of_leaf.begin() + 9), (leaves{0, 0, 0, 1, 1, 1, 1, 2, 2}));
    // Figure 6's collapses, numbered in order (l9 is made first). The paper's group 1 is a chain
    // (l4 with l10, then l3 with l12) that no contiguous layout can serve (lod/lodf.h); its
    // queue-shaped tree pairs l4 with l3 and then l10 with l12. Every other collapse is the paper's.
    ASSERT_EQ(f.collapses.size(), 6u);
    const std::vector<std::pair<std::uint32_t, std::uint32_t>> expected{{1, 2}, {5, 6}, {0, 9}, {4, 3}, {7, 8}, {10, 12}};
    for (std::size_t k = 0; k < 6; ++k) {
        EXPECT_EQ(f.collapses[k].old1, expected[k].first) << "collapse " << k;
        EXPECT_EQ(f.collapses[k].old2, expected[k].second) << "collapse " << k;
        EXPECT_EQ(f.cluster_of_leaf[9 + k], f.changed_group[k]) << "l" << 9 + k << " stays in its group";
    }
    // Figure 7's arrays: groups 0 and 2 exactly (l1 l2 l0 l9 l11; l7 l8 l13).
    EXPECT_EQ(active_leaves_of(f, 0, {0, 5, 0}), (leaves{1, 2, 0, 9, 11}));
    EXPECT_EQ(active_leaves_of(f, 2, {0, 3, 0}), (leaves{7, 8, 13}));
    EXPECT_EQ(active_leaves_of(f, 1, {0, 7, 0}), (leaves{5, 6, 4, 3, 10, 12, 14}));
}

TEST(lodf, three_collapses_and_the_splits_back_figures_7_and_9) {
    const lodf_structure f = paper_example();
    std::vector<cluster_changes> c(3);
    reset_lodf_clusters(f, c);
    // Figure 7: init_group 0, active_leaves 3 4 2, changes_number 0.
    EXPECT_EQ(c[0].active_leaves, 3u);
    EXPECT_EQ(c[1].active_leaves, 4u);
    EXPECT_EQ(c[2].active_leaves, 2u);
    EXPECT_EQ(sorted(active_leaves_of(f, 1, c[1])), (leaves{3, 4, 5, 6}));
    // Three collapses: Figure 9's counts before they are applied...
    count_lodf_changes(f, c, 0, 3);
    EXPECT_EQ(c[0].changes_number, 2u);
    EXPECT_EQ(c[1].changes_number, 1u);
    EXPECT_EQ(c[2].changes_number, 0u);
    std::vector<std::uint32_t> changed;
    EXPECT_EQ(apply_lodf_changes(c, true, changed), 2u);
    EXPECT_EQ(changed, (leaves{0, 1}));  // group 2 is not touched, so not uploaded
    // ...and after: init_group 4 2 0, active_leaves 1 3 2, counts reset.
    EXPECT_EQ(c[0].init_group, 4u);
    EXPECT_EQ(c[0].active_leaves, 1u);
    EXPECT_EQ(c[1].init_group, 2u);
    EXPECT_EQ(c[1].active_leaves, 3u);
    EXPECT_EQ(c[2].init_group, 0u);
    EXPECT_EQ(c[2].active_leaves, 2u);
    for (const cluster_changes& s : c) EXPECT_EQ(s.changes_number, 0u);
    // Figure 9's shaded leaves.
    EXPECT_EQ(active_leaves_of(f, 0, c[0]), (leaves{11}));
    EXPECT_EQ(sorted(active_leaves_of(f, 1, c[1])), (leaves{3, 4, 10}));
    EXPECT_EQ(active_leaves_of(f, 2, c[2]), (leaves{7, 8}));
    // init_position is 3 after them; splitting back (Eq. 12, 13) restores Figure 7.
    std::uint32_t position = 0;
    std::vector<cluster_changes> d(3);
    reset_lodf_clusters(f, d);
    retarget_lodf(f, d, position, 3, changed);
    EXPECT_EQ(position, 3u);
    EXPECT_EQ(retarget_lodf(f, d, position, 0, changed), 2u);
    EXPECT_EQ(position, 0u);
    for (std::uint32_t g = 0; g < 3; ++g) {
        EXPECT_EQ(d[g].init_group, 0u);
        EXPECT_EQ(d[g].active_leaves, f.clusters[g].original_leaves);
    }
    // All the way down: one leaf per group, F_{n-1} of Figure 4.
    retarget_lodf(f, d, position, 100, changed);
    EXPECT_EQ(position, 6u);
    EXPECT_EQ(active_leaves_of(f, 0, d[0]), (leaves{11}));
    EXPECT_EQ(active_leaves_of(f, 1, d[1]), (leaves{14}));
    EXPECT_EQ(active_leaves_of(f, 2, d[2]), (leaves{13}));
}

TEST(lodf, a_layout_that_breaks_a_rule_is_refused_with_the_reason) {
    const std::vector<leaves> queues{{1, 2, 0}, {5, 6, 4, 3}, {7, 8}};
    EXPECT_THROW(lay_out_lodf(9, queues, std::vector<std::uint32_t>{0, 1, 0, 1, 2}), std::invalid_argument);
    EXPECT_THROW(lay_out_lodf(9, queues, std::vector<std::uint32_t>{0, 0, 0, 1, 2, 1}), std::invalid_argument);
    const std::vector<leaves> twice{{1, 2, 0}, {5, 6, 4, 1}, {7, 8}};
    EXPECT_THROW(lay_out_lodf(9, twice, std::vector<std::uint32_t>{0, 1, 0, 1, 2, 1}), std::invalid_argument);
    try {
        lay_out_lodf(9, queues, std::vector<std::uint32_t>{0, 0, 0, 1, 2, 1});
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("cluster 0"), std::string::npos) << e.what();
    }
}

// A random structure: G clusters of random sizes, shuffled queues, a random interleaving.
lodf_structure random_structure(std::mt19937& rng, std::uint32_t leaf_count, std::uint32_t groups) {
    std::vector<std::uint32_t> order(leaf_count);
    for (std::uint32_t i = 0; i < leaf_count; ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::uint32_t> sizes(groups, 1);  // at least one leaf each
    for (std::uint32_t i = 0; i < leaf_count - groups; ++i)
        ++sizes[std::uniform_int_distribution<std::uint32_t>(0, groups - 1)(rng)];
    std::vector<leaves> queues(groups);
    std::vector<std::uint32_t> changed_group;
    std::size_t next = 0;
    for (std::uint32_t g = 0; g < groups; ++g) {
        queues[g].assign(order.begin() + std::ptrdiff_t(next), order.begin() + std::ptrdiff_t(next + sizes[g]));
        next += sizes[g];
        changed_group.insert(changed_group.end(), sizes[g] - 1, g);
    }
    std::shuffle(changed_group.begin(), changed_group.end(), rng);
    return lay_out_lodf(leaf_count, queues, changed_group);
}

// The active leaves of every level by plain set arithmetic over the collapses (Eq. 1), against
// the contiguous runs the counters give: a run is always exactly the cut of its cluster's tree.
TEST(lodf, every_cluster_draws_exactly_its_cut_as_one_run_at_every_level) {
    std::mt19937 rng(7);
    for (int trial = 0; trial < 40; ++trial) {
        const auto n = std::uint32_t(2 + rng() % 300), g = std::uint32_t(1 + rng() % std::min<std::uint32_t>(n, 12));
        const lodf_structure f = random_structure(rng, n, g);
        std::set<std::uint32_t> cut;
        for (std::uint32_t i = 0; i < n; ++i) cut.insert(i);
        std::vector<cluster_changes> c(g);
        reset_lodf_clusters(f, c);
        std::uint32_t position = 0;
        std::vector<std::uint32_t> changed;
        for (std::uint32_t k = 0; k <= f.collapse_count(); ++k) {
            if (k > 0) {
                ASSERT_EQ(cut.erase(f.collapses[k - 1].old1), 1u);
                ASSERT_EQ(cut.erase(f.collapses[k - 1].old2), 1u);
                cut.insert(n + k - 1);
                ASSERT_EQ(retarget_lodf(f, c, position, k, changed), 1u) << "one collapse touches one cluster";
                ASSERT_EQ(changed[0], f.changed_group[k - 1]);
            }
            leaves drawn;
            for (std::uint32_t gi = 0; gi < g; ++gi) {
                const leaves run = active_leaves_of(f, gi, c[gi]);
                drawn.insert(drawn.end(), run.begin(), run.end());
            }
            ASSERT_EQ(sorted(drawn), leaves(cut.begin(), cut.end())) << "trial " << trial << ", level " << k;
            ASSERT_EQ(drawn.size(), f.leaves_after(k));
        }
    }
}

// Jumping between any two levels gives the state of walking there one step at a time, and
// collapsing then splitting back returns F_0's leaves.
TEST(lodf, any_jump_equals_the_walk_and_collapse_then_split_returns_the_original_leaves) {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 40; ++trial) {
        const auto n = std::uint32_t(2 + rng() % 200), g = std::uint32_t(1 + rng() % std::min<std::uint32_t>(n, 9));
        const lodf_structure f = random_structure(rng, n, g);
        std::vector<cluster_changes> jump(g), walk(g);
        reset_lodf_clusters(f, jump);
        reset_lodf_clusters(f, walk);
        std::vector<cluster_changes> start = jump;
        std::uint32_t pj = 0, pw = 0;
        std::vector<std::uint32_t> changed;
        for (int hop = 0; hop < 10; ++hop) {
            const auto target = std::uint32_t(rng() % (f.collapse_count() + 1));
            const std::uint32_t before = pj;
            retarget_lodf(f, jump, pj, target, changed);
            const std::set<std::uint32_t> touched(changed.begin(), changed.end());
            while (pw != target) retarget_lodf(f, walk, pw, pw < target ? pw + 1 : pw - 1, changed);
            for (std::uint32_t gi = 0; gi < g; ++gi) {
                ASSERT_EQ(jump[gi].init_group, walk[gi].init_group);
                ASSERT_EQ(jump[gi].active_leaves, walk[gi].active_leaves);
            }
            // Exactly the clusters named between the two positions were touched.
            std::set<std::uint32_t> named;
            for (std::uint32_t k = std::min(before, target); k < std::max(before, target); ++k) named.insert(f.changed_group[k]);
            ASSERT_EQ(touched, named);
        }
        retarget_lodf(f, jump, pj, 0, changed);
        for (std::uint32_t gi = 0; gi < g; ++gi) {
            ASSERT_EQ(jump[gi].init_group, 0u);
            ASSERT_EQ(jump[gi].active_leaves, start[gi].active_leaves);
        }
    }
}

// A baked plant walked from F_0 to F_{n-1} and back: one leaf per cluster at the bottom, the
// model's foliage again at the top, and every step draws one index range per cluster.
TEST(lodf, a_baked_tree_walks_down_to_one_leaf_per_cluster_and_back) {
    const plant_model plant = generate_plant_model("broadleaf", 3, 64);
    const lodf_model m = bake_lodf(plant.lods[0], plant.has_hierarchy);
    const lodf_structure& f = m.structure;
    const auto g = std::uint32_t(f.clusters.size());
    std::vector<cluster_changes> c(g);
    reset_lodf_clusters(f, c);
    const auto drawn_indices = [&] {
        std::size_t n = 0;
        for (std::uint32_t k = 0; k < g; ++k) n += active_range(f, k, c[k]).index_count;
        return n;
    };
    const std::size_t full = drawn_indices();
    std::uint32_t position = 0;
    std::vector<std::uint32_t> changed;
    for (std::uint32_t step = 1; step <= 4; ++step) {
        retarget_lodf(f, c, position, f.collapse_count() * step / 4, changed);
        EXPECT_LT(drawn_indices(), full) << "step " << step;
    }
    for (std::uint32_t k = 0; k < g; ++k) EXPECT_EQ(c[k].active_leaves, 1u);
    EXPECT_EQ(drawn_indices(), 6u * g) << "F_{n-1}: one made quad per cluster";
    retarget_lodf(f, c, position, 0, changed);
    EXPECT_EQ(changed.size(), g);
    EXPECT_EQ(drawn_indices(), full);
}

}  // namespace
}  // namespace sylva
