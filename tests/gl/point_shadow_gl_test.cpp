// Point samples in the shadow cascades (systems/point_line_lod.h k_shadow_splat_push): a shadow
// splat w wide is moved away from the sun by w along the sun's ray, so it shades what lies more
// than about w behind it, not the leaves just beside or below it. A dense layer of samples,
// drawn into the cascade only, hangs over flat ground in the sun (70° up, from the east) and a
// camera looks straight down: the layer shades the ground when it hangs several widths up,
// and not when it hangs less than one width up. Without the push both would shade it.
#include <gtest/gtest.h>

#include "flat_scene.h"
#include "gl_test_support.h"
#include "systems/lighting/sky_model.h"
#include "systems/point_line_lod.h"
#include "systems/render/renderer.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

using testing::horizontal_quad;
using testing::luminance_at;
using testing::solid;

constexpr int k_size = 256;

// Samples facing up every `spacing` metres over a square of side 2·half at height 0.
mesh_data point_layer(float half, float spacing) {
    mesh_data m;
    m.primitive = primitive_kind::points;
    for (float z = -half; z < half; z += spacing)
        for (float x = -half; x < half; x += spacing) {
            m.indices.push_back(std::uint32_t(m.vertices.size()));
            m.vertices.push_back({{x, 0.0f, z}, {0.0f, 1.0f, 0.0f}, {0.5f, 0.5f}});
        }
    m.submeshes = {{0, std::uint32_t(m.indices.size()), material_kind::leaf}};
    m.bounds_min = {-half, 0.0f, -half};
    m.bounds_max = {half, 0.0f, half};
    return m;
}

TEST(point_shadow_gl, a_shadow_splat_shades_what_lies_more_than_its_width_behind_it) {
    SYLVA_REQUIRE_GL();
    render::context_options options;
    options.width = options.height = k_size;
    auto context = render::create_context(options);

    scene_assets assets;
    assets.meshes.push_back(horizontal_quad(40.0f, 0.0f, material_kind::ground));
    assets.meshes.push_back(point_layer(2.0f, 0.1f));  // 1,600 samples over 4 m x 4 m
    assets.library.meshes.push_back({2, representation::mesh_full, primitive_kind::triangles});
    assets.library.meshes.push_back({std::uint32_t(assets.meshes[1].vertices.size()),
                                     representation::points, primitive_kind::points});
    assets.terrain_meshes = {0};
    assets.leaf_textures = {solid(90)};
    assets.bark_textures = {solid(90)};
    assets.ground_texture = solid(160);
    render::renderer_settings settings;
    settings.width = settings.height = k_size;
    settings.cascades = 1;
    settings.shadow_resolution = 2048;
    render::renderer renderer(settings, assets);

    const camera cam = testing::looking_down({0.0, 30.0, 0.0}, 60.0f, float(k_size));
    const auto [light, sky, cascades] = testing::sun_from_the_east(cam, 70.0f);
    // d' = 8 px: casters k_shadow_sample_spacing·d' apart and as wide, 2·8·(2·tan 30°/256)
    // = 0.072 on the image plane, about 2 m at 28-30 m from the eye: far wider than two texels.
    const point_line_quality quality{8.0f, 1.3f, false, splat_style::opaque};
    const double width_m =
        k_shadow_sample_spacing * image_plane_units(8.0, cam.fov_y, k_size) * 28.0;
    ASSERT_GT(width_m, 1.9);

    auto ground_luma = [&](double height_m, glm::dvec3 at) {
        draw_list draws;
        instance_gpu layer;
        layer.position = glm::vec3(glm::dvec3(0.0, height_m, 0.0) - cam.position);
        layer.fade = 1e9f;
        draws.instances = {layer};
        if (height_m > 0.0) draws.batches = {{render_pass::shadow_cascade_0, 1, 0, 1}};
        render::frame_view view = testing::make_view(cam, light, sky, cascades, draws);
        view.set_samples(quality);
        renderer.render(view);
        renderer.finish();
        return luminance_at(renderer.read_color(), cam, at);
    };
    // A layer h up shades the ground h / tan 70° to the west (-x) of the point below it.
    const double tan_elevation = std::tan(70.0 * 3.14159265358979 / 180.0);
    const double high = 4.0 * width_m, low = 0.3 * width_m;
    const glm::dvec3 under_high{-high / tan_elevation, 0.0, 0.0},
        under_low{-low / tan_elevation, 0.0, 0.0};
    const float open_high = ground_luma(0.0, under_high), open_low = ground_luma(0.0, under_low);
    // Several widths up, pushed back by one it is still above the ground: a shadow.
    EXPECT_LT(ground_luma(high, under_high), 0.75f * open_high);
    // A third of a width up, pushed back by one it is below the ground it would shade: none.
    EXPECT_GT(ground_luma(low, under_low), 0.95f * open_low);
}

}  // namespace
}  // namespace sylva
