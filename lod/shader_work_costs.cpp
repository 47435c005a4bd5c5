#include "lod/shader_work_costs.h"

#include <array>
#include <cmath>
#include <sstream>

namespace sylva {
namespace {

constexpr double k_min_signal_to_noise = 5.0;

std::string figures(const work_sample& s) {
    std::ostringstream out;
    out << s.us << " ± " << s.error_us << " µs for " << s.vertices << " vertices, " << s.fragments
        << " fragments and " << s.shadow_fragments << " shadow fragments";
    return out.str();
}

}  // namespace

shader_work_costs fit_shader_work(const std::vector<work_sample>& samples) {
    for (const work_sample& s : samples)
        if (!std::isfinite(s.us) || !std::isfinite(s.error_us) || s.us <= 0.0 ||
            s.us < k_min_signal_to_noise * s.error_us)
            throw work_calibration_refused("the time of the added work is not above the timer's noise (" +
                                           figures(s) + ")");
    // Normal equations A c = b of the three columns, each scaled to unit size so that the
    // elimination does not mix millions of fragments with thousands of vertices.
    std::array<double, 3> scale{};
    for (const work_sample& s : samples) {
        scale[0] = std::max(scale[0], s.vertices);
        scale[1] = std::max(scale[1], s.fragments);
        scale[2] = std::max(scale[2], s.shadow_fragments);
    }
    for (const double v : scale)
        if (!(v > 0.0)) throw work_calibration_refused("the samples do not draw every kind of work");
    std::array<std::array<double, 4>, 3> m{};  // [A | b]
    // Each sample's row divided by its time: the residuals are relative, so the shadow shape's
    // hundreds of milliseconds do not drown the tiny triangles' tens.
    for (const work_sample& s : samples) {
        const double w = 1.0 / s.us;
        const std::array<double, 3> x{w * s.vertices / scale[0], w * s.fragments / scale[1],
                                      w * s.shadow_fragments / scale[2]};
        for (std::size_t i = 0; i < 3; ++i) {
            for (std::size_t j = 0; j < 3; ++j) m[i][j] += x[i] * x[j];
            m[i][3] += x[i] * (w * s.us);
        }
    }
    const double size = m[0][0] + m[1][1] + m[2][2];
    for (std::size_t c = 0; c < 3; ++c) {  // Gauss-Jordan with partial pivoting
        std::size_t pivot = c;
        for (std::size_t r = c + 1; r < 3; ++r)
            if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
        if (std::abs(m[pivot][c]) <= 1e-9 * size)
            throw work_calibration_refused("the samples' counts cannot separate vertex, fragment and shadow work");
        std::swap(m[c], m[pivot]);
        for (std::size_t r = 0; r < 3; ++r) {
            if (r == c) continue;
            const double f = m[r][c] / m[c][c];
            for (std::size_t k = c; k < 4; ++k) m[r][k] -= f * m[c][k];
        }
    }
    shader_work_costs costs;
    costs.vertex_us = m[0][3] / m[0][0] / scale[0];
    costs.fragment_us = m[1][3] / m[1][1] / scale[1];
    costs.shadow_fragment_us = m[2][3] / m[2][2] / scale[2];
    if (!(costs.vertex_us > 0.0 && costs.fragment_us > 0.0 && costs.shadow_fragment_us > 0.0)) {
        std::ostringstream out;
        out << "a negative or zero cost per unit of work (" << costs.vertex_us << " µs per vertex, "
            << costs.fragment_us << " per fragment, " << costs.shadow_fragment_us << " per shadow fragment)";
        throw work_calibration_refused(out.str());
    }
    return costs;
}

}  // namespace sylva
