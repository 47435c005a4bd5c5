#include "models/bake/radiance_transfer.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <glm/geometric.hpp>
#include <stdexcept>

#include "models/cache/radiance_transfer_io.h"
#include "models/random.h"

namespace sylva {
namespace {

// Clamped-cosine projection of n = +y, by hand (Ramamoorthi & Hanrahan 2001, Eqs. 7-9, with
// the basis constants of spherical_harmonics.h): band l is A_l Y_lm(n).
//   T_0 = pi * 0.282095                    =  0.886228
//   T_1 = 2 pi / 3 * 0.488603 * y (= 1)    =  1.023328
//   T_6 = pi / 4 * 0.315392 * (3 z^2 - 1)  = -0.247708  (z = 0)
//   T_8 = pi / 4 * 0.546274 * (x^2 - y^2)  = -0.429043
//   T_2, T_3, T_4, T_5, T_7 = 0 (they hold x or z)
constexpr float k_t0 = 0.886228f;
constexpr float k_t1 = 1.023328f;
constexpr float k_t6 = -0.247708f;
constexpr float k_t8 = -0.429043f;

// Projected solid angle of a square of half-size 1 centred 1 above the receiver, parallel to
// it (a cube face seen from the cube's centre): four corner rectangles of the form factor to a
// parallel rectangle, F = 1/(2 pi) [X/sqrt(1+X^2) atan(Y/sqrt(1+X^2)) + (X <-> Y)] with
// X = Y = 1 (Howell, "A Catalog of Radiation Heat Transfer Configuration Factors", B-3):
// F = 4 * 2 * 0.707107 * 0.615480 / (2 pi) = 0.554126, projected solid angle pi F = 1.740840,
// so T_0 loses 0.282095 * 1.740840 = 0.491082.
constexpr float k_cube_face_t0_loss = 0.491082f;

vertex receiver_at(glm::vec3 p, glm::vec3 n) {
    return vertex{p, n, glm::vec2(0.0f)};
}

// A square of half-size `half` at height y, facing `normal_y` (+1 up, -1 down), as one submesh.
mesh_data quad(float y, float half, float normal_y, material_kind material) {
    mesh_data m;
    const glm::vec3 n(0.0f, normal_y, 0.0f);
    m.vertices = {{{-half, y, -half}, n, {0, 0}},
                  {{half, y, -half}, n, {1, 0}},
                  {{half, y, half}, n, {1, 1}},
                  {{-half, y, half}, n, {0, 1}}};
    m.indices = {0, 1, 2, 0, 2, 3};
    m.submeshes = {{0, 6, material}};
    return m;
}

image_rgba8 flat_texture(std::uint8_t alpha) {
    image_rgba8 t{4, 4, std::vector<std::uint8_t>(4 * 4 * 4, 200)};
    for (std::size_t i = 3; i < t.texels.size(); i += 4) t.texels[i] = alpha;
    return t;
}

transfer_settings rays(std::uint32_t n) {
    transfer_settings s;
    s.rays_per_receiver = n;
    return s;
}

const vertex k_up = receiver_at(glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));

void expect_unoccluded_front(const radiance_transfer& t) {
    ASSERT_EQ(t.front.size(), 9u);
    EXPECT_NEAR(t.front[0], k_t0, 1e-5);
    EXPECT_NEAR(t.front[1], k_t1, 1e-5);
    for (int k : {2, 3, 4, 5, 7}) EXPECT_NEAR(t.front[k], 0.0f, 1e-6) << k;
    EXPECT_NEAR(t.front[6], k_t6, 1e-5);
    EXPECT_NEAR(t.front[8], k_t8, 1e-5);
}

TEST(radiance_transfer, unoccluded_receiver_gets_the_clamped_cosine_projection_on_both_sides) {
    const transfer_occluders occluders(mesh_data{}, image_rgba8{});
    const radiance_transfer t = occluders.bake(std::span(&k_up, 1), rays(64));
    EXPECT_EQ(t.bands, 3u);
    EXPECT_EQ(t.receiver_count(), 1u);
    expect_unoccluded_front(t);
    // The back is the projection of -n: the odd band flips sign, the even bands do not.
    EXPECT_NEAR(t.back[0], k_t0, 1e-5);
    EXPECT_NEAR(t.back[1], -k_t1, 1e-5);
    EXPECT_NEAR(t.back[6], k_t6, 1e-5);
    EXPECT_NEAR(t.back[8], k_t8, 1e-5);
}

TEST(radiance_transfer, opaque_quad_above_removes_its_projected_solid_angle_from_the_front) {
    const transfer_occluders occluders(quad(1.0f, 1.0f, -1.0f, material_kind::bark), image_rgba8{});
    const radiance_transfer t = occluders.bake(std::span(&k_up, 1), rays(4096));
    // 4096 rays: the estimate's spread is about 1 % of the loss.
    EXPECT_NEAR(t.front[0], k_t0 - k_cube_face_t0_loss, 0.01f);
    EXPECT_NEAR(t.back[0], k_t0, 1e-5);  // nothing below
}

TEST(radiance_transfer, opaque_surface_seen_from_behind_is_the_receivers_own_and_does_not_shadow) {
    // The quad faces up, away from the receiver: as for a vertex inside a closed bark tube.
    const transfer_occluders occluders(quad(1.0f, 1.0f, 1.0f, material_kind::bark), image_rgba8{});
    expect_unoccluded_front(occluders.bake(std::span(&k_up, 1), rays(1024)));
}

TEST(radiance_transfer, leaf_quad_shadows_from_either_side_unless_its_texels_are_cut_away) {
    for (const float facing : {1.0f, -1.0f}) {
        const mesh_data leaf = quad(1.0f, 1.0f, facing, material_kind::leaf);
        const transfer_occluders solid(leaf, flat_texture(255));
        EXPECT_NEAR(solid.bake(std::span(&k_up, 1), rays(4096)).front[0],
                    k_t0 - k_cube_face_t0_loss, 0.01f);
        const transfer_occluders cut_out(leaf, flat_texture(0));
        expect_unoccluded_front(cut_out.bake(std::span(&k_up, 1), rays(1024)));
    }
}

TEST(radiance_transfer, quad_behind_the_receiver_shadows_its_back_only) {
    // Facing up, towards the receiver's back side.
    const transfer_occluders occluders(quad(-1.0f, 1.0f, 1.0f, material_kind::bark), image_rgba8{});
    const radiance_transfer t = occluders.bake(std::span(&k_up, 1), rays(4096));
    expect_unoccluded_front(t);
    EXPECT_NEAR(t.back[0], k_t0 - k_cube_face_t0_loss, 0.01f);
}

// Receivers scattered under scattered leaves and bark: some shadowed, some not.
struct scattered_scene {
    mesh_data mesh;
    std::vector<vertex> receivers;
    scattered_scene() {
        rng random(7);
        for (int q = 0; q < 40; ++q) {
            const glm::vec3 c(random.uniform(-2, 2), random.uniform(0, 3), random.uniform(-2, 2));
            const auto base = std::uint32_t(mesh.vertices.size());
            const glm::vec3 n(0.0f, random.uniform() < 0.5f ? 1.0f : -1.0f, 0.0f);
            for (glm::vec2 d :
                 {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
                mesh.vertices.push_back(
                    {c + 0.3f * glm::vec3(d.x, 0.0f, d.y), n, (d + 1.0f) * 0.5f});
            for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
        }
        mesh.submeshes = {{0, 60, material_kind::bark}, {60, 180, material_kind::leaf}};
        for (int r = 0; r < 300; ++r) {
            const glm::vec3 n =
                glm::normalize(glm::vec3(random.uniform(-1, 1), 1.0f, random.uniform(-1, 1)));
            receivers.push_back(receiver_at(
                {random.uniform(-2, 2), random.uniform(-1, 2), random.uniform(-2, 2)}, n));
        }
    }
};

TEST(radiance_transfer, two_bands_are_the_first_four_coefficients_of_three) {
    const scattered_scene scene;
    const transfer_occluders occluders(scene.mesh, flat_texture(255));
    transfer_settings two = rays(64);
    two.bands = 2;
    const radiance_transfer t2 = occluders.bake(scene.receivers, two);
    const radiance_transfer t3 = occluders.bake(scene.receivers, rays(64));
    ASSERT_EQ(t2.receiver_count(), scene.receivers.size());
    bool any_shadowed = false;
    for (std::size_t r = 0; r < scene.receivers.size(); ++r) {
        for (std::size_t k = 0; k < 4; ++k) {
            ASSERT_EQ(t2.front[r * 4 + k], t3.front[r * 9 + k]);
            ASSERT_EQ(t2.back[r * 4 + k], t3.back[r * 9 + k]);
        }
        any_shadowed |= t3.front[r * 9] < k_t0 - 0.01f;
    }
    EXPECT_TRUE(any_shadowed);
}

TEST(radiance_transfer, one_and_two_threads_give_identical_bits_with_and_without_the_bounce) {
    const scattered_scene scene;
    for (const bool bounce : {false, true}) {
        auto bake_with = [&](std::size_t threads) {
            tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
            // Fresh occluders: the bounce source is baked under the same thread limit.
            const transfer_occluders occluders(scene.mesh, flat_texture(255), flat_texture(255));
            transfer_settings s = rays(64);
            s.interreflection = bounce;
            return occluders.bake(scene.receivers, s);
        };
        const radiance_transfer one = bake_with(1);
        const radiance_transfer two = bake_with(2);
        EXPECT_EQ(one.front, two.front) << bounce;
        EXPECT_EQ(one.back, two.back) << bounce;
    }
}

TEST(radiance_transfer, interreflection_adds_the_light_the_occluder_reflects) {
    // The quad above faces the receiver; its own vertices see nothing, so their transfer is the
    // exact T_0 = 0.886228, and the bark's albedo is its texture's mean, 200/255 = 0.784314.
    // Bounce T_0 = albedo/pi * 0.886228 * (projected solid angle 1.740840) = 0.385162 on top of
    // the shadowed 0.886228 - 0.491082 = 0.395146: 0.780308.
    const transfer_occluders occluders(quad(1.0f, 1.0f, -1.0f, material_kind::bark), image_rgba8{},
                                       flat_texture(255));
    transfer_settings s = rays(4096);
    s.interreflection = true;
    const radiance_transfer t = occluders.bake(std::span(&k_up, 1), s);
    EXPECT_NEAR(t.front[0], 0.780308f, 0.01f);
    EXPECT_NEAR(t.back[0], k_t0, 1e-5);
    // Nothing to bounce from: still the exact projection.
    expect_unoccluded_front(
        transfer_occluders(mesh_data{}, image_rgba8{}).bake(std::span(&k_up, 1), s));
}

TEST(radiance_transfer, rejects_bands_other_than_two_or_three_and_zero_rays) {
    const transfer_occluders occluders(mesh_data{}, image_rgba8{});
    transfer_settings s;
    s.bands = 4;
    EXPECT_THROW(occluders.bake(std::span(&k_up, 1), s), std::invalid_argument);
    EXPECT_THROW(occluders.bake(std::span(&k_up, 1), rays(0)), std::invalid_argument);
}

TEST(radiance_transfer_io, round_trip_keeps_every_bit_and_truncation_throws) {
    const scattered_scene scene;
    const transfer_occluders occluders(scene.mesh, flat_texture(255));
    transfer_settings two = rays(16);
    two.bands = 2;
    const std::vector<radiance_transfer> transfers = {occluders.bake(scene.receivers, rays(16)),
                                                      occluders.bake(scene.receivers, two)};
    const std::vector<std::byte> bytes = serialize_radiance_transfers(transfers);
    const std::vector<radiance_transfer> back = deserialize_radiance_transfers(bytes);
    ASSERT_EQ(back.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(back[i].bands, transfers[i].bands);
        EXPECT_EQ(back[i].front, transfers[i].front);
        EXPECT_EQ(back[i].back, transfers[i].back);
    }
    for (std::size_t cut :
         {std::size_t(0), std::size_t(3), std::size_t(12), bytes.size() / 2, bytes.size() - 1})
        EXPECT_THROW(deserialize_radiance_transfers(std::span(bytes).first(cut)),
                     std::runtime_error)
            << cut;
}

TEST(radiance_transfer_io, other_format_and_mismatched_sizes_throw) {
    radiance_transfer t;
    t.front = std::vector<float>(9, 1.0f);
    t.back = std::vector<float>(9, 2.0f);
    std::vector<std::byte> bytes = serialize_radiance_transfers(std::span(&t, 1));
    bytes[4] = std::byte(0xff);  // the format number follows the 4-byte magic
    EXPECT_THROW(deserialize_radiance_transfers(bytes), std::runtime_error);
    t.back.pop_back();
    EXPECT_THROW(deserialize_radiance_transfers(serialize_radiance_transfers(std::span(&t, 1))),
                 std::runtime_error);
}

}  // namespace
}  // namespace sylva
