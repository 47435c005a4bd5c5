// Point samples in the shadow cascades (lod/point_line_lod.h k_shadow_splat_push): a shadow
// splat w wide is moved away from the sun by w along the sun's ray, so it shades what lies more
// than about w behind it, not the leaves just beside or below it. A dense layer of samples,
// drawn into the cascade only, hangs over flat ground in the sun (70° up, from the east) and a
// camera looks straight down: the layer shades the ground when it hangs several widths up,
// and not when it hangs less than one width up. Without the push both would shade it.
//
// Point samples receiving shadows (shaders/shading.glsl SHADOW_SINGLE_TAP): a splat is shaded
// once, at its sample, with one bilinear tap of the shadow map instead of the 3x3-texel filter
// surfaces use, so a shadow's edge across a field of splats ramps over about one texel where
// the ground's ramps over about two.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "flat_scene.h"
#include "gl_test_support.h"
#include "lighting/shadow_cascades.h"
#include "lighting/sky_model.h"
#include "lod/point_line_lod.h"
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

// Flat grey ground, 80 m across (mesh 0, the terrain), then `parts` as meshes 1, 2, ...: triangle
// parts as full meshes, point parts as samples; leaves and bark of grey level `foliage`.
scene_assets ground_and(std::vector<mesh_data> parts, std::uint8_t foliage) {
    scene_assets assets;
    assets.meshes.push_back(horizontal_quad(40.0f, 0.0f, material_kind::ground));
    for (mesh_data& m : parts) assets.meshes.push_back(std::move(m));
    for (const mesh_data& m : assets.meshes) {
        const bool points = m.primitive == primitive_kind::points;
        assets.library.meshes.push_back(
            {std::uint32_t(points ? m.vertices.size() : m.indices.size() / 3),
             points ? representation::points : representation::mesh_full, m.primitive});
    }
    assets.terrain_meshes = {0};
    assets.leaf_textures = {solid(foliage)};
    assets.bark_textures = {solid(foliage)};
    assets.ground_texture = solid(160);
    return assets;
}

// The frame, k_size square, with one shadow cascade of `resolution` texels.
render::renderer_settings one_cascade(int resolution) {
    render::renderer_settings settings;
    settings.width = settings.height = k_size;
    settings.cascades = 1;
    settings.shadow_resolution = resolution;
    return settings;
}

TEST(point_shadow_gl, a_shadow_splat_shades_what_lies_more_than_its_width_behind_it) {
    SYLVA_REQUIRE_GL();
    render::context_options options;
    options.width = options.height = k_size;
    auto context = render::create_context(options);

    // Mesh 1: 1,600 samples over 4 m x 4 m.
    render::renderer renderer(one_cascade(2048), ground_and({point_layer(2.0f, 0.1f)}, 90));

    const camera cam = testing::looking_down({0.0, 30.0, 0.0}, 60.0f, float(k_size));
    // Named members, not a structured binding: clang 14 (the sanitizer builds) cannot capture
    // structured bindings in the lambda below.
    const testing::sunlit sunlight = testing::sun_from_the_east(cam, 70.0f);
    const sun& light = sunlight.light;
    const environment& sky = sunlight.sky;
    const cascade_set& cascades = sunlight.cascades;
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

// Pixels of image row `row` (x from 0 to k_size) strictly inside the ramp from shadow to light:
// more than 10 % of the way from the row's darkest value to its brightest, and less than 90 %.
// `dark_over_lit` receives the darkest over the brightest, to check there is a shadow at all.
int ramp_pixels(const image_rgba8& image, int row, float& dark_over_lit) {
    std::vector<float> luma;
    for (int x = 0; x < k_size; ++x) {
        const std::uint8_t* p = image.at(std::uint32_t(x), std::uint32_t(row));
        luma.push_back(0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]);
    }
    const auto [lo, hi] = std::minmax_element(luma.begin(), luma.end());
    const float dark = *lo, lit = *hi;
    dark_over_lit = dark / lit;
    int inside = 0;
    for (const float v : luma)
        if (v > dark + 0.1f * (lit - dark) && v < lit - 0.1f * (lit - dark)) ++inside;
    return inside;
}

TEST(point_shadow_gl, a_splat_reads_its_shadow_with_one_tap_so_its_shadow_edge_is_sharper) {
    SYLVA_REQUIRE_GL();
    constexpr int k_resolution = 128;  // coarse: a texel spans several pixels
    render::context_options options;
    options.width = options.height = k_size;
    auto context = render::create_context(options);

    // Mesh 1: the occluder; 2: samples far denser than the pixels (0.135 m).
    render::renderer renderer(
        one_cascade(k_resolution),
        ground_and({horizontal_quad(20.0f, 0.0f, material_kind::bark), point_layer(6.0f, 0.04f)},
                   160));

    // The occluder, 5 m up, covers x < 0 and is drawn into the cascade only; the sun, 70° up in
    // the east, puts its shadow's edge at x = -5 / tan 70° on the ground, under the camera.
    const double edge_x = -5.0 / std::tan(70.0 * 3.14159265358979 / 180.0);
    const camera cam = testing::looking_down({edge_x, 30.0, 0.0}, 60.0f, float(k_size));
    // Named members, not a structured binding: clang 14 (the sanitizer builds) cannot capture
    // structured bindings in the lambda below.
    testing::sunlit sunlight = testing::sun_from_the_east(cam, 70.0f);
    const sun& light = sunlight.light;
    const environment& sky = sunlight.sky;
    cascade_set& cascades = sunlight.cascades;
    cascades = fit_cascades(cam.view, cam.fov_y, cam.aspect, cam.near_plane, 60.0f, light.direction,
                            1, 0.5f, k_resolution, 50.0f, cam.position);
    // Several pixels per texel, so each ramp spans several pixels of the row.
    ASSERT_GT(cascades.texel_world_size[0],
              3.0f * float(2.0 * 30.0 * std::tan(glm::radians(30.0)) / k_size));

    auto render_row = [&](bool splats, float& dark_over_lit) {
        draw_list draws;
        instance_gpu occluder;
        occluder.position = glm::vec3(glm::dvec3(-20.0, 5.0, 0.0) - cam.position);
        occluder.fade = 1.0f;
        instance_gpu layer;
        layer.position = glm::vec3(glm::dvec3(edge_x, 0.02, 0.0) - cam.position);
        layer.fade = 1e9f;
        draws.instances = {occluder, layer};
        draws.batches = {{render_pass::shadow_cascade_0, 1, 0, 1}};
        if (splats) draws.batches.push_back({render_pass::opaque, 2, 1, 1});
        render::frame_view view = testing::make_view(cam, light, sky, cascades, draws);
        view.set_samples({1.0f, 1.3f, false, splat_style::opaque, false});
        renderer.render(view);
        renderer.finish();
        return ramp_pixels(renderer.read_color(), k_size / 2, dark_over_lit);
    };
    float ground_contrast = 1.0f, splat_contrast = 1.0f;
    const int ground = render_row(false, ground_contrast);
    const int splat = render_row(true, splat_contrast);
    EXPECT_LT(ground_contrast, 0.8f);  // both show the shadow
    EXPECT_LT(splat_contrast, 0.8f);
    // The ground's four taps ramp over about two texels; the splats' one tap over about one.
    EXPECT_GE(ground, 4);
    EXPECT_LE(splat, ground * 2 / 3)
        << "ground ramp " << ground << " px, splat ramp " << splat << " px";
    std::printf("shadow ramp: ground %d px, splats %d px\n", ground, splat);
}

}  // namespace
}  // namespace sylva
