#include "systems/render/shader_work_calibration.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>


namespace sylva::render {
namespace {

constexpr double k_large_triangle_px = 24.0;
// Legs of 0.4 px: most such triangles cover no sample and, like most leaf triangles of a plant
// in a frame, cost their vertices and little raster set-up.
constexpr double k_tiny_triangle_px = 0.4;
constexpr std::size_t k_shapes = 4;

}  // namespace

work_calibration_result calibrate_shader_work(renderer& r, const calibration_settings& settings) {
    const auto start = std::chrono::steady_clock::now();
    work_calibration_result result;
    calibration_view eye = calibration_view_for(r);
    camera& cam = eye.cam;
    const float pixel_m = eye.pixel_m, half_width = eye.half_width_m, half_height = eye.half_height_m;
    const std::uint32_t capacity = std::max(settings.max_count, 2 * settings.first_count);
    const std::array<std::uint16_t, 3> meshes{
        r.add_mesh(calibration_mesh(primitive_kind::triangles, capacity, pixel_m, half_width, half_height,
                                    k_calibration_triangle_px)),
        r.add_mesh(calibration_mesh(primitive_kind::triangles, capacity, pixel_m, half_width, half_height,
                                    k_large_triangle_px)),
        r.add_mesh(calibration_mesh(primitive_kind::triangles, capacity, pixel_m, half_width, half_height,
                                    k_tiny_triangle_px))};

    sun light;
    light.direction = glm::normalize(glm::vec3(0.3f, 0.8f, 0.4f));
    environment sky;
    // One cascade seeing what the eye sees, so the shadow shape's triangles shade a map the way
    // the view's shade the frame (and the view's fragments look the map up, as a scene's do).
    cascade_set cascades;
    cascades.count = 1;
    // The map's texels as large as the view's pixels, so the shadow shape's triangles shade
    // about as many texels as the view's large ones shade pixels whatever the map's resolution
    // (the camera's own frustum on a 1024 map drew 24 px triangles over 70,000 texels each
    // from a 64-pixel-high view). A map coarser than the view keeps the camera's frustum.
    const float map_px = float(r.settings().shadow_resolution);
    cascades.light_view_projection[0] =
        glm::scale(glm::mat4(1.0f), glm::vec3(std::min(1.0f, float(r.settings().width) / map_px),
                                              std::min(1.0f, float(r.settings().height) / map_px), 1.0f)) *
        cam.projection * cam.view;
    cascades.split_far[0] = 1e4f;
    cascades.texel_world_size[0] = pixel_m;
    draw_list list;
    frame_view view;
    view.view_camera = &cam;
    view.sun_light = &light;
    view.sky = &sky;
    view.cascades = &cascades;
    view.draws = &list;
    view.terrain_position = {0.0f, -1e7f, 0.0f};  // the terrain far out of view
    view.set_samples(point_line_quality{});

    struct shape {
        std::uint16_t mesh;
        render_pass pass;
    };
    const std::array<shape, k_shapes> shapes{
        shape{meshes[0], render_pass::opaque}, shape{meshes[1], render_pass::opaque},
        shape{meshes[1], render_pass::shadow_cascade_0}, shape{meshes[2], render_pass::opaque}};
    const frame_timer timer = settings.timer ? settings.timer : frame_timer(process_cpu_ms);
    struct frame_work {
        double ms = 0.0;
        frame_stats stats;
    };
    auto draw = [&](const shape& s, std::uint32_t count) {
        const auto index = std::uint32_t(&s - shapes.data());
        instance_gpu instance;
        instance.position = {0.0f, 0.0f, -k_calibration_distance_m};
        instance.fade = 1.0f;
        list.instances = {instance};
        list.batches = {{s.pass, s.mesh, 0, 1, count}};
        frame_work w;
        w.ms = timer({cost_path::triangles, point_line_quality{}, count, index}, [&] {
            r.render(view);
            w.stats = r.finish();
        });
        return w;
    };
    {
        const frame_work probe = draw(shapes[0], 1);
        if (!probe.stats.work_counted) {
            result.refusal = "the device does not count shader invocations (ARB_pipeline_statistics_query)";
            return result;
        }
    }
    (void)draw(shapes[2], 1);
    // N per shape as the primitive calibration chooses it: doubled until 2N costs
    // min_marginal_ms more than N.
    std::array<std::uint32_t, k_shapes> counts{};
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        std::uint32_t n = std::min(settings.first_count, settings.max_count / 2);
        (void)draw(shapes[i], 2 * n);
        std::array<double, 3> d{};
        for (double& x : d) x = draw(shapes[i], 2 * n).ms - draw(shapes[i], n).ms;
        std::sort(d.begin(), d.end());
        const double first = double(n);
        while (2 * n < settings.max_count && d[1] * double(n) / first < settings.min_marginal_ms) n *= 2;
        counts[i] = std::min(n, settings.max_count / 2);
    }
    auto sum_view = [](const std::array<std::uint64_t, 4>& pass) {
        double total = 0.0;
        for (std::size_t p = 0; p < pass.size(); ++p)
            if (p != std::size_t(gpu_pass::shadow)) total += double(pass[p]);
        return total;
    };
    std::array<std::vector<double>, k_shapes> marginal_ms;
    std::array<work_sample, k_shapes> added{};
    for (int rep = 0; rep < settings.max_repetitions; ++rep) {
        bool any = false;
        for (std::size_t k = 0; k < shapes.size(); ++k) {
            const std::size_t i = (k + std::size_t(rep)) % shapes.size();
            if (rep >= settings.min_repetitions) {
                const auto [ms, error] = median_and_error(marginal_ms[i]);
                if (error <= settings.target_relative_error * ms) continue;
            }
            any = true;
            frame_work once, twice;
            if (rep % 2 == 0) {
                once = draw(shapes[i], counts[i]);
                twice = draw(shapes[i], 2 * counts[i]);
            } else {
                twice = draw(shapes[i], 2 * counts[i]);
                once = draw(shapes[i], counts[i]);
            }
            marginal_ms[i].push_back(twice.ms - once.ms);
            // The counts are the same every repetition (the device draws the same frames).
            const std::size_t shadow = std::size_t(gpu_pass::shadow);
            work_sample& a = added[i];
            a.vertices = sum_view(twice.stats.pass_vertices) - sum_view(once.stats.pass_vertices) +
                         double(twice.stats.pass_vertices[shadow]) - double(once.stats.pass_vertices[shadow]);
            a.fragments = sum_view(twice.stats.pass_fragments) - sum_view(once.stats.pass_fragments);
            a.shadow_fragments =
                double(twice.stats.pass_fragments[shadow]) - double(once.stats.pass_fragments[shadow]);
        }
        if (!any) break;
    }
    for (std::size_t i = 0; i < shapes.size(); ++i) {
        const auto [ms, error] = median_and_error(marginal_ms[i]);
        work_sample s = added[i];
        s.us = 1000.0 * ms;
        s.error_us = 1000.0 * error;
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
