#include "app/bench_format.h"

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <system_error>

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
    std::vector<double> ms;
    std::vector<double> err;
    for (const auto& c : report.configurations) {
        ms.push_back(c.frame_ms_median);
        err.push_back(error(c));
    }
    std::vector<bool> flags(report.configurations.size(), false);
    for (const std::size_t i : pareto_front(ms, err)) flags[i] = true;
    return flags;
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
