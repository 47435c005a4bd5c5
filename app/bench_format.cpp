#include "app/bench_format.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <system_error>

#include "app/bench_catalogue.h"

namespace sylva::bench_format {

double flip_error(const bench_configuration& c) {
    return c.error.perceptual;
}
double ssim_error(const bench_configuration& c) {
    return 1.0 - c.error.ssim;
}


double rounded(double v) {
    if (!std::isfinite(v)) return v;
    if (std::fabs(v) >= 1e6) return std::round(v);
    std::array<char, 32> text{};
    const auto end =
        std::to_chars(text.data(), text.data() + text.size(), v, std::chars_format::general, 6).ptr;
    double r = v;
    std::from_chars(text.data(), end, r);
    return r;
}

std::string plain(double v) {
    if (std::isnan(v)) return "nan";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::array<char, 400> text{};  // fixed notation of 1e308 has 309 digits
    const auto end =
        std::to_chars(text.data(), text.data() + text.size(), v, std::chars_format::fixed).ptr;
    return {text.data(), end};
}

std::string fixed(double v, int decimals) {
    if (!std::isfinite(v)) return plain(v);
    std::array<char, 400> text{};
    const auto end =
        std::to_chars(text.data(), text.data() + text.size(), v, std::chars_format::fixed, decimals)
            .ptr;
    return {text.data(), end};
}

std::string significant(double v, int digits) {
    if (!std::isfinite(v)) return plain(v);
    std::array<char, 32> text{};
    const auto end =
        std::to_chars(text.data(), text.data() + text.size(), v, std::chars_format::general, digits)
            .ptr;
    return {text.data(), end};
}

std::vector<bool> front_flags(const bench_report& report, error_of error) {
    std::vector<bool> flags(report.configurations.size(), false);
    for (const bench_lighting_family& family : report.lighting_families) {
        const std::vector<std::size_t> members = in_lighting_family(report, family.name);
        std::vector<double> ms;
        std::vector<double> err;
        for (const std::size_t i : members) {
            ms.push_back(report.configurations[i].frame_ms_median);
            err.push_back(error(report.configurations[i]));
        }
        for (const std::size_t k : pareto_front(ms, err)) flags[members[k]] = true;
    }
    return flags;
}

std::vector<std::size_t> in_lighting_family(const bench_report& report, std::string_view lighting) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < report.configurations.size(); ++i)
        if (report.configurations[i].lighting == lighting) out.push_back(i);
    return out;
}

const bench_configuration* family_brute_force(const bench_report& report, std::string_view lighting) {
    for (const auto& c : report.configurations)
        if (c.lighting == lighting && c.family == k_family_brute_force) return &c;
    return nullptr;
}

const bench_configuration* family_baseline(const bench_report& report, std::string_view lighting) {
    for (const auto& c : report.configurations)
        if (c.lighting == lighting && c.family == k_family_baseline && c.quality == k_named_baseline_distance_m)
            return &c;
    return nullptr;
}

double time_ratio(const bench_configuration& a, const bench_configuration& b) {
    if (a.frame_ms_rounds.size() != b.frame_ms_rounds.size() || a.frame_ms_rounds.empty())
        return a.frame_ms_median / b.frame_ms_median;
    std::vector<double> ratios;
    for (std::size_t r = 0; r < a.frame_ms_rounds.size(); ++r)
        ratios.push_back(a.frame_ms_rounds[r] / b.frame_ms_rounds[r]);
    std::sort(ratios.begin(), ratios.end());
    const std::size_t mid = ratios.size() / 2;
    return ratios.size() % 2 ? ratios[mid] : 0.5 * (ratios[mid - 1] + ratios[mid]);
}

const bench_configuration* find_configuration(const bench_report& report, std::string_view name) {
    for (const auto& c : report.configurations)
        if (c.name == name) return &c;
    return nullptr;
}

double entry_or_nan(const std::map<std::string, double>& values, const std::string& key) {
    const auto it = values.find(key);
    return it == values.end() ? std::numeric_limits<double>::quiet_NaN() : it->second;
}

}  // namespace sylva::bench_format
