// The numerical stress suite (app/stress/stress_checks.h): runs every family's checks in order,
// turning a check that throws, or a GL check without a context, into a failed row, and prints
// the rows as a table. The checks themselves are in app/stress/<family>_checks.cpp.
#include "app/stress/stress_checks.h"

#include <unistd.h>

#include <algorithm>
#include <functional>
#include <string>

#include "app/stress/check_support.h"

namespace sylva {

namespace fs = std::filesystem;
using stress::row;
using stress::rows;
using stress::text;

rows run_stress_checks(const stress_options& options) {
    const fs::path scratch =
        options.scratch_dir.empty()
            ? fs::temp_directory_path() / ("sylva_stress_" + std::to_string(::getpid()))
            : options.scratch_dir;
    rows all;
    const auto add = [&](const std::string& name, const std::function<rows()>& check) {
        try {
            for (stress_row& r : check()) all.push_back(std::move(r));
        } catch (const std::exception& e) {
            all.push_back(row(name, "threw", 0.0, "no exception", false, e.what()));
        }
    };
    const auto gl = [&](const std::string& name,
                        const std::function<rows(render::gl_context&)>& check) {
        if (options.context)
            add(name, [&] { return check(*options.context); });
        else
            all.push_back(
                row(name, "not run", 0.0, "a GL 4.5 context", false, "no GL context (OSMesa)"));
    };
    gl("world offset renders",
       [&](render::gl_context& c) { return check_world_offset_renders(c, options.threads); });
    add("camera path offsets", [] { return check_camera_path_offsets(); });
    add("degenerate models", [&] { return check_degenerate_models(scratch); });
    add("plant clusters", [&] { return check_plant_clusters(options.threads); });
    add("extreme sky", [] { return check_extreme_sky(); });
    gl("extreme light renders",
       [&](render::gl_context& c) { return check_extreme_light_renders(c, options.threads); });
    add("time drift", [&] { return check_time_drift(options.threads); });
    add("extreme LOD", [&] { return check_extreme_lod(options.threads); });
    if (options.scratch_dir.empty()) {
        std::error_code ec;
        fs::remove_all(scratch, ec);
    }
    return all;
}

std::string format_stress_table(const rows& table) {
    const char* headers[] = {"check", "measured", "limit", "result"};
    std::size_t width[3] = {std::char_traits<char>::length(headers[0]),
                            std::char_traits<char>::length(headers[1]),
                            std::char_traits<char>::length(headers[2])};
    for (const stress_row& r : table) {
        width[0] = std::max(width[0], r.check.size());
        width[1] = std::max(width[1], r.measured.size());
        width[2] = std::max(width[2], r.limit.size());
    }
    const auto line = [&](const std::string& a, const std::string& b, const std::string& c,
                          const std::string& d) {
        std::string s = a + std::string(width[0] - a.size() + 2, ' ') + b +
                        std::string(width[1] - b.size() + 2, ' ') + c +
                        std::string(width[2] - c.size() + 2, ' ') + d;
        return s + "\n";
    };
    std::string out = line(headers[0], headers[1], headers[2], headers[3]);
    out += line(std::string(width[0], '-'), std::string(width[1], '-'), std::string(width[2], '-'),
                "------");
    std::size_t failed = 0;
    for (const stress_row& r : table) {
        out += line(r.check, r.measured, r.limit, r.passed ? "pass" : "FAIL");
        failed += r.passed ? 0 : 1;
    }
    out +=
        text("\n%zu checks, %zu passed, %zu failed\n", table.size(), table.size() - failed, failed);
    for (const stress_row& r : table)
        if (!r.passed && !r.detail.empty()) out += "  FAIL " + r.check + ": " + r.detail + "\n";
    return out;
}

}  // namespace sylva
