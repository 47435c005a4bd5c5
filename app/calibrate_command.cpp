// `sylva calibrate`: measures what a triangle, a point and a line cost on this GL device
// (systems/render/primitive_cost_calibration.h) and what shader work costs
// (systems/render/shader_work_calibration.h), stores both in the bake cache and prints them,
// the first with the costs it gives at a range of d'. `play` and `bench` calibrate on first use anyway;
// this shows the figures, and --force measures again (after a driver update, say).
#include <spdlog/spdlog.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/atomic_file.h"
#include "app/commands.h"
#include "app/device_costs.h"
#include "scenarios/scenario_loader.h"
#include "setup/spawn_scenario.h"

namespace sylva {
namespace {

struct calibrate_options {
    bool force = false;
    float splat_factor = 1.3f;
    std::string json;
    std::string cache_dir;
    int width = 960;
    int height = 540;
};

constexpr float k_shown_sample_distances[] = {0.5f, 1.0f, 1.5f, 2.0f, 2.25f, 2.5f, 3.0f, 4.0f};

nlohmann::ordered_json report_json(const std::string& device, const device_calibration& c,
                                   float splat_factor) {
    nlohmann::ordered_json j;
    j["device"] = device;
    j["measured_now"] = c.measured_now;
    if (!c.model) j["refused"] = c.refusal;
    if (c.measurement) {
        j["seconds"] = c.measurement->seconds;
        nlohmann::ordered_json samples = nlohmann::ordered_json::array();
        for (std::size_t i = 0; i < c.measurement->samples.size(); ++i) {
            const cost_sample& s = c.measurement->samples[i];
            samples.push_back({{"path", cost_path_name(s.path)},
                               {"pixels", s.pixels},
                               {"us", s.us},
                               {"error_us", s.error_us},
                               {"count", c.measurement->counts[i]}});
        }
        j["samples"] = samples;
    }
    if (!c.model) return j;
    nlohmann::ordered_json paths = nlohmann::ordered_json::object();
    for (std::size_t p = 0; p < k_cost_paths; ++p)
        paths[cost_path_name(cost_path(p))] = {{"a_us", c.model->paths[p].a_us},
                                               {"b_us_per_px", c.model->paths[p].b_us_per_px}};
    j["model"] = paths;
    nlohmann::ordered_json costs = nlohmann::ordered_json::array();
    for (const float d : k_shown_sample_distances)
        for (const splat_style style : {splat_style::soft, splat_style::opaque}) {
            const point_line_quality q{d, splat_factor, true, style, true};
            const primitive_costs pc = c.model->costs_for(q);
            costs.push_back({{"sample_distance_px", d},
                             {"splats", style == splat_style::soft ? "soft" : "opaque"},
                             {"point", pc.point},
                             {"line", pc.line}});
        }
    j["costs_per_triangle"] = costs;
    return j;
}

void print(const std::string& device, const device_calibration& c, float splat_factor) {
    std::printf("device: %s\n", device.c_str());
    if (c.measurement) {
        std::printf(
            "measured in %.1f s (marginal cost of one more primitive, median of the "
            "repetitions):\n",
            c.measurement->seconds);
        for (std::size_t i = 0; i < c.measurement->samples.size(); ++i) {
            const cost_sample& s = c.measurement->samples[i];
            std::printf("  %-20s %7.2f px  %8.4f ± %.4f us  (N = %u)\n", cost_path_name(s.path),
                        s.pixels, s.us, s.error_us, c.measurement->counts[i]);
        }
    } else {
        std::printf("from the bake cache (--force measures again)\n");
    }
    if (!c.model) {
        std::printf("calibration refused: %s\npoints and lines select with the paper's costs.\n",
                    c.refusal.c_str());
        return;
    }
    std::printf("model, us per primitive = a + b x pixels:\n");
    for (std::size_t p = 0; p < k_cost_paths; ++p)
        std::printf("  %-20s a %8.4f  b %8.5f\n", cost_path_name(cost_path(p)),
                    c.model->paths[p].a_us, c.model->paths[p].b_us_per_px);
    std::printf("costs in triangles (c_p %.2f):\n   d' px   soft point   opaque point   line\n",
                splat_factor);
    for (const float d : k_shown_sample_distances) {
        const primitive_costs soft =
            c.model->costs_for({d, splat_factor, true, splat_style::soft, true});
        const primitive_costs opaque =
            c.model->costs_for({d, splat_factor, true, splat_style::opaque, true});
        std::printf("  %6.2f   %10.3f   %12.3f   %6.3f\n", d, soft.point, opaque.point, soft.line);
    }
}

void print_work(const device_work_calibration& w) {
    std::printf("shader work (the auto ladder's rung costs):\n");
    if (w.measurement) {
        static constexpr const char* k_shapes[] = {"small triangles, view", "large triangles, view",
                                                   "large triangles, shadow", "tiny triangles, view"};
        for (std::size_t i = 0; i < w.measurement->samples.size(); ++i) {
            const work_sample& s = w.measurement->samples[i];
            std::printf("  %-24s %9.1f ± %.1f us for %.0f vertices, %.0f fragments, %.0f shadow fragments\n",
                        k_shapes[i], s.us, s.error_us, s.vertices, s.fragments, s.shadow_fragments);
        }
    }
    if (!w.costs) {
        std::printf("  refused: %s\n  the auto ladder costs its rungs by their triangles.\n", w.refusal.c_str());
        return;
    }
    std::printf("  %.5f us per vertex, %.6f us per view fragment, %.6f us per shadow fragment\n",
                w.costs->vertex_us, w.costs->fragment_us, w.costs->shadow_fragment_us);
}

nlohmann::ordered_json work_json(const device_work_calibration& w) {
    nlohmann::ordered_json j;
    j["measured_now"] = w.measured_now;
    if (w.measurement) {
        nlohmann::ordered_json samples = nlohmann::ordered_json::array();
        for (const work_sample& s : w.measurement->samples)
            samples.push_back({{"us", s.us},
                               {"error_us", s.error_us},
                               {"vertices", s.vertices},
                               {"fragments", s.fragments},
                               {"shadow_fragments", s.shadow_fragments}});
        j["samples"] = samples;
        j["seconds"] = w.measurement->seconds;
    }
    if (w.costs)
        j["costs"] = {{"vertex_us", w.costs->vertex_us},
                      {"fragment_us", w.costs->fragment_us},
                      {"shadow_fragment_us", w.costs->shadow_fragment_us}};
    else
        j["refused"] = w.refusal;
    return j;
}

int calibrate(const calibrate_options& o) {
    try {
        bake_cache cache(o.cache_dir);
        const scenario s = load_bundled_scenario("tiny");  // leaf textures for the renderer
        const scene_assets assets = build_scene_assets(s, &cache);
        render::context_options context_options;
        context_options.width = 64;
        context_options.height = 64;
        context_options.headless = true;
        auto context = render::create_context(context_options);
        render::renderer_settings settings;
        settings.width = o.width;
        settings.height = o.height;
        settings.shadows = false;
        render::renderer r(settings, assets);
        const std::string device = describe_cost_device(*context, r, o.splat_factor);
        if (o.force) spdlog::info("calibrating primitive costs on {}", context->renderer());
        const device_calibration c = device_cost_model(r, *context, cache, o.splat_factor, o.force);
        print(device, c, o.splat_factor);
        // Shader work is measured with a shadow map: one cascade takes the shadow shape.
        settings.shadows = true;
        render::renderer shadowed(settings, assets);
        const device_work_calibration w = device_work_costs(shadowed, *context, cache, o.force);
        print_work(w);
        if (!o.json.empty()) {
            nlohmann::ordered_json j = report_json(device, c, o.splat_factor);
            j["shader_work"] = work_json(w);
            write_atomically(o.json, j.dump(2) + "\n");
            spdlog::info("wrote {}", o.json);
        }
        return c.model && w.costs ? k_exit_ok : k_exit_failure;
    } catch (const std::exception& e) {
        spdlog::error("{}", e.what());
        return k_exit_failure;
    }
}

}  // namespace

command_runner add_calibrate_command(CLI::App& app) {
    auto o = std::make_shared<calibrate_options>();
    app.add_flag("--force", o->force,
                 "Measure again even if the bake cache holds this device's costs");
    app.add_option("--splat-factor", o->splat_factor,
                   "c_p the splats are sized with (Deussen 2002 Eq. 1)")
        ->capture_default_str()
        ->check(CLI::Range(1.0f, 4.0f));
    app.add_option("--json", o->json,
                   "Also write the measurement, the model and the costs to this JSON file");
    app.add_option("--cache", o->cache_dir,
                   "Bake cache folder (default: $SYLVA_CACHE_DIR, ~/.cache/sylva)");
    app.add_option("--width", o->width, "Width of the frames it draws")
        ->capture_default_str()
        ->check(CLI::Range(64, 8192));
    app.add_option("--height", o->height, "Height of the frames it draws")
        ->capture_default_str()
        ->check(CLI::Range(64, 8192));
    app.footer(
        "The calibration draws N and 2N leaf-sized triangles, splats and lines on each of the "
        "renderer's paths "
        "and takes the difference, the marginal cost, interleaving repetitions so a busy machine "
        "slows all "
        "alike; it fits t = a + b x pixels per path and gives the costs relative to a triangle at "
        "any d'. It "
        "refuses (exit 1) when the timer's noise is as large as the signal; points and lines then "
        "select with "
        "the paper's costs (Deussen 2002 §4.1: a triangle as three points). The cache key names "
        "the CPU model "
        "and threads, LP_NUM_THREADS, the GL renderer and version. It also measures what a vertex, a view "
        "fragment and a shadow-map fragment cost (tiny, small and large triangles in the view, large ones into a "
        "shadow map, the invocations counted by the device): the auto ladder costs each rung from the shader "
        "work its tables counted.");
    return [o] { return calibrate(*o); };
}

}  // namespace sylva
