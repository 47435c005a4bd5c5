// The point/line representation (Deussen 2002) drawn by the GL renderer: at a tiny sample
// distance every part is polygonal and the image is the full-mesh image; at a few pixels the
// plants become points and lines that still cover about the same pixels in about the same
// colours, and the ID buffer names them.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/scenario_player.h"
#include "gl_test_support.h"
#include "measure/image_metrics.h"
#include "measure/temporal_metrics.h"
#include "scenarios/scenario_loader.h"
#include "tests/tiny_scene.h"

namespace sylva {
namespace {

scenario tiny() {
    return testing::tiny_with_mesh_levels();
}

player_options points_lines(float sample_distance_px) {
    player_options options;
    options.id_buffer = true;
    options.policy.mode = lod_policy::kind::points_lines;
    options.policy.points = {sample_distance_px, 1.3f};
    options.measure_costs = false;  // the paper's costs: the same selection on every machine
    return options;
}

struct rendered {
    image_rgba8 image;
    std::vector<std::uint8_t> mask;
    frame_record record;
};

rendered render_frame(player_options options) {
    scenario_player player(tiny(), 2, testing::shared_gl_context(), nullptr, options);
    player.set_frame(1);
    rendered r;
    r.record = player.step();
    r.image = player.capture();
    r.mask = plant_mask(player.capture_plant_ids());
    return r;
}

TEST(point_line_gl, at_a_tiny_sample_distance_every_part_is_polygonal_and_matches_the_full_mesh) {
    SYLVA_REQUIRE_GL();
    player_options full(geometry_mode::full);
    full.id_buffer = true;
    const rendered mesh = render_frame(full);
    const rendered polygons = render_frame(points_lines(0.05f));
    EXPECT_EQ(polygons.record.points, 0u);
    EXPECT_EQ(polygons.record.lines, 0u);
    // Every triangle but the zero-area ones the bake drops.
    EXPECT_LE(polygons.record.triangles, mesh.record.triangles);
    EXPECT_GE(double(polygons.record.triangles), 0.99 * double(mesh.record.triangles));
    // The same triangles in another order: identical but for ties in depth.
    EXPECT_GT(psnr_db(mesh.image, polygons.image), 40.0);
    EXPECT_GT(coverage_iou(mesh.mask, polygons.mask), 0.97);
}

TEST(point_line_gl, at_a_few_pixels_plants_become_points_and_lines_covering_the_same_pixels) {
    SYLVA_REQUIRE_GL();
    player_options full(geometry_mode::full);
    full.id_buffer = true;
    const rendered mesh = render_frame(full);
    const rendered samples = render_frame(points_lines(2.0f));
    EXPECT_GT(samples.record.points, 0u);
    EXPECT_GT(samples.record.lines, 0u);
    EXPECT_LT(samples.record.triangles, mesh.record.triangles / 4);
    EXPECT_GT(coverage_iou(mesh.mask, samples.mask), 0.6);
    EXPECT_GT(psnr_db(mesh.image, samples.image), 20.0);
}

}  // namespace
}  // namespace sylva
