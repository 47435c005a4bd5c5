#pragma once
// Rotation of 3-band real SH coefficients (spherical_harmonics.h basis and order), exact to
// float precision for bands 0..2: an environment projected once can be turned (the sun's
// azimuth moving, an environment map's map_rotation_deg) without integrating it again.
//
// Method: band l is a (2l+1)-dimensional space closed under rotation, so a band-l function is
// fixed by its values at 2l+1 directions in general position. With A[k][m] = Y_lm(d_k) at fixed
// directions d_k and B[k][m] = Y_lm(R^T d_k), the rotated band is c'_l = A^-1 B c_l. This is the
// fixed-direction ("ZH lobe") rotation of P.-P. Sloan, B. Luna and J. Snyder, "Local, Deformable
// Precomputed Radiance Transfer", SIGGRAPH 2005, §4; A^-1 is computed once, in double.
// Band 0 is rotation invariant.
#include <glm/mat3x3.hpp>

#include "lighting/spherical_harmonics.h"

namespace sylva {

// The coefficients of the rotated function g(w) = f(R^T w): what f had at direction d, g has at
// R d. `rotation` must be a proper rotation (orthonormal, det +1; float rounding is fine); one
// with a non-finite entry is taken as the identity.
// Input coefficients are sanitised as projections are (NaN -> 0, magnitudes held at the
// largest finite float) and the result is finite. Deterministic: fixed summation order.
sh9 rotate(const sh9& coefficients, const glm::mat3& rotation);
sh9_rgb rotate(const sh9_rgb& coefficients, const glm::mat3& rotation);

}  // namespace sylva
