#include "systems/render/primitive_cost_calibration.h"

#include <algorithm>
#include <cmath>
#include <glm/trigonometric.hpp>
#include <vector>

#include "models/random.h"
#include "systems/update_camera_system.h"

namespace sylva::render {
namespace {

constexpr float k_distance_m = 20.0f;  // where the calibration primitives float, in front of the eye

// `count` primitives of one kind scattered over the middle of the view at k_distance_m, as leaf
// samples (the leaf texture's opaque centre), facing the eye.
mesh_data calibration_mesh(primitive_kind kind, std::uint32_t count, float pixel_m, float triangle_px,
                           float half_width_m, float half_height_m) {
    mesh_data mesh;
    mesh.primitive = kind;
    rng random(0xca1b7a7eULL, std::uint64_t(kind));
    const std::uint32_t per = kind == primitive_kind::triangles ? 3u : (kind == primitive_kind::lines ? 2u : 1u);
    const float edge = triangle_px * pixel_m;
    for (std::uint32_t i = 0; i < count; ++i) {
        const glm::vec3 c{random.uniform(-half_width_m, half_width_m), random.uniform(-half_height_m, half_height_m),
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

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

double quantize_cost_ratio(double ratio) {
    if (!std::isfinite(ratio) || ratio <= 0.0) return 1.0;
    return std::clamp(std::round(ratio * 4.0) / 4.0, 0.25, 64.0);
}

calibration_result calibrate_primitive_costs(renderer& r, const calibration_settings& settings) {
    camera cam;
    cam.position = {0.0, 0.0, 0.0};
    cam.forward = {0.0f, 0.0f, -1.0f};
    cam.aspect = float(r.settings().width) / float(r.settings().height);
    cam.viewport_height_px = float(r.settings().height);
    derive_camera_matrices(cam);
    const auto pixel_m = float(image_plane_units(1.0, cam.fov_y, cam.viewport_height_px)) * k_distance_m;
    const float half_height = 0.3f * std::tan(0.5f * cam.fov_y) * k_distance_m;
    const float half_width = half_height * cam.aspect;

    const std::uint32_t n = settings.primitives;
    const std::array<std::uint16_t, 3> meshes{
        r.add_mesh(calibration_mesh(primitive_kind::triangles, n, pixel_m, settings.triangle_px, half_width, half_height)),
        r.add_mesh(calibration_mesh(primitive_kind::points, n, pixel_m, settings.triangle_px, half_width, half_height)),
        r.add_mesh(calibration_mesh(primitive_kind::lines, n, pixel_m, settings.triangle_px, half_width, half_height))};

    sun light;
    light.direction = glm::normalize(glm::vec3(0.3f, 0.8f, 0.4f));
    environment sky;
    cascade_set cascades;  // no shadow pass: the opaque pass (and soft splats' passes) are timed
    draw_list list;
    instance_gpu instance;
    instance.position = {0.0f, 0.0f, -k_distance_m};
    instance.fade = float(n);  // every splat whole (draw_list.h instance_gpu::fade)
    frame_view view;
    view.view_camera = &cam;
    view.sun_light = &light;
    view.sky = &sky;
    view.cascades = &cascades;
    view.draws = &list;
    view.terrain_position = {0.0f, -1e7f, 0.0f};  // the terrain far out of view
    // Splats of one size: the cost of a primitive, not of the fog's larger far splats.
    view.set_samples(
        {settings.sample_distance_px, settings.splat_factor, true, settings.splats, false});

    auto time_frame = [&](int which) {
        list.instances.clear();
        list.batches.clear();
        if (which >= 0) {
            list.instances.push_back(instance);
            list.batches.push_back({render_pass::opaque, meshes[std::size_t(which)], 0, 1, 0});
        }
        r.render(view);
        const frame_stats stats = r.finish();
        return stats.gpu_pass_ms[std::size_t(gpu_pass::opaque)] +
               stats.gpu_pass_ms[std::size_t(gpu_pass::splats)];
    };
    time_frame(0);  // compile the programs and touch the buffers before timing anything
    time_frame(1);
    time_frame(2);
    std::array<std::vector<double>, 4> ms;
    for (int rep = 0; rep < settings.repetitions; ++rep)
        for (int which = -1; which < 3; ++which)
            ms[std::size_t(which + 1)].push_back(time_frame(which));
    const double empty = median(ms[0]);
    const double per_million = 1e6 / double(n);
    calibration_result result;
    result.triangle_ms_per_million = std::max(median(ms[1]) - empty, 1e-6) * per_million;
    result.point_ms_per_million = std::max(median(ms[2]) - empty, 1e-6) * per_million;
    result.line_ms_per_million = std::max(median(ms[3]) - empty, 1e-6) * per_million;
    // Costs relative to a triangle, each ratio rounded to a quarter.
    result.costs.triangle = 1.0;
    result.costs.point = 1.0 / quantize_cost_ratio(result.triangle_ms_per_million / result.point_ms_per_million);
    result.costs.line = quantize_cost_ratio(result.line_ms_per_million / result.triangle_ms_per_million);
    return result;
}

}  // namespace sylva::render
