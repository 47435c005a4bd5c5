#pragma once
// Real spherical harmonics, 3 bands (9 coefficients), for diffuse environment lighting:
// project a radiance function, convolve it with the clamped cosine to get irradiance, evaluate.
//
// Direction convention: world space, y up, x east, -z north (z south); directions are unit
// vectors. The basis functions below are Sloan's table applied to the world (x, y, z) as is, in
// exactly the order shaders/common.glsl sh_irradiance() evaluates them. That makes world z the
// polar axis of the zonal function Y6 (not "up"); this is harmless because bands 0..2 are each
// closed under rotation, so the 9-term projection of any function is the same whichever axis
// the table is written around. Keep this order in sync with the shader.
//
//   index  l  function                 constant
//   0      0  1                        0.282095  = 1/(2 sqrt(pi))
//   1      1  y                        0.488603  = sqrt(3/(4 pi))
//   2      1  z                        0.488603
//   3      1  x                        0.488603
//   4      2  x y                      1.092548  = sqrt(15/(4 pi))
//   5      2  y z                      1.092548
//   6      2  3 z^2 - 1                0.315392  = sqrt(5/(16 pi))
//   7      2  x z                      1.092548
//   8      2  x^2 - y^2                0.546274  = sqrt(15/(16 pi))
//
// Sources: P.-P. Sloan, "Stupid Spherical Harmonics (SH) Tricks", GDC 2008, Appendix A2;
// R. Ramamoorthi and P. Hanrahan, "An Efficient Representation for Irradiance Environment
// Maps", SIGGRAPH 2001, Eq. 3 (basis), Eqs. 7-9 (clamped-cosine convolution).
//
// Range policy: radiance samples are sanitised before integration (NaN -> 0, magnitudes
// clamped to k_sh_max_radiance) and sums are accumulated in double, so projection, convolution
// and evaluation stay finite for any input; 1e-30 .. 1e30 pass through unchanged (to float
// rounding). The 9-term projection of a signed function is kept signed (no clamping at zero),
// so the functions stay linear; the shader clamps the evaluated irradiance at zero.
#include <array>
#include <functional>
#include <glm/vec3.hpp>

namespace sylva {

// Bands 0..bands-1 hold bands^2 coefficients (band l has 2l + 1): 4 for 2 bands, 9 for 3.
constexpr int sh_coefficient_count(int bands) {
    return bands * bands;
}
inline constexpr int k_sh_bands = 3;

// 2 bands from 3: the first sh_coefficient_count(2) = 4 coefficients of a 9-term projection ARE
// the 2-band projection. The basis is orthonormal, so c_i = integral f Y_i depends on Y_i alone,
// not on which other basis functions are kept, and the truncated sum is the least-squares best
// fit in bands 0..1 (the projection theorem). Transfer vectors of 4 coefficients therefore dot
// with the first 4 of radiance_sh, no re-projection needed.
using sh9 = std::array<float, 9>;

struct sh9_rgb {
    std::array<glm::vec3, 9> c{};
};

// Largest radiance magnitude a projection accepts. Bounds through the pipeline: |c_i| <=
// sqrt(4 pi) L (Cauchy-Schwarz), convolution multiplies by <= pi, evaluation sums 9 terms with
// |Y_i| <= 1.1: below 128 L in all, so FLT_MAX / 256 leaves every stage finite.
inline constexpr float k_sh_max_radiance = 3.4028235e38f / 256.0f;

// The 9 basis functions at a unit direction (table above).
sh9 sh_basis(glm::vec3 unit_dir);

// Coefficients c_i = integral over the sphere of L(w) Y_i(w) dw, by the midpoint rule on a
// (theta, phi) grid with the polar axis along world y (up), so with an even samples_theta the
// horizon is a cell boundary and the sky/ground discontinuity is not smeared across a cell.
// Deterministic: no randomness, fixed summation order.
sh9_rgb project_radiance(const std::function<glm::vec3(glm::vec3)>& radiance, int samples_theta,
                         int samples_phi);

// The 9-term projection of a directional light (a delta in direction) carrying `irradiance`
// (what a surface facing it receives): c_i = E Y_i(d). Exact, no integration.
sh9_rgb project_directional_light(glm::vec3 unit_dir, glm::vec3 irradiance);

// Irradiance coefficients from radiance coefficients: multiply band l by the clamped-cosine
// kernel A_l (Ramamoorthi & Hanrahan 2001, Eqs. 7-9): A0 = pi, A1 = 2 pi / 3, A2 = pi / 4.
sh9_rgb irradiance_from_radiance(const sh9_rgb& radiance);

// sum_i c_i Y_i(unit_dir). Not clamped at zero (ringing can make it slightly negative).
glm::vec3 evaluate(const sh9_rgb& coefficients, glm::vec3 unit_dir);

}  // namespace sylva
