// Determinism across chunk boundaries. thread_count_determinism_test plays tiny, whose 60 plants
// fit in one 4096-entity chunk: no parallel loop there runs more than one chunk, so the
// per-chunk counts, the draw list's prefix-sum merge and the hand-over from chunk to chunk are
// never crossed. Here a small scene runs with a chunk of k_chunk entities
// (player_options::chunk_size: chunking never depends on the thread count, and a smaller chunk
// only splits the same loops into more tasks). Each representation family is played with 1, 2
// and 4 threads; the test first proves from the schedule's loop records that every parallel
// loop of every frame ran at least three chunks, then that the per-frame image and state
// hashes are identical, and identical to those of the default chunk.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "../gl/gl_test_support.h"
#include "app/scenario_player.h"
#include "ecs/parallel.h"
#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

constexpr std::size_t k_chunk = 8;
constexpr std::size_t k_min_chunks = 3;

// The scene: 120 plants in about 20 eco tiles of at most 8, spruces split into octree cells
// (Deussen 2002 §6.1), a 40 m shadow distance so that far tiles can be drawn as their point
// sets (§6.2), a camera in a corner looking across the terrain, and the ground in 8 x 8 tiles
// (their grids chosen in chunks too).
scenario chunk_scene() {
    return load_scenario_file(std::filesystem::path(SYLVA_SOURCE_DIR) /
                              "tests/determinism/data/chunk_boundaries.json");
}

struct variant {
    std::string name;
    player_options options;
    bool eco_tiles = true;
};

player_options with_policy(lod_policy::kind mode, std::string lighting = {}) {
    player_options o;
    o.policy.mode = mode;
    o.scenario_lod = false;
    o.measure_costs = false;  // the paper's costs: a measured cost would differ run to run
    o.lighting = std::move(lighting);
    o.chunk_size = k_chunk;
    return o;
}

struct frame_trace {
    std::uint64_t image = 0;
    std::uint64_t state = 0;
    std::uint32_t aggregated_tiles = 0;
    std::array<std::uint32_t, std::size_t(representation::count)> instances{};
    // Per system in registration order, the loops it ran.
    std::vector<std::pair<std::string, std::vector<ecs::loop_record>>> loops;
};

struct run_trace {
    std::vector<frame_trace> frames;
    bool every_species_sh = false;  // every species lit by SH transfer
};

run_trace play(const variant& v, int threads, bake_cache& cache) {
    scenario s = chunk_scene();
    s.eco_tiles.enabled = v.eco_tiles;
    scenario_player player(std::move(s), threads, testing::shared_gl_context(), &cache, v.options);
    run_trace run;
    run.every_species_sh = true;
    for (const species_entry& species : player.assets().library.species)
        run.every_species_sh = run.every_species_sh && species.lighting == lighting_variant::sh;
    std::vector<frame_trace>& frames = run.frames;
    for (std::uint32_t f = 0; f < player.settings().frames; ++f) {
        const frame_record r = player.step();
        frame_trace t;
        t.state = r.state_hash;
        t.aggregated_tiles = r.aggregated_tiles;
        t.instances = r.instances;
        const image_rgba8 image = player.capture();
        t.image = fnv1a(image.texels.data(), image.texels.size());
        for (const std::string_view name : player.schedule().system_names())
            t.loops.emplace_back(std::string(name), player.schedule().last_loops(name));
        frames.push_back(std::move(t));
    }
    return run;
}

// How many loops with work each system must have run in every frame of a variant, so the
// chunk check below cannot pass because a loop was skipped.
struct expected_loops {
    std::size_t cull = 1;  // the tile pass, or the flat pass without tiles
    std::size_t select_representation = 1;
    std::size_t update_point_prefix = 0;  // plants, then octree cells (points and lines only)
    std::size_t build_draw_list = 3;      // plant counts, plant items, instance records
};

std::size_t loops_with_work(const frame_trace& t, const std::string& system) {
    for (const auto& [name, loops] : t.loops)
        if (name == system) {
            std::size_t n = 0;
            for (const ecs::loop_record& loop : loops) n += loop.count > 0;
            return n;
        }
    ADD_FAILURE() << "no system " << system;
    return 0;
}

// Every parallel loop that had work ran every one of its chunks, and at least k_min_chunks.
// A loop with nothing to do: cull's pass over plants outside the eco tiles (spawn_scenario
// puts every plant in a tile) and, except under points and lines, the octree-cell loops (cells
// exist only where point sets are baked).
void expect_every_loop_crosses_chunks(const std::vector<frame_trace>& frames,
                                      const expected_loops& expected) {
    // What ran, for the log: per loop with work, the fewest chunks any frame ran it in.
    for (const auto& [system, loops] : frames.front().loops)
        for (std::size_t i = 0; i < loops.size(); ++i) {
            std::size_t fewest = loops[i].chunks_run, items = loops[i].count;
            for (const frame_trace& t : frames)
                for (const auto& [name, other] : t.loops)
                    if (name == system && i < other.size() && other[i].chunks_run < fewest) {
                        fewest = other[i].chunks_run;
                        items = other[i].count;
                    }
            if (items > 0)
                std::printf("  %s loop %zu: >= %zu chunks of %zu (%zu items)\n", system.c_str(), i,
                            fewest, loops[i].chunk, items);
        }
    for (std::size_t f = 0; f < frames.size(); ++f) {
        SCOPED_TRACE("frame " + std::to_string(f));
        for (const auto& [system, loops] : frames[f].loops)
            for (std::size_t i = 0; i < loops.size(); ++i) {
                const ecs::loop_record& loop = loops[i];
                if (loop.count == 0) continue;
                EXPECT_EQ(loop.chunks_run, ecs::chunk_count(loop.count, loop.chunk))
                    << system << " loop " << i;
                EXPECT_GE(loop.chunks_run, k_min_chunks)
                    << system << " loop " << i << ": " << loop.count << " items in chunks of "
                    << loop.chunk;
            }
        EXPECT_EQ(loops_with_work(frames[f], "cull"), expected.cull);
        EXPECT_EQ(loops_with_work(frames[f], "select_representation"),
                  expected.select_representation);
        EXPECT_EQ(loops_with_work(frames[f], "update_point_prefix"), expected.update_point_prefix);
        EXPECT_EQ(loops_with_work(frames[f], "build_draw_list"), expected.build_draw_list);
    }
}

// Plays `v` with 1, 2 and 4 threads (and once with the default chunk) and returns the 1-thread
// run.
run_trace expect_same_for_1_2_and_4_threads(const variant& v, const expected_loops& expected) {
    const std::filesystem::path cache_dir =
        std::filesystem::temp_directory_path() /
        ("sylva_chunk_test_" + v.name + "_" + std::to_string(::getpid()));
    bake_cache cache(cache_dir);
    const run_trace run = play(v, 1, cache);
    const std::vector<frame_trace>& one = run.frames;
    EXPECT_GE(one.size(), 2u);
    expect_every_loop_crosses_chunks(one, expected);
    EXPECT_NE(one.front().image, one.back().image) << "the camera moves: frames must differ";
    for (const int threads : {2, 4}) {
        SCOPED_TRACE(std::to_string(threads) + " threads");
        const std::vector<frame_trace> other = play(v, threads, cache).frames;
        EXPECT_EQ(other.size(), one.size());
        for (std::size_t f = 0; f < std::min(one.size(), other.size()); ++f) {
            EXPECT_EQ(other[f].state, one[f].state) << "frame " << f;
            EXPECT_EQ(other[f].image, one[f].image) << "frame " << f;
            // The same loops in the same chunks: chunking is a function of the counts only.
            EXPECT_EQ(other[f].loops, one[f].loops) << "frame " << f;
        }
    }
    // And the same as with the default chunk, where every loop over plants runs one chunk: the
    // chunk size changes how work is cut, never a result.
    variant whole = v;
    whole.options.chunk_size = ecs::k_default_chunk;
    const std::vector<frame_trace> one_chunk = play(whole, 2, cache).frames;
    EXPECT_EQ(one_chunk.size(), one.size());
    for (std::size_t f = 0; f < std::min(one.size(), one_chunk.size()); ++f) {
        EXPECT_EQ(one_chunk[f].state, one[f].state) << "default chunk, frame " << f;
        EXPECT_EQ(one_chunk[f].image, one[f].image) << "default chunk, frame " << f;
    }
    std::filesystem::remove_all(cache_dir);
    return run;
}

std::uint32_t drawn_as(const std::vector<frame_trace>& frames, representation r) {
    std::uint32_t n = 0;
    for (const frame_trace& t : frames) n += t.instances[std::size_t(r)];
    return n;
}

TEST(chunk_boundary_determinism, mesh_levels) {
    SYLVA_REQUIRE_GL();
    const std::vector<frame_trace> one =
        expect_same_for_1_2_and_4_threads(
            {"mesh_levels", with_policy(lod_policy::kind::distance_levels)}, {})
            .frames;
    EXPECT_GT(drawn_as(one, representation::mesh_full), 0u);
    EXPECT_GT(drawn_as(one, representation::mesh_far), 0u);
}

TEST(chunk_boundary_determinism, points_and_lines_with_tile_sets) {
    SYLVA_REQUIRE_GL();
    expected_loops expected;
    expected.update_point_prefix = 2;
    expected.build_draw_list = 5;  // and the octree cells' counts and items
    const std::vector<frame_trace> one =
        expect_same_for_1_2_and_4_threads(
            {"points_lines", with_policy(lod_policy::kind::points_lines)}, expected)
            .frames;
    std::uint32_t aggregated = 0;
    for (const frame_trace& t : one) aggregated += t.aggregated_tiles;
    EXPECT_GT(aggregated, 0u) << "no eco tile was drawn as its point set";
    EXPECT_GT(drawn_as(one, representation::points), 0u);
}

// Without eco tiles, so that cull's flat pass over every plant is the one crossing chunks.
TEST(chunk_boundary_determinism, billboard_clouds_culled_flat) {
    SYLVA_REQUIRE_GL();
    const std::vector<frame_trace> one =
        expect_same_for_1_2_and_4_threads(
            {"billboard_clouds", with_policy(lod_policy::kind::billboard_clouds), false}, {})
            .frames;
    EXPECT_GT(drawn_as(one, representation::billboard_cloud), 0u);
}

TEST(chunk_boundary_determinism, sh_lit_points_and_lines) {
    SYLVA_REQUIRE_GL();
    expected_loops expected;
    expected.update_point_prefix = 2;
    expected.build_draw_list = 5;
    const run_trace one = expect_same_for_1_2_and_4_threads(
        {"points_lines_sh", with_policy(lod_policy::kind::points_lines, "sh")}, expected);
    EXPECT_TRUE(one.every_species_sh);
}

// Full mesh, billboard cloud, points and lines, crossed billboard: every handover between the
// papers' rungs, with switch sizes for the scene's 90-pixel-high frames, for both species.
player_options with_every_handover() {
    player_options options = with_policy(lod_policy::kind::ladder);
    ladder l;
    l.count = 4;
    l.rungs = {representation::mesh_full, representation::billboard_cloud, representation::points,
               representation::crossed_billboard};
    l.below_px = {0.0f, 40.0f, 16.0f, 6.0f};
    l.band = {0.0f, 0.15f, 0.15f, 0.15f};
    options.policy.ladders = {l, l};
    return options;
}

// DESIGN §1.5: every rung of a ladder in one frame, with bands, split spruces fading their
// cells' points in and out as partners.
TEST(chunk_boundary_determinism, ladder_with_every_handover) {
    SYLVA_REQUIRE_GL();
    const player_options options = with_every_handover();
    expected_loops expected;
    expected.update_point_prefix = 2;
    expected.build_draw_list = 5;
    const std::vector<frame_trace> one =
        expect_same_for_1_2_and_4_threads({"ladder", options}, expected).frames;
    for (const representation r : {representation::mesh_full, representation::billboard_cloud,
                                   representation::points, representation::crossed_billboard})
        EXPECT_GT(drawn_as(one, r), 0u) << "no plant on rung " << int(r);
}

// The same ladder ending on the eco tiles' sets (Deussen 2002 §6.2): tiles hand over from their
// plants' points to their sets across the band, in part, as the tile walk decides.
TEST(chunk_boundary_determinism, ladder_to_the_eco_tiles) {
    SYLVA_REQUIRE_GL();
    player_options options = with_every_handover();
    for (ladder& l : options.policy.ladders) l.rungs[3] = representation::eco_tile;
    expected_loops expected;
    expected.update_point_prefix = 2;
    expected.build_draw_list = 5;
    const std::vector<frame_trace> one =
        expect_same_for_1_2_and_4_threads({"ladder_eco_tiles", options}, expected).frames;
    std::uint32_t aggregated = 0;
    for (const frame_trace& t : one) aggregated += t.aggregated_tiles;
    EXPECT_GT(aggregated, 0u) << "no eco tile was drawn as its point set";
    for (const representation r : {representation::mesh_full, representation::points, representation::eco_tile})
        EXPECT_GT(drawn_as(one, r), 0u) << "no plant on rung " << int(r);
}

// DESIGN §1.5 `auto`: the same ladder with every rung chosen by the budget solver from tables
// measured on this scene's species (through the test's cache), a budget between all-cheapest
// and all-best so that the solver has to mix rungs.
TEST(chunk_boundary_determinism, auto_ladder_under_a_budget) {
    SYLVA_REQUIRE_GL();
    player_options options = with_every_handover();
    options.plant_budget_ms = 20.0;
    expected_loops expected;
    expected.select_representation = 2;  // the histograms, then the choices
    expected.update_point_prefix = 2;
    expected.build_draw_list = 5;
    const std::vector<frame_trace> one =
        expect_same_for_1_2_and_4_threads({"auto_ladder", options}, expected).frames;
    std::size_t rungs_used = 0;
    for (const representation r : {representation::mesh_full, representation::billboard_cloud,
                                   representation::points, representation::crossed_billboard})
        rungs_used += drawn_as(one, r) > 0;
    EXPECT_GE(rungs_used, 2u) << "the budget should make the solver mix rungs";
}

// The budget solver with the eco-tile rung (lod/ladder.h): not a rung of the solver's own; a
// plant it puts on points goes on to its tile by size, and the tile walk decides.
TEST(chunk_boundary_determinism, auto_ladder_to_the_eco_tiles) {
    SYLVA_REQUIRE_GL();
    player_options options = with_every_handover();
    for (ladder& l : options.policy.ladders) l.rungs[3] = representation::eco_tile;
    options.plant_budget_ms = 20.0;
    expected_loops expected;
    expected.select_representation = 2;
    expected.update_point_prefix = 2;
    expected.build_draw_list = 5;
    const std::vector<frame_trace> one =
        expect_same_for_1_2_and_4_threads({"auto_ladder_eco", options}, expected).frames;
    EXPECT_GT(drawn_as(one, representation::eco_tile), 0u) << "no plant was drawn by its tile";
}

}  // namespace
}  // namespace sylva
