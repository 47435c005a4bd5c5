#include "systems/cull_system.h"

#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "systems/select_representation_system.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

frustum_planes looking_down_minus_z() {
    camera cam;
    cam.fov_y = glm::radians(90.0f);
    cam.aspect = 1.0f;
    cam.near_plane = 1.0f;
    cam.far_plane = 100.0f;
    cam.forward = {0.0f, 0.0f, -1.0f};
    derive_camera_matrices(cam);
    return extract_frustum_planes(cam.projection * cam.view);
}

TEST(frustum, planes_are_normalised_and_face_inside) {
    const frustum_planes f = looking_down_minus_z();
    for (const auto& p : f.planes) {
        EXPECT_NEAR(glm::length(glm::vec3(p)), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(glm::vec3(p), glm::vec3(0, 0, -10)) + p.w, 0.0f);  // a point inside
    }
}

TEST(frustum, sphere_tests_against_a_90_degree_frustum) {
    const frustum_planes f = looking_down_minus_z();
    EXPECT_TRUE(sphere_in_frustum(f, {0, 0, -10}, 0.5f));
    EXPECT_FALSE(sphere_in_frustum(f, {0, 0, 10}, 1.0f));     // behind
    EXPECT_FALSE(sphere_in_frustum(f, {0, 0, -200}, 1.0f));   // beyond far
    // At z = -10 the side planes are at x = ±10 (90° fov): a sphere at x = 11 reaches in with
    // radius 1 (distance to the plane x = -z is 1/√2) but not with radius 0.5.
    EXPECT_TRUE(sphere_in_frustum(f, {11, 0, -10}, 1.0f));
    EXPECT_FALSE(sphere_in_frustum(f, {11, 0, -10}, 0.5f));
}

TEST(select_representation, switches_at_the_species_distance_scaled_by_size_and_lod_scale) {
    species_entry oak;
    oak.reduced_distance_m = 50.0f;
    oak.far_distance_m = 200.0f;
    EXPECT_EQ(choose_representation(oak, 49.0f, 1.0f, 1.0f), representation::mesh_full);
    EXPECT_EQ(choose_representation(oak, 51.0f, 1.0f, 1.0f), representation::mesh_reduced);
    EXPECT_EQ(choose_representation(oak, 99.0f, 2.0f, 1.0f), representation::mesh_full);
    EXPECT_EQ(choose_representation(oak, 51.0f, 1.0f, 0.5f), representation::mesh_reduced);
    EXPECT_EQ(choose_representation(oak, 24.0f, 1.0f, 0.5f), representation::mesh_full);
    EXPECT_EQ(choose_representation(oak, 201.0f, 1.0f, 1.0f), representation::mesh_far);
    EXPECT_EQ(choose_representation(oak, 399.0f, 2.0f, 1.0f), representation::mesh_reduced);
}

TEST(select_representation, bench_policies_fix_or_hard_switch_the_choice) {
    species_entry oak;
    oak.reduced_distance_m = 50.0f;
    oak.far_distance_m = 200.0f;
    EXPECT_EQ(choose_representation(lod_policy{}, oak, 51.0f, 1.0f, 1.0f), representation::mesh_reduced);
    lod_policy single{lod_policy::kind::single, representation::mesh_far, representation::none, 0.0f};
    EXPECT_EQ(choose_representation(single, oak, 1.0f, 1.0f, 1.0f), representation::mesh_far);
    // Hard switch at 30 m for a plant of scale 2 and lod_scale 0.5: 30 * 2 * 0.5 = 30 m.
    lod_policy baseline{lod_policy::kind::hard_switch, representation::mesh_full, representation::mesh_far, 30.0f};
    EXPECT_EQ(choose_representation(baseline, oak, 29.9f, 2.0f, 0.5f), representation::mesh_full);
    EXPECT_EQ(choose_representation(baseline, oak, 30.0f, 2.0f, 0.5f), representation::mesh_far);
    EXPECT_EQ(choose_representation(baseline, oak, std::nanf(""), 2.0f, 0.5f), representation::mesh_far);
}

}  // namespace
}  // namespace sylva
