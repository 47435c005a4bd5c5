// `sylva stress`: the numerical stress suite (app/stress/stress_checks.h) as a table.
#include <spdlog/spdlog.h>

#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/stress/stress_checks.h"

namespace sylva {
namespace {

struct stress_command_options {
    int threads = 2;
};

int run_stress(const stress_command_options& o) {
    // The checks log what they provoke (dropped triangles, ...); the table says it all.
    const auto level = spdlog::get_level();
    spdlog::set_level(spdlog::level::err);
    stress_options options;
    options.threads = o.threads;
    std::unique_ptr<render::gl_context> context;
    try {
        render::context_options context_options;
        context_options.width = 160;
        context_options.height = 90;
        context_options.headless = true;
        context = render::create_context(context_options);
        options.context = context.get();
    } catch (const std::exception& e) {
        spdlog::error("no GL context, the render checks fail: {}", e.what());
    }
    const std::vector<stress_row> rows = run_stress_checks(options);
    spdlog::set_level(level);
    std::fputs(format_stress_table(rows).c_str(), stdout);
    for (const stress_row& r : rows)
        if (!r.passed) return k_exit_failure;
    return k_exit_ok;
}

}  // namespace

command_runner add_stress_command(CLI::App& app) {
    auto options = std::make_shared<stress_command_options>();
    app.footer(
        "Checks (one table row each; the limit is printed next to what was measured):\n"
        "  world offsets 1e4..1e6 m render like the origin and camera paths do not jitter;\n"
        "  NaN / infinite glTF positions are rejected and zero-area triangles dropped;\n"
        "  eco tiles over plants at one point or on a line stay bounded and cull like flat;\n"
        "  sun and sky intensity 0..1e12, sun below/on the horizon and at the zenith, turbidity\n"
        "  1.7..10 keep SH, uniforms and images finite; a million frames of time do not drift;\n"
        "  lod_scale 0.01..100 and distances 0..inf or NaN choose sane LODs.\n"
        "Renders scenarios/tiny.json at 160x90 headless (OSMesa). Exit 0 when every check\n"
        "passes, 1 otherwise.");
    app.add_option("--threads", options->threads,
                   "Worker threads for the scenario players (0: all)")
        ->check(CLI::Range(0, 256))
        ->capture_default_str();
    return [options] { return run_stress(*options); };
}

}  // namespace sylva
