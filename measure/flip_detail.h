#pragma once
// The steps of LDR-FLIP (measure/flip_error.cpp) that flip_error() chains, exposed so tests can
// check each against values derived by hand from Andersson et al. 2020 (a step edge, a single
// bright pixel, a sinusoid), not only the pooled mean. Not an API for other code: use
// flip_error() (measure/image_metrics.h).
#include <cstddef>
#include <vector>

#include "models/image/image.h"

namespace sylva::flip_detail {

// One channel of an image, row-major, v.size() == width * height.
struct plane {
    std::size_t width = 0;
    std::size_t height = 0;
    std::vector<double> v;
};

// A contrast sensitivity function as the paper's sum of two Gaussians: in the frequency domain
// a1 exp(-b1 f^2) + a2 exp(-b2 f^2) (f in cycles per degree), in the spatial domain
// a1 sqrt(pi/b1) exp(-pi^2 x^2/b1) + a2 sqrt(pi/b2) exp(-pi^2 x^2/b2) (x in degrees).
struct csf {
    double a1, b1, a2, b2;
};
// Andersson et al. 2020's colour pipeline (Section 4), checked against the authors' reference
// code (NVlabs/flip, python/flip_api.py generate_spatial_filter; b2 = 1e-5 where a2 = 0 only
// avoids a division by zero there).
inline constexpr csf k_csf_achromatic{1.0, 0.0047, 0.0, 1e-5};
inline constexpr csf k_csf_red_green{1.0, 0.0053, 0.0, 1e-5};
inline constexpr csf k_csf_blue_yellow{34.1, 0.04, 13.5, 0.025};

// Step 2: `in` filtered with the CSF's spatial kernel evaluated at the radius r = |(x, y)| on a
// (2R+1)^2 pixel grid (R = ceil(3 sqrt(max b / (2 pi^2)) ppd), the same for every channel) and
// normalised to sum 1. Borders mirror.
plane filter_csf(const plane& in, const csf& f, double pixels_per_degree);

// Step 5's kernels: `across` is the first (edges) or second (points) derivative of a Gaussian of
// sd = 0.5 * 0.082 * ppd pixels over [-ceil(3 sd), ceil(3 sd)], its positive weights normalised
// to sum 1 and its negative weights to sum -1; `along` is the Gaussian normalised to sum 1.
struct feature_kernels {
    std::vector<double> across;
    std::vector<double> along;
};
feature_kernels make_feature_kernels(double pixels_per_degree, bool points);

// Step 5's detector response per pixel: the length of the (x, y) vector of responses, the x one
// correlating `across` along rows and `along` down columns, the y one the other way round.
std::vector<double> feature_strength(const plane& luminance, const feature_kernels& k);

// Steps 1-7 per pixel: the FLIP error map, row-major; flip_error() is its mean. `a` is the
// reference. Throws std::invalid_argument as flip_error() does.
std::vector<double> error_map(const image_rgba8& a, const image_rgba8& b, double pixels_per_degree);

}  // namespace sylva::flip_detail
