#pragma once
// Rotating SH transfer vectors about the vertical axis: a plant instance turns its model by a
// yaw, so the transfer baked in model space must turn with it before it is dotted with the
// world's light (Behrendt 2005 §4 shades by "the scalar product of the coefficients"). A yaw is
// the only rotation instances have, and about y the 3-band rotation has a short closed form;
// shaders/transfer.glsl evaluates the same expressions per vertex (keep the two in sync).
//
// Basis order and constants: lighting/spherical_harmonics.h. With world = R(yaw) model,
// R(yaw) = [c 0 s; 0 1 0; -s 0 c] (shaders/surface.vert's instance rotation), the world
// coefficients w of a model-space function with coefficients t are, per band (c = cos yaw,
// s = sin yaw; derived by substituting R^T w into each basis polynomial and re-expanding on the
// unit sphere with x^2 + y^2 + z^2 = 1):
//   band 0:  w0 = t0
//   band 1:  w1 = t1                 (y)
//            w2 = c t2 - s t3        (z)
//            w3 = s t2 + c t3        (x)
//   band 2:  w4 = c t4 + s t5                                        (xy)
//            w5 = -s t4 + c t5                                       (yz)
//            w6 = (c^2 - s^2/2) t6 - sqrt3 c s t7 + (sqrt3/2) s^2 t8 (3z^2 - 1)
//            w7 = sqrt3 c s t6 + (c^2 - s^2) t7 - c s t8             (xz)
//            w8 = (sqrt3/2) s^2 t6 + c s t7 + (1 - s^2/2) t8         (x^2 - y^2)
#include <vector>

#include "models/mesh.h"
#include "models/bake/radiance_transfer.h"
#include "lighting/spherical_harmonics.h"

namespace sylva {

// The coefficients of f(R(yaw)^T w) given those of f (scalar transfer or one light channel).
sh9 rotate_about_y(const sh9& t, float yaw);

// Both sides of a streamed vertex transfer turned by `yaw` (half floats in and out).
vertex_transfer rotate_about_y(const vertex_transfer& t, float yaw);

// The two 9-coefficient vectors of a streamed transfer, and back.
sh9 transfer_side(const vertex_transfer& t,
                  int side);  // 0: the side the normal faces, 1: the other
vertex_transfer pack_transfer(const sh9& front, const sh9& back);
// Every receiver of a bake as streamed records (2 bands: coefficients 4..8 zero).
std::vector<vertex_transfer> pack_transfer(const radiance_transfer& t);

}  // namespace sylva
