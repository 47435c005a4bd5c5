#include "systems/render/primitive_cost_calibration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <glm/trigonometric.hpp>
#include <vector>

#include "models/random.h"
#include "systems/update_camera_system.h"

namespace sylva::render {

mesh_data calibration_mesh(primitive_kind kind, std::uint32_t count, float pixel_m, float half_width_m,
                           float half_height_m, double triangle_leg_px) {
    mesh_data mesh;
    mesh.primitive = kind;
    rng random(0xca1b7a7eULL, std::uint64_t(kind));
    const std::uint32_t per =
        kind == primitive_kind::triangles ? 3u : (kind == primitive_kind::lines ? 2u : 1u);
    const float triangle_leg = float(triangle_leg_px) * pixel_m;
    const float line_length = float(k_calibration_line_px) * pixel_m;
    const float edge = kind == primitive_kind::lines ? line_length : triangle_leg;
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::vec3 c{random.uniform(-half_width_m, half_width_m),
                          random.uniform(-half_height_m, half_height_m),
                          random.uniform(-1.0f, 1.0f)};
        const float angle = random.uniform(0.0f, 6.2831853f);
        const glm::vec3 a{std::cos(angle) * edge, std::sin(angle) * edge, 0.0f};
        const glm::vec3 b{-std::sin(angle) * edge, std::cos(angle) * edge, 0.0f};
        const glm::vec3 corners[3] = {c, c + a, c + b};
        for (std::uint32_t v = 0; v < per; ++v) {
            mesh.indices.push_back(std::uint32_t(mesh.vertices.size()));
            mesh.vertices.push_back({corners[v], {0.0f, 0.0f, 1.0f}, {0.5f, 0.5f}});
        }
    }
    mesh.submeshes.push_back({0, std::uint32_t(mesh.indices.size()), material_kind::leaf});
    return mesh;
}

namespace {

primitive_kind kind_of(cost_path path) {
    switch (path) {
        case cost_path::triangles:
            return primitive_kind::triangles;
        case cost_path::native_lines:
        case cost_path::wide_lines:
            return primitive_kind::lines;
        default:
            return primitive_kind::points;
    }
}

double pixels_of(const calibration_point& p) {
    switch (kind_of(p.path)) {
        case primitive_kind::triangles:
            return triangle_pixels();
        case primitive_kind::lines:
            return line_pixels(p.quality);
        case primitive_kind::points:
            break;
    }
    return splat_pixels(p.quality);
}

}  // namespace

std::pair<double, double> median_and_error(std::vector<double> v) {
    if (v.empty()) return {0.0, 0.0};
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    const double median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    std::vector<double> deviation;
    for (const double x : v) deviation.push_back(std::abs(x - median));
    std::sort(deviation.begin(), deviation.end());
    const double mad = n % 2 ? deviation[n / 2] : 0.5 * (deviation[n / 2 - 1] + deviation[n / 2]);
    return {median, 1.2533 * 1.4826 * mad / std::sqrt(double(n))};
}

calibration_scene::calibration_scene(const renderer& r) {
    cam.position = {0.0, 0.0, 0.0};
    cam.forward = {0.0f, 0.0f, -1.0f};
    cam.aspect = float(r.settings().width) / float(r.settings().height);
    cam.viewport_height_px = float(r.settings().height);
    derive_camera_matrices(cam);
    pixel_m = float(image_plane_units(1.0, cam.fov_y, cam.viewport_height_px)) * k_calibration_distance_m;
    half_height_m = 0.3f * std::tan(0.5f * cam.fov_y) * k_calibration_distance_m;
    half_width_m = half_height_m * cam.aspect;
    light.direction = glm::normalize(glm::vec3(0.3f, 0.8f, 0.4f));
    view.view_camera = &cam;
    view.sun_light = &light;
    view.sky = &sky;
    view.cascades = &cascades;
    view.draws = &list;
    view.terrain_position = {0.0f, -1e7f, 0.0f};  // the terrain far out of view
}

marginal_timings time_marginals(const std::vector<std::uint32_t>& count_scales,
                                const std::function<double(std::size_t, std::uint32_t)>& time,
                                const calibration_settings& settings) {
    const std::size_t points = count_scales.size();
    marginal_timings out;
    out.marginal_ms.resize(points);
    for (std::size_t i = 0; i < points; ++i) {
        const std::uint32_t first = std::min(settings.first_count * count_scales[i], settings.max_count / 2);
        std::uint32_t n = first;
        (void)time(i, 2 * n);
        std::vector<double> d;
        for (int k = 0; k < 3; ++k) d.push_back(time(i, 2 * n) - time(i, n));
        std::sort(d.begin(), d.end());
        const double marginal = d[1];
        while (2 * n < settings.max_count && marginal * double(n) / double(first) < settings.min_marginal_ms)
            n *= 2;
        out.counts.push_back(std::min(n, settings.max_count / 2));
    }
    auto settled = [&](std::size_t i) {
        const auto [ms, error] = median_and_error(out.marginal_ms[i]);
        return error <= settings.target_relative_error * ms;
    };
    for (int rep = 0; rep < settings.max_repetitions; ++rep) {
        bool any = false;
        for (std::size_t k = 0; k < points; ++k) {
            const std::size_t i = (k + std::size_t(rep)) % points;
            if (rep >= settings.min_repetitions && settled(i)) continue;
            any = true;
            double t_once = 0.0, t_twice = 0.0;
            if (rep % 2 == 0) {
                t_once = time(i, out.counts[i]);
                t_twice = time(i, 2 * out.counts[i]);
            } else {
                t_twice = time(i, 2 * out.counts[i]);
                t_once = time(i, out.counts[i]);
            }
            out.marginal_ms[i].push_back(t_twice - t_once);
        }
        if (!any) break;
    }
    return out;
}

double wall_clock_ms(const calibration_frame&, const std::function<void()>& draw) {
    const auto start = std::chrono::steady_clock::now();
    draw();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

double process_cpu_ms(const calibration_frame&, const std::function<void()>& draw) {
    timespec before{}, after{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &before);
    draw();
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &after);
    return double(after.tv_sec - before.tv_sec) * 1e3 +
           double(after.tv_nsec - before.tv_nsec) * 1e-6;
}

frame_timer device_frame_timer(const std::string& gl_renderer) {
    const bool cpu = gl_renderer.find("llvmpipe") != std::string::npos ||
                     gl_renderer.find("softpipe") != std::string::npos ||
                     gl_renderer.find("swrast") != std::string::npos;
    return cpu ? frame_timer(process_cpu_ms) : frame_timer(wall_clock_ms);
}

calibration_result calibrate_primitive_costs(renderer& r, const calibration_settings& settings) {
    const auto start = std::chrono::steady_clock::now();
    calibration_scene scene(r);
    const std::uint32_t capacity = std::max(settings.max_count, 2 * settings.first_count);
    std::array<std::uint16_t, 3> meshes{};
    for (const primitive_kind kind :
         {primitive_kind::triangles, primitive_kind::points, primitive_kind::lines})
        meshes[std::size_t(kind)] = r.add_mesh(
            calibration_mesh(kind, capacity, scene.pixel_m, scene.half_width_m, scene.half_height_m));
    // No shadow pass: the view's passes are timed.

    const frame_timer timer = settings.timer ? settings.timer : frame_timer(process_cpu_ms);
    auto time_frame = [&](const calibration_frame& frame) {
        instance_gpu instance;
        instance.position = {0.0f, 0.0f, -k_calibration_distance_m};
        instance.fade = float(frame.count);  // every splat whole (draw_list.h instance_gpu::fade)
        scene.list.instances = {instance};
        scene.list.batches = {
            {render_pass::opaque, meshes[std::size_t(kind_of(frame.path))], 0, 1, frame.count}};
        scene.view.set_samples(frame.quality);
        return timer(frame, [&] {
            r.render(scene.view);
            (void)r.finish();
        });
    };

    const std::vector<calibration_point> plan = calibration_plan(settings.splat_factor);
    std::vector<std::uint32_t> scales;
    for (const calibration_point& p : plan) scales.push_back(p.count_scale);
    const marginal_timings timings = time_marginals(
        scales, [&](std::size_t i, std::uint32_t n) { return time_frame({plan[i].path, plan[i].quality, n}); },
        settings);
    calibration_result result;
    result.counts = timings.counts;
    for (std::size_t i = 0; i < plan.size(); ++i) {
        // The marginal time of one primitive: the median over the repetitions of 2N less N, over N.
        const auto [ms, error] = median_and_error(timings.marginal_ms[i]);
        const double per = 1000.0 / double(timings.counts[i]);
        result.samples.push_back({plan[i].path, pixels_of(plan[i]), ms * per, error * per});
    }
    try {
        try {
            result.model = fit_cost_model(result.samples, settings.splat_factor);
        } catch (const calibration_refused& e) {
            result.refusal = e.what();
        }
    } catch (const calibration_refused& e) {
        result.refusal = e.what();
    }
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace sylva::render
