#pragma once
// Precomputed radiance transfer for diffuse surfaces (Behrendt 2005 §4, after Sloan, Kautz &
// Snyder 2002, "Precomputed Radiance Transfer for Real-Time Rendering in Dynamic, Low-Frequency
// Lighting Environments", SIGGRAPH, §5 "diffuse shadowed transfer"): per receiver, the vector
// that turns the environment's SH radiance coefficients into the receiver's irradiance with
// the plant's own shadows, so the run time shades by a dot product.
//
// Estimator. T = T_unoccluded(n) - integral (1 - V(w)) max(n.w, 0) Y(w) dw. T_unoccluded is the
// clamped-cosine projection, exact in closed form (Ramamoorthi & Hanrahan 2001, Eqs. 7-9: band l
// is A_l Y_lm(n)); only the occluded part is estimated by Monte Carlo over a spherical
// Fibonacci point set (equal-area strata, any count) randomly rotated per receiver. An
// unoccluded receiver thus gets the exact projection, and noise appears only where the plant
// casts shadows. Each ray counts toward the front or the back by the sign of n.w, so one set
// of rays estimates both sides.
//
// Determinism: every receiver's rays come from hash(seed, receiver index) and its sums are
// its own, so the result is bit-identical for any thread count and any chunking.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "models/image/image.h"
#include "models/mesh.h"

namespace sylva {

// Bump when the bake changes. 2: the reduced and far levels resampled from the full level's
// transfer (models/bake/transfer_resampling.h) instead of ray-cast.
constexpr std::uint32_t k_radiance_transfer_format = 2;

struct transfer_settings {
    std::uint32_t bands = 3;  // 2 (4 coefficients) or 3 (9)
    std::uint32_t rays_per_receiver = 64;
    bool interreflection = false;  // one diffuse bounce (Sloan 2002 interreflected transfer)
    std::uint64_t seed = 1;
};

// Albedo of a material without a texture in the interreflection bounce: a mid grey, an
// assumption, since nothing says what colour the renderer would give it.
constexpr float k_default_albedo = 0.5f;

// Transfer vectors per receiver (a vertex, a point sample or a line vertex), bands^2 floats
// each, in the coefficient order of lighting/spherical_harmonics.h.
// front: T_i = integral V(w) max(n.w, 0) Y_i(w) dw   (light arriving on the side n faces)
// back:  T_i = integral V(w) max(-n.w, 0) Y_i(w) dw  (the other side: double-sided leaves, and
//        the light a thin leaf transmits). Exit radiance at run time: albedo/pi sum T_i L_i,
//        L the environment's radiance coefficients.
struct radiance_transfer {
    std::uint32_t bands = 3;
    std::vector<float> front;  // receiver_count * bands^2
    std::vector<float> back;

    std::size_t receiver_count() const { return bands ? front.size() / (bands * bands) : 0; }
};

// The plant's full mesh as occluder, built once and reused for many receivers (its three mesh
// levels, its point samples, its line vertices). Leaf triangles are alpha-tested against
// `leaf_texture` in an occlusion filter, so light passes through cut-out texels exactly where
// the renderer discards them; every other material is opaque and one-sided (see the .cpp).
// The textures' mean colours are the materials' albedos for the interreflection bounce
// (`bark_texture` serves every non-leaf material); a missing texture counts as k_default_albedo.
class transfer_occluders {
public:
    transfer_occluders(const mesh_data& full, const image_rgba8& leaf_texture,
                       const image_rgba8& bark_texture = image_rgba8{});
    ~transfer_occluders();
    transfer_occluders(const transfer_occluders&) = delete;
    transfer_occluders& operator=(const transfer_occluders&) = delete;

    // Throws std::invalid_argument on bands other than 2 or 3, or zero rays. With
    // settings.interreflection, first bakes the occluder's own vertices (shadowed only; kept
    // for later bakes with the same bands, rays and seed) for the bounce.
    radiance_transfer bake(std::span<const vertex> receivers,
                           const transfer_settings& settings) const;

    struct scene;  // the Embree device, scene and the filters' data (radiance_transfer.cpp)

private:
    // One pass over `receivers`; with `bounce_source` (the occluder's own vertices' shadowed
    // transfer) each hit also adds the light the hit surface reflects.
    radiance_transfer bake_pass(std::span<const vertex> receivers,
                                const transfer_settings& settings,
                                const radiance_transfer* bounce_source) const;

    std::unique_ptr<scene> m_scene;
};

}  // namespace sylva
