#include "lighting/transfer_rotation.h"

#include <cmath>
#include <glm/gtc/packing.hpp>

namespace sylva {

sh9 rotate_about_y(const sh9& t, float yaw) {
    const float c = std::cos(yaw), s = std::sin(yaw);
    const float sqrt3 = 1.7320508f;
    sh9 w{};
    w[0] = t[0];
    w[1] = t[1];
    w[2] = c * t[2] - s * t[3];
    w[3] = s * t[2] + c * t[3];
    w[4] = c * t[4] + s * t[5];
    w[5] = -s * t[4] + c * t[5];
    w[6] = (c * c - 0.5f * s * s) * t[6] - sqrt3 * c * s * t[7] + 0.5f * sqrt3 * s * s * t[8];
    w[7] = sqrt3 * c * s * t[6] + (c * c - s * s) * t[7] - c * s * t[8];
    w[8] = 0.5f * sqrt3 * s * s * t[6] + c * s * t[7] + (1.0f - 0.5f * s * s) * t[8];
    return w;
}

sh9 transfer_side(const vertex_transfer& t, int side) {
    sh9 out{};
    for (int i = 0; i < 9; ++i) out[std::size_t(i)] = glm::unpackHalf1x16(t.half[9 * side + i]);
    return out;
}

vertex_transfer pack_transfer(const sh9& front, const sh9& back) {
    vertex_transfer out;
    for (int i = 0; i < 9; ++i) {
        out.half[i] = glm::packHalf1x16(front[std::size_t(i)]);
        out.half[9 + i] = glm::packHalf1x16(back[std::size_t(i)]);
    }
    return out;
}

std::vector<vertex_transfer> pack_transfer(const radiance_transfer& t) {
    const std::size_t n = std::size_t(t.bands) * t.bands;
    std::vector<vertex_transfer> out(t.receiver_count());
    for (std::size_t r = 0; r < out.size(); ++r) {
        sh9 front{}, back{};
        for (std::size_t i = 0; i < n && i < 9; ++i) {
            front[i] = t.front[r * n + i];
            back[i] = t.back[r * n + i];
        }
        out[r] = pack_transfer(front, back);
    }
    return out;
}

vertex_transfer rotate_about_y(const vertex_transfer& t, float yaw) {
    return pack_transfer(rotate_about_y(transfer_side(t, 0), yaw),
                         rotate_about_y(transfer_side(t, 1), yaw));
}

}  // namespace sylva
