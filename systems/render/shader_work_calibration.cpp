#include "systems/render/shader_work_calibration.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>

namespace sylva::render {
namespace {

constexpr double k_large_triangle_px = 24.0;
// Legs of 0.4 px: most such triangles cover no sample and, like most leaf triangles of a plant
// in a frame, cost their vertices and little raster set-up.
constexpr double k_tiny_triangle_px = 0.4;
constexpr std::size_t k_shapes = 4;
// The meshes' triangle legs: small, large, tiny.
constexpr std::array<double, 3> k_legs_px{k_calibration_triangle_px, k_large_triangle_px, k_tiny_triangle_px};

}  // namespace

work_calibration_result calibrate_shader_work(renderer& r, const calibration_settings& settings) {
    const auto start = std::chrono::steady_clock::now();
    work_calibration_result result;
    if (!r.settings().shadows) {
        result.refusal = "the renderer draws no shadow map to time the shadow shape in";
        return result;
    }
    calibration_scene scene(r);
    const std::uint32_t capacity = std::max(settings.max_count, 2 * settings.first_count);
    std::array<std::uint16_t, 3> meshes{};
    for (std::size_t m = 0; m < meshes.size(); ++m)
        meshes[m] = r.add_mesh(calibration_mesh(primitive_kind::triangles, capacity, scene.pixel_m,
                                                scene.half_width_m, scene.half_height_m, k_legs_px[m]));
    // One cascade seeing what the eye sees, so the shadow shape's triangles shade a map the way
    // the view's shade the frame (and the view's fragments look the map up, as a scene's do).
    // The map's texels as large as the view's pixels, so the shadow shape's triangles shade
    // about as many texels as the view's large ones shade pixels whatever the map's resolution
    // (the camera's own frustum on a 1024 map drew 24 px triangles over 70,000 texels each
    // from a 64-pixel-high view). A map coarser than the view keeps the camera's frustum.
    const float map_px = float(r.settings().shadow_resolution);
    scene.cascades.count = 1;
    scene.cascades.light_view_projection[0] =
        glm::scale(glm::mat4(1.0f), glm::vec3(std::min(1.0f, float(r.settings().width) / map_px),
                                              std::min(1.0f, float(r.settings().height) / map_px), 1.0f)) *
        scene.cam.projection * scene.cam.view;
    scene.cascades.split_far[0] = 1e4f;
    scene.cascades.texel_world_size[0] = scene.pixel_m;
    scene.view.set_samples(point_line_quality{});

    struct shape {
        std::uint16_t mesh;
        render_pass pass;
    };
    const std::array<shape, k_shapes> shapes{
        shape{meshes[0], render_pass::opaque}, shape{meshes[1], render_pass::opaque},
        shape{meshes[1], render_pass::shadow_cascade_0}, shape{meshes[2], render_pass::opaque}};
    const frame_timer timer = settings.timer ? settings.timer : frame_timer(process_cpu_ms);
    // The device's counts of the last frame drawn of each shape with each N (the same frames
    // give the same counts every time).
    std::array<std::map<std::uint32_t, frame_stats>, k_shapes> counted;
    auto draw = [&](std::size_t i, std::uint32_t count) {
        instance_gpu instance;
        instance.position = {0.0f, 0.0f, -k_calibration_distance_m};
        instance.fade = 1.0f;
        scene.list.instances = {instance};
        scene.list.batches = {{shapes[i].pass, shapes[i].mesh, 0, 1, count}};
        frame_stats stats;
        const double ms = timer({cost_path::triangles, point_line_quality{}, count, std::uint32_t(i)}, [&] {
            r.render(scene.view);
            stats = r.finish();
        });
        counted[i][count] = stats;
        return ms;
    };
    (void)draw(0, 1);
    if (!counted[0][1].work_counted) {
        result.refusal = "the device does not count shader invocations (ARB_pipeline_statistics_query)";
        return result;
    }
    (void)draw(2, 1);
    const marginal_timings timings = time_marginals(std::vector<std::uint32_t>(k_shapes, 1u), draw, settings);
    const auto view_sum = [](const decltype(frame_stats::pass_vertices)& pass) {
        double total = 0.0;
        for (std::size_t p = 0; p < pass.size(); ++p)
            if (p != std::size_t(gpu_pass::shadow)) total += double(pass[p]);
        return total;
    };
    constexpr std::size_t shadow = std::size_t(gpu_pass::shadow);
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const frame_stats& once = counted[i].at(timings.counts[i]);
        const frame_stats& twice = counted[i].at(2 * timings.counts[i]);
        const auto [ms, error] = median_and_error(timings.marginal_ms[i]);
        work_sample s;
        s.us = 1000.0 * ms;
        s.error_us = 1000.0 * error;
        s.vertices = view_sum(twice.pass_vertices) - view_sum(once.pass_vertices) +
                     double(twice.pass_vertices[shadow]) - double(once.pass_vertices[shadow]);
        s.fragments = view_sum(twice.pass_fragments) - view_sum(once.pass_fragments);
        s.shadow_fragments = double(twice.pass_fragments[shadow]) - double(once.pass_fragments[shadow]);
        result.samples.push_back(s);
    }
    try {
        result.costs = fit_shader_work(result.samples);
    } catch (const work_calibration_refused& e) {
        result.refusal = e.what();
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace sylva::render
