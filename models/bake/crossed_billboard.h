#pragma once
// The crossed billboard: the typical engine's far representation of a plant, two vertical quads
// crossing at the trunk axis, each textured with the plant baked orthographically onto it
// (models/bake/billboard_bake.h). One atlas per species holds both quads' images side by side:
//
//   atlas (2R x R texels)                 quad 0: x-y plane, normal +z, u along +x
//   +-------------+-------------+         quad 1: z-y plane, normal +x, u along -z
//   |   quad 0    |   quad 1    |         each as wide as twice the model's larger |extent|
//   |  (seen from |  (seen from |         along its axis, centred on the trunk, and as tall
//   |     +z)     |     +x)     |         as the model (min.y .. max.y)
//   +-------------+-------------+
//   s: 0 .. 0.5    0.5 .. 1      t: 0 at the top, 1 at the bottom (row 0 = t 0 as GL uploads)
//
// Each quad is baked from its front side only and drawn double-sided, so its back shows the
// front image mirrored. That is deliberate for this baseline: an orthographic silhouette seen
// from behind is exactly the mirror of the front one, so coverage stays right and only which
// leaf is in front (and the colour of the surface facing away) differs; it halves the atlas.
// The back's normals must be mirrored through the quad's plane by the shader (see
// material_kind::billboard). Billboard clouds, which need true back sides, bake them with
// back_side() from models/bake/billboard_bake.h.
#include <array>
#include <cstdint>
#include <vector>

#include "models/bake/billboard_bake.h"
#include "models/image/image.h"
#include "models/mesh.h"
#include "models/plant_model.h"
#include "models/bake/radiance_transfer.h"

namespace sylva {

// Bump whenever the bake, the quad layout or the atlas layout changes what it produces.
// 2: meshes in models/cache/mesh_io.h form; 3: optional transfer pages
constexpr std::uint32_t k_crossed_billboard_format = 3;
constexpr std::size_t k_crossed_billboard_quads = 2;

struct crossed_billboard_settings {
    std::uint32_t resolution = 256;   // each quad's image is resolution x resolution texels
    std::uint32_t supersampling = 4;  // s x s subsamples per texel
};

struct crossed_billboard {
    mesh_data mesh;      // 2 quads, 4 triangles, one material_kind::billboard submesh
    image_rgba8 albedo;  // (2 * resolution) x resolution, alpha = coverage
    image_rgba8 normal;  // model-space normals n * 0.5 + 0.5, alpha = coverage
    // With the plant's radiance transfer (Behrendt 2005 §4): k_transfer_pages pages of the
    // atlas's size (models/bake/transfer_pages.h), the front's transfer; else none. Seen from behind
    // a quad shows its front image mirrored, and the shader mirrors its transfer through the
    // quad's plane as it does the normals.
    std::vector<image_rgba8> transfer_pages;
};

// The quads' planes in atlas order, from the full mesh of a plant standing on the origin (y up).
std::array<billboard_plane, k_crossed_billboard_quads> crossed_billboard_planes(const mesh_data& full);

// `crossed` (a crossed billboard's pair of quads) as the facing billboard draws it: one
// material_kind::facing_billboard submesh, whose vertex shader turns the plant about its
// vertical axis so that the quad whose baked view is nearer the eye's faces it, and collapses the
// other (shaders/instance.glsl face_the_eye); its bounds the circle either quad sweeps.
mesh_data facing_billboard_mesh(const mesh_data& crossed);

// Bakes lods[0] with the model's leaf and bark textures, and with `transfer` (lods[0]'s, one
// receiver per vertex) its transfer pages. Deterministic.
crossed_billboard bake_crossed_billboard(const plant_model& model,
                                         const crossed_billboard_settings& settings = {},
                                         const radiance_transfer* transfer = nullptr);

}  // namespace sylva
