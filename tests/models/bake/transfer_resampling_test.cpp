#include "models/bake/transfer_resampling.h"

#include <gtest/gtest.h>

namespace sylva {
namespace {

// Two full-mesh vertices, 2 bands: A at the origin facing +y with front (1, 0, 0, 0) and back
// (0.25, 0, 0, 0); B at x = 10 facing +y with front (0.5, 0, 0.1, 0), back 0.
struct two_vertices {
    mesh_data full;
    radiance_transfer transfer;
    two_vertices() {
        full.vertices = {{{0, 0, 0}, {0, 1, 0}, {0, 0}}, {{10, 0, 0}, {0, 1, 0}, {0, 0}}};
        transfer.bands = 2;
        transfer.front = {1.0f, 0.0f, 0.0f, 0.0f, 0.5f, 0.0f, 0.1f, 0.0f};
        transfer.back = {0.25f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    }
};

TEST(transfer_resampling, takes_the_nearest_vertex_and_turns_it_to_the_receivers_side) {
    const two_vertices s;
    const std::vector<vertex> receivers = {{{1, 0, 0}, {0, 1, 0}, {0, 0}},   // near A, same side
                                           {{1, 0, 0}, {0, -1, 0}, {0, 0}},  // near A, facing away
                                           {{9, 0, 0}, {0.6f, 0.8f, 0}, {0, 0}}};  // near B
    const radiance_transfer t = resample_transfer(s.full, s.transfer, receivers, 1);
    ASSERT_EQ(t.receiver_count(), 3u);
    EXPECT_FLOAT_EQ(t.front[0], 1.0f);
    EXPECT_FLOAT_EQ(t.back[0], 0.25f);
    EXPECT_FLOAT_EQ(t.front[4], 0.25f);  // A's back is this receiver's front
    EXPECT_FLOAT_EQ(t.back[4], 1.0f);
    EXPECT_FLOAT_EQ(t.front[8], 0.5f);
    EXPECT_FLOAT_EQ(t.front[10], 0.1f);
}

TEST(transfer_resampling, averages_the_k_nearest) {
    const two_vertices s;
    const std::vector<vertex> receivers = {{{4, 0, 0}, {0, 1, 0}, {0, 0}}};
    const radiance_transfer t = resample_transfer(s.full, s.transfer, receivers, 2);
    EXPECT_FLOAT_EQ(t.front[0], 0.75f);  // (1 + 0.5) / 2
    EXPECT_FLOAT_EQ(t.front[2], 0.05f);
    EXPECT_FLOAT_EQ(t.back[0], 0.125f);
    // k beyond the vertex count uses them all.
    EXPECT_FLOAT_EQ(resample_transfer(s.full, s.transfer, receivers, 8).front[0], 0.75f);
}

TEST(transfer_resampling, rejects_a_transfer_of_another_mesh) {
    two_vertices s;
    s.transfer.front.resize(4);
    s.transfer.back.resize(4);
    EXPECT_THROW(resample_transfer(s.full, s.transfer, {}, 1), std::invalid_argument);
    EXPECT_THROW(resample_transfer(two_vertices().full, two_vertices().transfer, {}, 0),
                 std::invalid_argument);
}

}  // namespace
}  // namespace sylva
