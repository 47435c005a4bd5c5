#include "models/bake/colour_importance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <map>

namespace sylva {
namespace {

// CIE 1976 L*a*b* companding: the cube root above (6/29)³, a line below it.
float lab_f(float t) {
    constexpr float k_delta = 6.0f / 29.0f;
    return t > k_delta * k_delta * k_delta ? std::cbrt(t)
                                           : t / (3.0f * k_delta * k_delta) + 4.0f / 29.0f;
}

}  // namespace

glm::vec3 linear_rgb_to_lab(glm::vec3 rgb) {
    // IEC 61966-2-1 sRGB primaries to CIE XYZ, normalised to the D65 white point.
    const float x = (0.4124f * rgb.r + 0.3576f * rgb.g + 0.1805f * rgb.b) / 0.95047f;
    const float y = 0.2126f * rgb.r + 0.7152f * rgb.g + 0.0722f * rgb.b;
    const float z = (0.0193f * rgb.r + 0.1192f * rgb.g + 0.9505f * rgb.b) / 1.08883f;
    const float fx = lab_f(x);
    const float fy = lab_f(y);
    const float fz = lab_f(z);
    return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

float colour_difference(glm::vec3 linear_a, glm::vec3 linear_b) {
    return glm::length(linear_rgb_to_lab(linear_a) - linear_rgb_to_lab(linear_b));
}

glm::vec3 majority_colour(std::span<const glm::vec3> colours, std::span<const float> weights) {
    struct bin {
        glm::dvec3 lab{0.0};  // weighted sums
        double weight = 0.0;
    };
    std::map<std::array<int, 3>, bin>
        bins;  // ordered: ties in the medoid go to the same bin on every run
    for (std::size_t i = 0; i < colours.size(); ++i) {
        if (!(weights[i] > 0.0f)) continue;
        const glm::vec3 lab = linear_rgb_to_lab(colours[i]);
        const glm::vec3 cell = glm::floor(lab / k_majority_bin_de);
        bin& b = bins[{int(cell.x), int(cell.y), int(cell.z)}];
        b.lab += double(weights[i]) * glm::dvec3(lab);
        b.weight += weights[i];
    }
    if (bins.empty()) return glm::vec3{0.0f};
    glm::dvec3 medoid{0.0};
    double best = std::numeric_limits<double>::infinity();
    for (const auto& [key_a, a] : bins) {
        double cost = 0.0;
        for (const auto& [key_b, b] : bins)
            cost += b.weight * glm::length(a.lab / a.weight - b.lab / b.weight);
        if (cost < best) {
            best = cost;
            medoid = a.lab / a.weight;
        }
    }
    glm::dvec3 sum{0.0};
    double total = 0.0;
    for (std::size_t i = 0; i < colours.size(); ++i) {
        if (!(weights[i] > 0.0f) ||
            glm::length(glm::dvec3(linear_rgb_to_lab(colours[i])) - medoid) > k_distinct_low)
            continue;
        sum += double(weights[i]) * glm::dvec3(colours[i]);
        total += weights[i];
    }
    return glm::vec3(sum / total);  // the medoid's own colours are within the radius: total > 0
}

float colour_importance(float delta_e, float petal_importance) {
    const float s =
        std::clamp((delta_e - k_distinct_low) / (k_distinct_high - k_distinct_low), 0.0f, 1.0f);
    const float smooth = s * s * (3.0f - 2.0f * s);
    return 1.0f + std::max(0.0f, petal_importance - 1.0f) * smooth;
}

}  // namespace sylva
