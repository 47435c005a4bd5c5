#include "lighting/sh_rotation.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <limits>
#include <numbers>
#include <utility>

namespace sylva {

namespace {

using dvec3 = glm::dvec3;
template <std::size_t n>
using dmatrix = std::array<std::array<double, n>, n>;

// The exact constants of Sloan's table (spherical_harmonics.h), in double: the rotation is
// built from ratios of them, which the six-digit float constants would blur at 1e-6.
const double k_y1 = std::sqrt(3.0 / (4.0 * std::numbers::pi));
const double k_y2_mixed = std::sqrt(15.0 / (4.0 * std::numbers::pi));
const double k_y2_zonal = std::sqrt(5.0 / (16.0 * std::numbers::pi));
const double k_y2_sectoral = std::sqrt(15.0 / (16.0 * std::numbers::pi));

// Band 1 (indices 1..3: y, z, x) and band 2 (indices 4..8) at a unit direction.
std::array<double, 3> band1(dvec3 d) {
    return {k_y1 * d.y, k_y1 * d.z, k_y1 * d.x};
}
std::array<double, 5> band2(dvec3 d) {
    return {k_y2_mixed * d.x * d.y, k_y2_mixed * d.y * d.z, k_y2_zonal * (3.0 * d.z * d.z - 1.0),
            k_y2_mixed * d.x * d.z, k_y2_sectoral * (d.x * d.x - d.y * d.y)};
}

// Fixed directions. Band 1: the axes, so A is diagonal. Band 2: two axes and three face
// diagonals; by hand A's columns xy, yz and xz each have one non-zero row, and the remaining
// 2x2 block (3z^2 - 1, x^2 - y^2 at +x and +z) is [[-1, 1], [2, 0]], so A is invertible.
const double k_r = std::numbers::sqrt2 / 2.0;
const std::array<dvec3, 3> k_band1_directions = {dvec3(0, 1, 0), dvec3(0, 0, 1), dvec3(1, 0, 0)};
const std::array<dvec3, 5> k_band2_directions = {dvec3(1, 0, 0), dvec3(0, 0, 1), dvec3(k_r, k_r, 0),
                                                 dvec3(k_r, 0, k_r), dvec3(0, k_r, k_r)};

// Gauss-Jordan elimination with partial pivoting; only ever given the well-conditioned A above.
template <std::size_t n>
dmatrix<n> inverse(dmatrix<n> a) {
    dmatrix<n> inv{};
    for (std::size_t i = 0; i < n; ++i) inv[i][i] = 1.0;
    for (std::size_t col = 0; col < n; ++col) {
        std::size_t pivot = col;
        for (std::size_t r = col + 1; r < n; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        std::swap(a[col], a[pivot]);
        std::swap(inv[col], inv[pivot]);
        const double scale = 1.0 / a[col][col];
        for (std::size_t c = 0; c < n; ++c) {
            a[col][c] *= scale;
            inv[col][c] *= scale;
        }
        for (std::size_t r = 0; r < n; ++r) {
            if (r == col) continue;
            const double f = a[r][col];
            for (std::size_t c = 0; c < n; ++c) {
                a[r][c] -= f * a[col][c];
                inv[r][c] -= f * inv[col][c];
            }
        }
    }
    return inv;
}

template <std::size_t n, class Basis>
dmatrix<n> basis_at(const std::array<dvec3, n>& directions, Basis basis) {
    dmatrix<n> a{};
    for (std::size_t k = 0; k < n; ++k) a[k] = basis(directions[k]);
    return a;
}

// M = A^-1 B, B[k][m] = Y_m(R^T d_k) (header). R^T d is renormalised so a float rotation that is
// orthonormal only to rounding still evaluates the band-2 polynomials on the unit sphere.
template <std::size_t n, class Basis>
dmatrix<n> band_rotation(const std::array<dvec3, n>& directions, const dmatrix<n>& a_inverse,
                         const glm::dmat3& rotation, Basis basis) {
    dmatrix<n> b{};
    for (std::size_t k = 0; k < n; ++k) {
        const dvec3 turned = glm::transpose(rotation) * directions[k];
        const double len = glm::length(turned);
        b[k] = basis(len > 0.0 ? turned / len : directions[k]);
    }
    dmatrix<n> m{};
    for (std::size_t r = 0; r < n; ++r)
        for (std::size_t c = 0; c < n; ++c)
            for (std::size_t k = 0; k < n; ++k) m[r][c] += a_inverse[r][k] * b[k][c];
    return m;
}

struct sh_rotation_matrices {
    dmatrix<3> band1;
    dmatrix<5> band2;
};

sh_rotation_matrices rotation_matrices(const glm::mat3& rotation) {
    // Function-local statics: initialised once, thread-safely, always to the same values.
    static const dmatrix<3> band1_inverse = inverse(basis_at(k_band1_directions, band1));
    static const dmatrix<5> band2_inverse = inverse(basis_at(k_band2_directions, band2));
    // A rotation with a non-finite entry (no caller in Sylva makes one) is taken as none.
    bool finite = true;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) finite = finite && std::isfinite(rotation[c][r]);
    const glm::dmat3 r = finite ? glm::dmat3(rotation) : glm::dmat3(1.0);
    return {band_rotation(k_band1_directions, band1_inverse, r, band1),
            band_rotation(k_band2_directions, band2_inverse, r, band2)};
}

double sanitise(float v) {
    if (std::isnan(v)) return 0.0;
    constexpr float k_max = std::numeric_limits<float>::max();
    return double(std::clamp(v, -k_max, k_max));
}

float to_finite_float(double v) {
    if (std::isnan(v)) return 0.0f;
    constexpr double k_max = double(std::numeric_limits<float>::max());
    return float(std::clamp(v, -k_max, k_max));
}

// One channel: coefficient k of the input is in[k] (already sanitised), written to out[k].
void rotate_channel(const sh_rotation_matrices& m, const std::array<double, 9>& in,
                    std::array<float, 9>& out) {
    out[0] = to_finite_float(in[0]);
    for (std::size_t r = 0; r < 3; ++r) {
        double sum = 0.0;
        for (std::size_t c = 0; c < 3; ++c) sum += m.band1[r][c] * in[1 + c];
        out[1 + r] = to_finite_float(sum);
    }
    for (std::size_t r = 0; r < 5; ++r) {
        double sum = 0.0;
        for (std::size_t c = 0; c < 5; ++c) sum += m.band2[r][c] * in[4 + c];
        out[4 + r] = to_finite_float(sum);
    }
}

}  // namespace

sh9 rotate(const sh9& coefficients, const glm::mat3& rotation) {
    const sh_rotation_matrices m = rotation_matrices(rotation);
    std::array<double, 9> in{};
    for (std::size_t k = 0; k < 9; ++k) in[k] = sanitise(coefficients[k]);
    sh9 out{};
    rotate_channel(m, in, out);
    return out;
}

sh9_rgb rotate(const sh9_rgb& coefficients, const glm::mat3& rotation) {
    const sh_rotation_matrices m = rotation_matrices(rotation);
    sh9_rgb out;
    for (int channel = 0; channel < 3; ++channel) {
        std::array<double, 9> in{};
        for (std::size_t k = 0; k < 9; ++k) in[k] = sanitise(coefficients.c[k][channel]);
        sh9 rotated{};
        rotate_channel(m, in, rotated);
        for (std::size_t k = 0; k < 9; ++k) out.c[k][channel] = rotated[k];
    }
    return out;
}

}  // namespace sylva
