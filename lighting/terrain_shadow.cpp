#include "lighting/terrain_shadow.h"

#include <algorithm>
#include <cmath>

namespace sylva {

void terrain_shadow_heights(std::span<const float> heights, std::uint32_t resolution,
                            double spacing, glm::vec3 towards_sun, std::vector<float>& shadow) {
    const std::size_t n = std::size_t(resolution);
    shadow.assign(heights.begin(), heights.end());
    const double horizontal = std::hypot(double(towards_sun.x), double(towards_sun.z));
    if (n < 2 || towards_sun.y <= 0.0f || horizontal < 1e-6) return;
    // u: the axis along which the sun's horizontal direction s is longer (x: columns, z: rows),
    // v the other. One step towards the sun is one sample along u and dv along v, a horizontal
    // run of spacing / |s_u| over which the sun's ray climbs `drop`.
    const bool along_x = std::abs(towards_sun.x) >= std::abs(towards_sun.z);
    const double s_u = (along_x ? towards_sun.x : towards_sun.z) / horizontal;
    const double s_v = (along_x ? towards_sun.z : towards_sun.x) / horizontal;
    const double dv = s_v / std::abs(s_u);
    const double drop = spacing / std::abs(s_u) * (double(towards_sun.y) / horizontal);
    auto index = [&](std::size_t u, std::size_t v) { return along_x ? v * n + u : u * n + v; };
    const int du = s_u > 0.0 ? 1 : -1;
    // The line nearest the sun keeps H = h; every other takes the line before it towards the sun.
    const std::size_t first = du > 0 ? n - 1 : 0;
    for (std::size_t step = 1; step < n; ++step) {
        const std::size_t u = du > 0 ? first - step : first + step;
        const std::size_t q = du > 0 ? u + 1 : u - 1;
        for (std::size_t v = 0; v < n; ++v) {
            const double qv = double(v) + dv;
            if (qv < 0.0 || qv > double(n - 1)) continue;  // the ray leaves the field: no terrain
            const std::size_t v0 = std::min(std::size_t(qv), n - 2);
            const double f = qv - double(v0);
            const double hq =
                double(shadow[index(q, v0)]) * (1.0 - f) + double(shadow[index(q, v0 + 1)]) * f;
            float& h = shadow[index(u, v)];
            h = std::max(h, float(hq - drop));
        }
    }
}

}  // namespace sylva
