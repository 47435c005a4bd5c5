// Precomputed radiance transfer in the renderer (Behrendt 2005 §4, shaders/transfer.glsl): a
// surface whose transfer is the unoccluded clamped-cosine projection must look like the same
// surface lit by its normal (the sky term is identical, the sun's 3-band approximation is within
// a few per cent), one whose transfer is halved must look darker, and another object's shadow
// must still darken an SH-lit surface although the shadow map is read outside the plant's own
// sphere.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "flat_scene.h"
#include "gl_test_support.h"
#include "lighting/sky_model.h"
#include "lighting/transfer_rotation.h"
#include "systems/render/renderer.h"
#include "models/bake/transfer_pages.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

using testing::horizontal_quad;
using testing::luminance_at;
using testing::render_frame;
using testing::solid;

// Ramamoorthi & Hanrahan 2001, Eqs. 7-9: the clamped cosine about n has band-l coefficients
// A_l Y_lm(n), A = (pi, 2 pi / 3, pi / 4): an unoccluded receiver's transfer.
sh9 clamped_cosine(glm::vec3 n, float scale) {
    const float a[3] = {3.14159265f, 2.0943951f, 0.78539816f};
    const sh9 y = sh_basis(n);
    sh9 t{};
    for (std::size_t i = 0; i < 9; ++i) t[i] = scale * a[i == 0 ? 0 : (i < 4 ? 1 : 2)] * y[i];
    return t;
}

mesh_data with_transfer(mesh_data m, float scale) {
    const vertex_transfer t =
        pack_transfer(clamped_cosine({0, 1, 0}, scale), clamped_cosine({0, -1, 0}, scale));
    m.transfer.assign(m.vertices.size(), t);
    return m;
}

struct transfer_scene {
    scene_assets assets;
    camera cam;
    sun light;
    environment sky;
};

// Mesh 1: a normal-lit bark card; 2: the same with unoccluded transfer; 3: with half of it;
// 4: a second SH card; 5: an opaque roof that shadows card 4 only.
transfer_scene make_scene() {
    transfer_scene s;
    s.assets.meshes.push_back(horizontal_quad(60.0f, 0.0f, material_kind::ground));
    s.assets.meshes.push_back(horizontal_quad(1.5f, 1.0f, material_kind::bark));
    s.assets.meshes.push_back(
        with_transfer(horizontal_quad(1.5f, 1.0f, material_kind::bark), 1.0f));
    s.assets.meshes.push_back(
        with_transfer(horizontal_quad(1.5f, 1.0f, material_kind::bark), 0.5f));
    s.assets.meshes.push_back(
        with_transfer(horizontal_quad(1.5f, 1.0f, material_kind::bark), 1.0f));
    s.assets.meshes.push_back(horizontal_quad(2.5f, 6.0f, material_kind::bark));
    // Mesh 6: a leaf card whose front faces down, seen from above on its back face. Nothing
    // reaches its front; its back is unoccluded: lit only if the back transfer is the one used.
    mesh_data leaf = horizontal_quad(1.5f, 1.0f, material_kind::leaf);
    for (vertex& v : leaf.vertices) v.normal = {0.0f, -1.0f, 0.0f};
    leaf.indices = {0, 1, 2, 0, 2, 3};
    leaf.transfer.assign(leaf.vertices.size(), pack_transfer(sh9{}, clamped_cosine({0, 1, 0}, 1.0f)));
    s.assets.meshes.push_back(leaf);
    const lighting_variant lit[] = {lighting_variant::normal_mapped,
                                    lighting_variant::normal_mapped,
                                    lighting_variant::sh,
                                    lighting_variant::sh,
                                    lighting_variant::sh,
                                    lighting_variant::normal_mapped,
                                    lighting_variant::sh};
    for (std::size_t i = 0; i < s.assets.meshes.size(); ++i)
        s.assets.library.meshes.push_back({std::uint32_t(s.assets.meshes[i].triangle_count()),
                                           representation::mesh_full, primitive_kind::triangles,
                                           lit[i]});
    // The cards' species sphere: 1.5 m about their centre, so the roof 5 m up is another object.
    species_entry card;
    card.center_height = 1.0f;
    card.bounding_radius = 2.2f;
    card.transfer_radius = 2.2f;
    card.lighting = lighting_variant::sh;
    s.assets.library.species = {card};
    s.assets.terrain_meshes = {0};
    s.assets.leaf_textures = {solid(60)};
    s.assets.bark_textures = {solid(60)};
    s.assets.ground_texture = solid(60);

    s.cam = testing::looking_down({0.0, 40.0, 0.0}, 50.0f, 256.0f);
    s.light.direction = sun_direction_from_angles(60.0f, 90.0f);  // from the east (+x)
    s.light.color = glm::vec3(1.0f);
    s.light.intensity = 2.0f;
    sky_model model;
    model.sun_direction = s.light.direction;
    model.sky_intensity = 0.3f;  // the sun dominates, so its shadow is plain to see
    const sh9_rgb radiance = project_sky(model, 32, 64);
    const sh9_rgb irradiance = irradiance_from_radiance(radiance);
    for (std::size_t i = 0; i < 9; ++i) {
        s.sky.radiance_sh[i] = radiance.c[i];
        s.sky.irradiance_sh[i] = irradiance.c[i];
    }
    return s;
}

TEST(transfer_lighting, unoccluded_transfer_matches_normal_lighting_and_less_transfer_is_darker) {
    SYLVA_REQUIRE_GL();
    render::context_options options;
    options.width = options.height = 256;
    auto context = render::create_context(options);
    transfer_scene s = make_scene();
    render::renderer_settings settings;
    settings.width = settings.height = 256;
    settings.cascades = 1;
    settings.shadow_resolution = 2048;
    render::renderer renderer(settings, s.assets);

    // Cards at x = -8 (normal), -3 (unoccluded transfer), 2 (half transfer), 8 (in the roof's
    // shadow); the roof 5 m higher and 2.9 m east of the last card, so the sun (60° up in the
    // east) throws its shadow onto that card while the camera, looking straight down, still
    // sees the card's western half.
    // The leaf card seen on its back face at (-3, 6).
    const glm::dvec3 at[] = {{-8, 0, 0}, {-3, 0, 0}, {2, 0, 0}, {8, 0, 0}, {10.9, 0, 0}, {-3, 0, 6}};
    draw_list draws;
    for (const glm::dvec3& p : at) {
        instance_gpu i;
        i.position = glm::vec3(p - s.cam.position);
        draws.instances.push_back(i);
    }
    for (std::uint16_t m = 1; m <= 6; ++m) {
        draws.batches.push_back({render_pass::opaque, m, std::uint32_t(m - 1), 1});
        draws.batches.push_back({render_pass::shadow_cascade_0, m, std::uint32_t(m - 1), 1});
    }
    const cascade_set cascades =
        fit_cascades(s.cam.view, s.cam.fov_y, s.cam.aspect, s.cam.near_plane, 60.0f,
                     s.light.direction, 1, 0.5f, 2048, 50.0f, s.cam.position);
    const image_rgba8 image = render_frame(renderer, s.cam, s.light, s.sky, cascades, draws);

    const float normal_lit = luminance_at(image, s.cam, {-8.0, 1.0, 0.6});
    const float by_transfer = luminance_at(image, s.cam, {-3.0, 1.0, 0.6});
    const float half_transfer = luminance_at(image, s.cam, {2.0, 1.0, 0.6});
    ASSERT_GT(normal_lit, 40.0f);
    ASSERT_LT(normal_lit, 200.0f);  // below the tone curve's shoulder, where darker stays darker
    EXPECT_NEAR(by_transfer, normal_lit, 0.06f * normal_lit);
    EXPECT_LT(half_transfer, 0.85f * by_transfer);
    // The roof, outside the card's 2.2 m sphere, is another object: its shadow darkens the card.
    const float in_roof_shadow = luminance_at(image, s.cam, {7.0, 1.0, 0.6});
    EXPECT_LT(in_roof_shadow, 0.8f * by_transfer);
    // A leaf seen on its back face is lit by its back transfer (gl_FrontFacing), here the
    // unoccluded one: about as bright as the card with unoccluded transfer (its front, which
    // receives nothing, transmits nothing either).
    const float leaf_back = luminance_at(image, s.cam, {-3.0, 1.0, 6.6});
    EXPECT_NEAR(leaf_back, by_transfer, 0.08f * by_transfer);
}

// A crossed billboard's quad seen from behind shows its front image mirrored, so its transfer
// must be mirrored through the quad's plane too: with the sun behind the viewer, the back view
// is lit as the front view is with the sun behind that viewer.
TEST(transfer_lighting, a_billboard_seen_from_behind_is_lit_by_its_mirrored_transfer) {
    SYLVA_REQUIRE_GL();
    render::context_options options;
    options.width = options.height = 128;
    auto context = render::create_context(options);
    scene_assets assets;
    assets.meshes.push_back(horizontal_quad(60.0f, -0.5f, material_kind::ground));
    mesh_data quad;  // the x-y plane, front toward +z, as crossed_billboard's first quad
    quad.vertices = {{{-1, 0, 0}, {0, 0, 1}, {0, 1}}, {{1, 0, 0}, {0, 0, 1}, {1, 1}},
                     {{1, 2, 0}, {0, 0, 1}, {1, 0}}, {{-1, 2, 0}, {0, 0, 1}, {0, 0}}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.submeshes = {{0, 6, material_kind::billboard}};
    assets.meshes.push_back(quad);
    assets.terrain_meshes = {0};
    for (std::size_t i = 0; i < 2; ++i)
        assets.library.meshes.push_back({2, representation::crossed_billboard, primitive_kind::triangles,
                                         i == 0 ? lighting_variant::normal_mapped : lighting_variant::sh});
    species_entry plant;
    plant.lighting = lighting_variant::sh;
    assets.library.species = {plant};
    assets.leaf_textures = assets.bark_textures = assets.billboard_albedo = {solid(60)};
    image_rgba8 normal = solid(128);
    for (std::size_t i = 2; i < normal.texels.size(); i += 4) normal.texels[i] = 255;  // model +z
    assets.billboard_normal = {normal};
    assets.ground_texture = solid(60);
    // The front side's transfer: unoccluded, facing +z; nothing from behind.
    billboard_image image;
    image.albedo = solid(60);
    const sh9 front = clamped_cosine({0, 0, 1}, 1.0f);
    for (std::size_t t = 0; t < 16 * 16; ++t)
        for (std::size_t i = 0; i < k_billboard_transfer_floats; ++i) image.transfer.push_back(i < 9 ? front[i] : 0.0f);
    assets.billboard_transfer = blank_transfer_pages(16, 16);
    blit_transfer(assets.billboard_transfer, image, 0, 0);
    render::renderer_settings settings;
    settings.width = settings.height = 128;
    settings.shadows = false;
    render::renderer renderer(settings, assets);

    environment sky;  // no sky light: the sun alone
    sun light;
    light.color = glm::vec3(1.0f);
    light.intensity = 2.0f;
    auto view_from = [&](double z, float sun_azimuth_deg) {
        camera cam;
        cam.position = {0.0, 1.0, z};
        cam.forward = {0.0f, 0.0f, z > 0.0 ? -1.0f : 1.0f};
        cam.aspect = 1.0f;
        cam.fov_y = glm::radians(30.0f);
        cam.viewport_height_px = 128.0f;
        derive_camera_matrices(cam);
        light.direction = sun_direction_from_angles(10.0f, sun_azimuth_deg);
        const cascade_set cascades{};
        draw_list draws;
        instance_gpu i;
        i.position = glm::vec3(-cam.position);
        draws.instances = {i};
        draws.batches = {{render_pass::opaque, 1, 0, 1}};
        return luminance_at(render_frame(renderer, cam, light, sky, cascades, draws), cam, {0.0, 1.0, 0.0});
    };
    // Azimuth 180 is south (+z), 0 north (-z): each time the sun is behind the viewer.
    const float front_view = view_from(6.0, 180.0f);
    const float back_view = view_from(-6.0, 0.0f);
    ASSERT_GT(front_view, 40.0f);
    EXPECT_NEAR(back_view, front_view, 0.05f * front_view);
}

}  // namespace
}  // namespace sylva
