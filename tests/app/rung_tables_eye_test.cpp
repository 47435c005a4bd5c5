// Where the rung tables are measured from (app/rung_tables.h typical_eye_height_m): the median
// height above the ground of the scenario's camera keys, to 0.5 m, at least 0.5 m.
#include <gtest/gtest.h>

#include "app/rung_tables.h"

namespace sylva {
namespace {

scenario_camera_key key(double x, double y, double z, bool above_terrain) {
    scenario_camera_key k;
    k.key.position = {x, y, z};
    k.above_terrain = above_terrain;
    return k;
}

TEST(rung_tables, are_seen_from_the_median_eye_height_of_the_camera_keys) {
    scenario s;
    // Ground at height x / 10 under each key. Heights above it: 30 (given above the terrain),
    // 27 − 10 = 17, 24 − 2 = 22 (absolute): median 22.
    s.camera.keyframes = {key(0, 30, 0, true), key(100, 27, 0, false), key(20, 24, 0, false)};
    const auto ground = [](double x, double) { return x / 10.0; };
    EXPECT_DOUBLE_EQ(typical_eye_height_m(s, ground), 22.0);
    // Four keys: the mean of the middle two, 17 and 22 → 19.5; rounded to 0.5 m.
    s.camera.keyframes.push_back(key(0, 1.7, 0, true));
    EXPECT_DOUBLE_EQ(typical_eye_height_m(s, ground), 19.5);
    s.camera.keyframes = {key(0, 1.64, 0, true)};
    EXPECT_DOUBLE_EQ(typical_eye_height_m(s, ground), 1.5);
    // A camera at or below the ground still looks from half a metre.
    s.camera.keyframes = {key(50, 2.0, 0, false)};
    EXPECT_DOUBLE_EQ(typical_eye_height_m(s, ground), 0.5);
    s.camera.keyframes.clear();
    EXPECT_EQ(typical_eye_height_m(s, ground), k_rung_table_level_eye);
}

}  // namespace
}  // namespace sylva
