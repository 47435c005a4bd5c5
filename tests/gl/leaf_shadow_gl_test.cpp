// Alpha-tested leaves cast leaf-shaped shadows: a card whose texture is opaque on its western
// half and transparent on its eastern half hangs 5 m above flat ground, with the sun 45° up in
// the east. The ground must be dark under the opaque half's shadow and lit under the
// transparent half's, as seen by a camera looking straight down.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "flat_scene.h"
#include "gl_test_support.h"
#include "lighting/sky_model.h"
#include "systems/render/renderer.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

using testing::horizontal_quad;
using testing::luminance_at;
using testing::render_frame;
using testing::solid;

// Opaque where u < 0.5 (west, -x), fully transparent where u >= 0.5.
image_rgba8 half_transparent_leaf() {
    image_rgba8 image = solid(90);
    for (std::uint32_t y = 0; y < 16; ++y)
        for (std::uint32_t x = 8; x < 16; ++x) image.at(x, y)[3] = 0;
    return image;
}

TEST(leaf_shadows, alpha_tested_leaves_cast_shadows_shaped_by_their_texture) {
    SYLVA_REQUIRE_GL();
    render::context_options options;
    options.width = 256;
    options.height = 256;
    auto context = render::create_context(options);

    scene_assets assets;
    assets.meshes.push_back(horizontal_quad(40.0f, 0.0f, material_kind::ground));
    assets.meshes.push_back(horizontal_quad(2.0f, 5.0f, material_kind::leaf));
    assets.terrain_meshes = {0};
    assets.leaf_textures = {half_transparent_leaf()};
    assets.bark_textures = {solid(100)};
    assets.ground_texture = solid(160);
    render::renderer_settings settings;
    settings.width = settings.height = 256;
    settings.cascades = 1;
    settings.shadow_resolution = 2048;
    render::renderer renderer(settings, assets);

    const camera cam = testing::looking_down({-5.0, 30.0, 0.0}, 60.0f, 256.0f);
    const auto [light, sky, cascades] = testing::sun_from_the_east(cam, 45.0f);
    draw_list draws;
    instance_gpu leaf;
    leaf.position = glm::vec3(glm::dvec3(0.0) - cam.position);
    draws.instances = {leaf};
    draws.batches = {{render_pass::opaque, 1, 0, 1}, {render_pass::shadow_cascade_0, 1, 0, 1}};

    const image_rgba8 image = render_frame(renderer, cam, light, sky, cascades, draws);

    // The card's shadow falls 5 m west (-x): x in [-7, -3], its opaque half's in [-7, -5].
    const float open_ground = luminance_at(image, cam, {-12.0, 0.0, 0.0});
    const float under_opaque_half = luminance_at(image, cam, {-6.0, 0.0, 0.0});
    const float under_transparent_half = luminance_at(image, cam, {-4.0, 0.0, 0.0});
    EXPECT_LT(under_opaque_half, 0.75f * open_ground);
    EXPECT_GT(under_transparent_half, 0.95f * open_ground);
    // And the same card without its shadow pass batch casts nothing.
    draws.batches = {{render_pass::opaque, 1, 0, 1}};
    EXPECT_GT(luminance_at(render_frame(renderer, cam, light, sky, cascades, draws), cam, {-6.0, 0.0, 0.0}),
              0.95f * open_ground);
}

}  // namespace
}  // namespace sylva
