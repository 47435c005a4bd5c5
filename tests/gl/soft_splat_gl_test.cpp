// Soft splats in the renderer (lod/point_line_lod.h, our extension of Deussen 2002 §5.1):
// each soft splat must deposit the leaf area it stands for, d'²/c_p pixels, so a sparse field of
// them darkens the image 1/c_p² as much as the same field of opaque c_p·d'² splats; and the
// visibility pass must keep splats behind a dense layer from blending over it; the splat layer
// they are drawn in must stay behind whatever lies in front of them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/trigonometric.hpp>

#include "flat_scene.h"
#include "gl_test_support.h"
#include "models/random.h"
#include "lighting/sky_model.h"
#include "lod/point_line_lod.h"
#include "systems/render/renderer.h"
#include "systems/update_camera_system.h"

namespace sylva {
namespace {

using testing::horizontal_quad;
using testing::solid;

constexpr int k_size = 128;

// Leaf samples facing up, on a jittered grid of `spacing` metres over a square of side 2·half.
mesh_data point_field(float half, float spacing, std::uint64_t seed) {
    mesh_data m;
    m.primitive = primitive_kind::points;
    rng random(seed, 1);
    for (float z = -half; z < half; z += spacing)
        for (float x = -half; x < half; x += spacing) {
            const glm::vec3 p{x + random.uniform(0.0f, 0.5f * spacing), 0.0f,
                              z + random.uniform(0.0f, 0.5f * spacing)};
            m.indices.push_back(std::uint32_t(m.vertices.size()));
            m.vertices.push_back({p, {0.0f, 1.0f, 0.0f}, {0.5f, 0.5f}});
        }
    m.submeshes = {{0, std::uint32_t(m.indices.size()), material_kind::leaf}};
    m.bounds_min = {-half, 0.0f, -half};
    m.bounds_max = {half, 0.0f, half};
    return m;
}

struct splat_scene {
    scene_assets assets;
    camera cam;
    sun light;
    environment sky;
};

// Mesh 0: dark ground; 1: a sparse field (1 m apart on a jittered grid, about 3.5 px at 39 m:
// the soft splats' Gaussian tails touch at most); 2: a dense field (7 cm apart, about 15
// samples per pixel).
splat_scene make_scene() {
    splat_scene s;
    s.assets.meshes.push_back(horizontal_quad(60.0f, 0.0f, material_kind::ground));
    s.assets.meshes.push_back(point_field(6.0f, 1.0f, 7));
    s.assets.meshes.push_back(point_field(2.0f, 0.07f, 8));
    s.assets.library.meshes.push_back({2, representation::mesh_full, primitive_kind::triangles});
    for (std::size_t i = 1; i < s.assets.meshes.size(); ++i)
        s.assets.library.meshes.push_back({std::uint32_t(s.assets.meshes[i].vertices.size()),
                                           representation::points, primitive_kind::points});
    s.assets.terrain_meshes = {0};
    s.assets.leaf_textures = {solid(140)};
    s.assets.bark_textures = {solid(140)};
    s.assets.ground_texture = solid(20);

    s.cam = testing::looking_down({0.0, 40.0, 0.0}, 50.0f, float(k_size));
    s.light.direction = sun_direction_from_angles(70.0f, 90.0f);
    s.light.color = glm::vec3(1.0f);
    s.light.intensity = 2.0f;
    return s;
}

struct placed {
    glm::dvec3 position{0.0};
    float tint = 0.0f;
    float fade = 1e9f;  // the prefix's fractional length (draw_list.h): every splat whole
};

// One frame of `instances` of `mesh` (the first `count` splats of each; 0: all), with soft or
// opaque splats at d' = `sample_distance_px` (1 px by default), c_p = 1.3, grown by
// `sample_fog` (frame_view::sample_fog); no
// shadows. Returns the image's luma.
std::vector<float> render_luma(render::renderer& renderer, const splat_scene& s, std::uint16_t mesh,
                               const std::vector<placed>& instances, splat_style style,
                               std::uint32_t count = 0, float sample_fog = 0.0f,
                               float sample_distance_px = 1.0f) {
    draw_list draws;
    for (const placed& p : instances) {
        instance_gpu i;
        i.position = glm::vec3(p.position - s.cam.position);
        i.tint = p.tint;
        i.fade = p.fade;
        draws.instances.push_back(i);
    }
    if (!instances.empty())
        draws.batches.push_back(
            {render_pass::opaque, mesh, 0, std::uint32_t(instances.size()), count});
    const cascade_set cascades;
    render::frame_view view = testing::make_view(s.cam, s.light, s.sky, cascades, draws);
    view.set_samples({sample_distance_px, 1.3f, true, style, false});
    view.sample_fog = sample_fog;
    renderer.render(view);
    renderer.finish();
    const image_rgba8 image = renderer.read_color();
    std::vector<float> luma;
    for (std::size_t i = 0; i + 3 < image.texels.size(); i += 4)
        luma.push_back(0.2126f * image.texels[i] + 0.7152f * image.texels[i + 1] +
                       0.0722f * image.texels[i + 2]);
    return luma;
}

double summed_difference(const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += double(a[i]) - double(b[i]);
    return sum;
}

double window_mean(const std::vector<float>& luma, int half) {
    double sum = 0.0;
    for (int y = k_size / 2 - half; y < k_size / 2 + half; ++y)
        for (int x = k_size / 2 - half; x < k_size / 2 + half; ++x)
            sum += luma[std::size_t(y * k_size + x)];
    return sum / double(4 * half * half);
}

struct gl_fixture {
    gl_fixture() : context(create()), renderer(settings(), scene.assets) {}
    static std::unique_ptr<render::gl_context> create() {
        render::context_options options;
        options.width = options.height = k_size;
        return render::create_context(options);
    }
    static render::renderer_settings settings() {
        render::renderer_settings r;
        r.width = r.height = k_size;
        r.shadows = false;
        return r;
    }
    splat_scene scene = make_scene();
    std::unique_ptr<render::gl_context> context;
    render::renderer renderer;
};

TEST(soft_splat_gl, a_soft_splat_deposits_one_over_c_p_squared_of_an_opaque_splats_coverage) {
    SYLVA_REQUIRE_GL();
    gl_fixture f;
    const auto empty = render_luma(f.renderer, f.scene, 1, {}, splat_style::soft);
    const auto opaque =
        render_luma(f.renderer, f.scene, 1, {{{0.0, 1.0, 0.0}}}, splat_style::opaque);
    const auto soft = render_luma(f.renderer, f.scene, 1, {{{0.0, 1.0, 0.0}}}, splat_style::soft);
    // Each of the 144 opaque splats covers c_p·d'² = 1.3 pixels on average with the sample's
    // colour; each soft one deposits d'²/c_p = 0.77 pixels of it: the ratio is 1/c_p² = 0.592.
    const double opaque_sum = summed_difference(opaque, empty);
    ASSERT_GT(opaque_sum, 144 * 1.3 * 30.0);  // the samples are clearly brighter than the ground
    EXPECT_NEAR(summed_difference(soft, empty) / opaque_sum, 1.0 / (1.3 * 1.3), 0.06);
}

TEST(soft_splat_gl, splats_behind_a_dense_layer_do_not_blend_over_it) {
    SYLVA_REQUIRE_GL();
    gl_fixture f;
    // A darker layer 3 m up (tint -1) drawn first, a brighter one 1 m up (tint +1) after it: a
    // blend without the visibility pass would lay the far layer over the near one.
    const float near_tint = -1.0f, far_tint = 1.0f;
    const double near_only = window_mean(
        render_luma(f.renderer, f.scene, 2, {{{0.0, 3.0, 0.0}, near_tint}}, splat_style::soft), 8);
    const double far_only = window_mean(
        render_luma(f.renderer, f.scene, 2, {{{0.0, 1.0, 0.0}, far_tint}}, splat_style::soft), 8);
    const double both = window_mean(
        render_luma(f.renderer, f.scene, 2,
                    {{{0.0, 3.0, 0.0}, near_tint}, {{0.0, 1.0, 0.0}, far_tint}}, splat_style::soft),
        8);
    ASSERT_GT(far_only, near_only + 15.0);
    // The far layer shows only through the near layer's gaps: about 15 samples per pixel, so
    // its opaque visibility splats (1.3 px each) leave almost no pixel uncovered.
    EXPECT_LT(both - near_only, 0.15 * (far_only - near_only));
}

// A fractional prefix (point_prefix::last_fade): an instance whose fade is 2.5 draws its first
// two splats whole and the third at half opacity, half-way between fades of 2 and 3. One such
// prefix per instance, on a 10 x 10 grid 1.5 m apart.
TEST(soft_splat_gl, a_fractional_prefix_draws_its_last_splat_at_the_fraction) {
    SYLVA_REQUIRE_GL();
    gl_fixture f;
    auto grid = [](float fade) {
        std::vector<placed> instances;
        for (int z = 0; z < 10; ++z)
            for (int x = 0; x < 10; ++x)
                instances.push_back({{1.5 * (x - 4.5), 1.0, 1.5 * (z - 4.5)}, 0.0f, fade});
        return instances;
    };
    const auto empty = render_luma(f.renderer, f.scene, 1, {}, splat_style::soft);
    auto deposit = [&](float fade) {
        return summed_difference(
            render_luma(f.renderer, f.scene, 1, grid(fade), splat_style::soft, 3), empty);
    };
    const double two = deposit(2.0f), two_and_a_half = deposit(2.5f), three = deposit(3.0f);
    ASSERT_GT(three, 300 * 0.77 * 30.0);  // 300 splats of 0.77 px, clearly brighter than the ground
    // The splats land at different sub-pixel positions, so each deposits a slightly different
    // amount: compare with the whole prefixes on either side.
    EXPECT_LT(two, 0.8 * three);
    EXPECT_NEAR(two_and_a_half, 0.5 * (two + three), 0.04 * three);
}

// Fog-weighted sampling (point_line_lod.h fog_sample_distance): a prefix counted with samples
// d'·exp(ρ·r/2) apart is drawn with splats grown by the same factor, from each splat's own
// distance. The sparse field 39 m below the eye with ρ = 0.02 (fifty times the scene fog, for a
// clear factor): every splat grows exp(0.01·39) = 1.477 times, its area 2.18 times.
TEST(soft_splat_gl, fogged_splats_grow_as_their_samples_were_spaced) {
    SYLVA_REQUIRE_GL();
    gl_fixture f;
    const auto empty = render_luma(f.renderer, f.scene, 1, {}, splat_style::opaque);
    const std::vector<placed> field{{{0.0, 1.0, 0.0}}};
    const double plain =
        summed_difference(render_luma(f.renderer, f.scene, 1, field, splat_style::opaque), empty);
    const double grown = summed_difference(
        render_luma(f.renderer, f.scene, 1, field, splat_style::opaque, 0, 0.02f), empty);
    ASSERT_GT(plain, 144 * 1.3 * 30.0);
    EXPECT_NEAR(grown / plain, std::exp(0.02 * 39.0), 0.25);
}

// The splat layer (systems/render/splat_layer.h, splats of 4 px and more) is drawn over the
// frame at its splats' depth:
// a surface in front of the splats hides them pixel by pixel, and the ID buffer names the
// splats' plant where they show and keeps the surface's own where it hides them. A dense field
// 1 m up, 4 m around the centre, under an opaque square 3 m up, 1.5 m around it (about ±5.6 px
// at 37 m from the eye, 0.27 m a pixel).
TEST(soft_splat_gl, a_surface_in_front_of_the_splat_layer_hides_it) {
    SYLVA_REQUIRE_GL();
    splat_scene scene = make_scene();
    scene.assets.meshes.push_back(point_field(4.0f, 0.1f, 9));
    scene.assets.library.meshes.push_back(
        {std::uint32_t(scene.assets.meshes.back().vertices.size()), representation::points,
         primitive_kind::points});
    const auto field = std::uint16_t(scene.assets.meshes.size() - 1);
    scene.assets.meshes.push_back(horizontal_quad(1.5f, 3.0f, material_kind::ground));
    scene.assets.library.meshes.push_back(
        {2, representation::mesh_full, primitive_kind::triangles});
    scene.assets.terrain_meshes.push_back(std::uint16_t(scene.assets.meshes.size() - 1));
    const auto context = gl_fixture::create();
    render::renderer_settings settings = gl_fixture::settings();
    settings.id_buffer = true;
    render::renderer renderer(settings, scene.assets);

    // d' = 2 px: soft splats 4.6 px wide, drawn through the layer (k_splat_layer_min_side_px).
    ASSERT_GE(2.0f * 2.0f * std::sqrt(1.3f), k_splat_layer_min_side_px);
    const auto without = render_luma(renderer, scene, field, {}, splat_style::soft, 0, 0.0f, 2.0f);
    const auto with =
        render_luma(renderer, scene, field, {{{0.0, 1.0, 0.0}}}, splat_style::soft, 0, 0.0f, 2.0f);
    const std::vector<std::uint32_t> ids = renderer.read_ids();
    auto at = [](int x, int y) { return std::size_t(y * k_size + x); };
    const int c = k_size / 2;
    // Beside the square (2.7 to 3.5 m from the centre): the splats, brighter than the ground,
    // all named by their one instance.
    const std::uint32_t splat_id = ids[at(c - 12, c)];
    EXPECT_NE(splat_id, 0u);
    for (const int x : {c - 13, c - 11, c + 10, c + 12}) {
        EXPECT_GT(with[at(x, c)], without[at(x, c)] + 20.0f) << x;
        EXPECT_EQ(ids[at(x, c)], splat_id) << x;
    }
    // Under the square: the frame as it was, to the last bit, and the square's own ID (the
    // frame numbers its instances anew when the splats join, so IDs are compared within it).
    for (int y = c - 3; y < c + 3; ++y)
        for (int x = c - 3; x < c + 3; ++x) {
            EXPECT_EQ(with[at(x, y)], without[at(x, y)]) << x << ", " << y;
            EXPECT_NE(ids[at(x, y)], splat_id) << x << ", " << y;
        }
}

// The layer's IDs: a pixel gets the splats' plant only where a visibility splat lies under it.
// Where only a Gaussian shows (the soft splats are twice as wide as the visibility splats, and
// only every second one has a visibility splat at all) the pixel keeps the ID of the surface
// behind, as with splats drawn straight into the frame. A sparse field 1 m up over an opaque
// plant square 0.5 m up, 6 m around the centre, at d' = 2 px through the layer.
TEST(soft_splat_gl, the_splat_layer_names_its_plant_only_under_visibility_splats) {
    SYLVA_REQUIRE_GL();
    splat_scene scene = make_scene();  // mesh 1: the sparse field
    scene.assets.meshes.push_back(horizontal_quad(6.0f, 0.5f, material_kind::bark));
    scene.assets.library.meshes.push_back(
        {2, representation::mesh_full, primitive_kind::triangles});
    const auto square = std::uint16_t(scene.assets.meshes.size() - 1);
    const auto context = gl_fixture::create();
    render::renderer_settings settings = gl_fixture::settings();
    settings.id_buffer = true;
    render::renderer renderer(settings, scene.assets);

    auto render = [&](bool splats) {
        draw_list draws;
        instance_gpu plant;
        plant.position = glm::vec3(-scene.cam.position);
        plant.fade = 1.0f;
        instance_gpu field;
        field.position = glm::vec3(glm::dvec3(0.0, 1.0, 0.0) - scene.cam.position);
        field.fade = 1e9f;
        draws.instances = {plant, field};
        draws.batches = {{render_pass::opaque, square, 0, 1, 0}};
        if (splats) draws.batches.push_back({render_pass::opaque, 1, 1, 1, 0});
        const cascade_set cascades;
        render::frame_view view =
            testing::make_view(scene.cam, scene.light, scene.sky, cascades, draws);
        view.set_samples({2.0f, 1.3f, true, splat_style::soft, false});
        renderer.render(view);
        renderer.finish();
        return std::make_pair(renderer.read_color(), renderer.read_ids());
    };
    const auto [without, square_ids] = render(false);
    const auto [with, ids] = render(true);
    const std::uint32_t square_id = square_ids[std::size_t(k_size / 2 * k_size + k_size / 2)];
    ASSERT_NE(square_id, 0u);
    // The square's image, 4 px in from its edges (6 m at 39 m from the eye: about ±20 px).
    int splat_pixels = 0, halo_pixels = 0;
    for (int y = k_size / 2 - 16; y < k_size / 2 + 16; ++y)
        for (int x = k_size / 2 - 16; x < k_size / 2 + 16; ++x) {
            const std::size_t i = std::size_t(y * k_size + x);
            ASSERT_EQ(square_ids[i], square_id) << x << ", " << y;
            EXPECT_NE(ids[i], 0u) << x << ", " << y;  // never "nothing drawn" over the square
            const bool changed =
                std::memcmp(with.at(std::uint32_t(x), std::uint32_t(y)),
                            without.at(std::uint32_t(x), std::uint32_t(y)), 3) != 0;
            if (ids[i] != square_id) {
                ++splat_pixels;
            } else if (changed) {
                ++halo_pixels;
            }
        }
    std::printf("splat layer IDs: %d pixels name the field, %d show it but keep the square's\n",
                splat_pixels, halo_pixels);
    EXPECT_GT(splat_pixels, 20);  // the visibility splats name the field's plant
    EXPECT_GT(halo_pixels, 20);   // and the Gaussians show beyond them, over the square's ID
}

}  // namespace
}  // namespace sylva
