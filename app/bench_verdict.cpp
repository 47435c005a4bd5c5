#include "app/bench_verdict.h"

#include <algorithm>
#include <cmath>

#include "app/bench_catalogue.h"
#include "app/bench_format.h"

namespace sylva {
namespace {

using namespace bench_format;

bool judged(const bench_configuration& c) {
    return c.family != k_family_reference && c.family != k_family_brute_force &&
           c.family != k_family_baseline;
}

baseline_point_verdict judge(const bench_configuration& point,
                             const std::vector<const bench_configuration*>& sweep) {
    baseline_point_verdict v;
    v.baseline = point.name;
    const bench_configuration* fastest = nullptr;    // of the whole sweep
    const bench_configuration* best_fast = nullptr;  // as fast as the point, best SSIM
    for (const bench_configuration* c : sweep) {
        const double ratio = time_ratio(*c, point);
        if (!fastest || ratio < time_ratio(*fastest, point)) fastest = c;
        if (!(ratio <= 1.0)) continue;
        if (c->error.ssim >= point.error.ssim && c->error.perceptual <= point.error.perceptual &&
            (v.beaten_by.empty() || ratio < v.time_ratio)) {
            v.beaten_by = c->name;
            v.time_ratio = ratio;
        }
        if (!best_fast || c->error.ssim > best_fast->error.ssim) best_fast = c;
    }
    if (!v.beaten_by.empty()) return v;
    if (!best_fast) {
        v.why_not = fastest ? "none as fast; fastest " + fastest->name + " at " +
                                  fixed(time_ratio(*fastest, point), 2) + "x"
                            : "no configuration";
        return v;
    }
    const bool ssim_short = best_fast->error.ssim < point.error.ssim;
    v.why_not =
        "as fast: " + best_fast->name + " (" + fixed(time_ratio(*best_fast, point), 2) + "x) has " +
        (ssim_short ? "SSIM " + fixed(best_fast->error.ssim, 4) + " < " + fixed(point.error.ssim, 4)
                    : "FLIP " + fixed(best_fast->error.perceptual, 4) + " > " +
                          fixed(point.error.perceptual, 4));
    return v;
}

}  // namespace

bool family_verdict::beats_every_point() const {
    return !points.empty() &&
           std::all_of(points.begin(), points.end(),
                       [](const baseline_point_verdict& p) { return !p.beaten_by.empty(); });
}

std::string family_verdict::summary() const {
    if (beats_every_point()) return "yes";
    std::string out = "no: not ";
    bool first = true;
    for (const baseline_point_verdict& p : points) {
        if (!p.beaten_by.empty()) continue;
        out += (first ? "" : ", ") + p.baseline;
        first = false;
    }
    return out;
}

std::vector<family_verdict> baseline_verdicts(const bench_report& report) {
    std::vector<family_verdict> out;
    for (const bench_lighting_family& lighting : report.lighting_families) {
        std::vector<const bench_configuration*> points;
        std::vector<std::string> families;
        for (const std::size_t i : in_lighting_family(report, lighting.name)) {
            const bench_configuration& c = report.configurations[i];
            if (c.family == k_family_baseline) points.push_back(&c);
            if (judged(c) &&
                std::find(families.begin(), families.end(), c.family) == families.end())
                families.push_back(c.family);
        }
        if (points.empty()) continue;
        std::stable_sort(points.begin(), points.end(),
                         [](const bench_configuration* a, const bench_configuration* b) {
                             return a->quality < b->quality;
                         });
        for (const std::string& family : families) {
            family_verdict v;
            v.lighting = lighting.name;
            v.family = family;
            std::vector<const bench_configuration*> sweep;
            for (const std::size_t i : in_lighting_family(report, lighting.name))
                if (report.configurations[i].family == family) {
                    sweep.push_back(&report.configurations[i]);
                    v.configurations.push_back(report.configurations[i].name);
                }
            for (const bench_configuration* point : points)
                v.points.push_back(judge(*point, sweep));
            out.push_back(std::move(v));
        }
    }
    return out;
}

}  // namespace sylva
