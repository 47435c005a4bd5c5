#pragma once
// The crossed billboard: the typical engine's far representation of a plant, two vertical quads
// crossing at the trunk axis, each textured with the plant baked orthographically onto it
// (models/bake/billboard_bake.h). One atlas per species holds both quads' images side by side,
// and beside them the facing billboard's views:
//
//   atlas (7R x R texels)      quad 0: x-y plane, normal +z, u along +x
//   +-------+-------+-+--+--+--+--+--+--+--+--+-+   quad 1: z-y plane, normal +x, u along -z
//   | quad 0| quad 1| |z |x |z |x |z |x |z |x | |   each as wide as twice the model's larger
//   | from  | from  | |e0|e0|e1|e1|e2|e2|e3|e3| |   |extent| along its axis, centred on the
//   |  +z   |  +x   | |  |  |  |  |  |  |  |  | |   trunk, and as tall as the model
//   +-------+-------+-+--+--+--+--+--+--+--+--+-+   (min.y .. max.y)
//   s: 0 .. 1/7 .. 2/7, empty to 2.5/7, the facing   t: 0 at the top, 1 at the bottom (row 0 =
//   views (R/2 x R each, 1/14 of s), empty from 6.5/7  t 0 as GL uploads)
//   The facing views: the plant seen from +z and from +x, raised by the elevations
//   k_facing_elevations_deg (facing_view_plane).
//
// One row, so that at the coarse mip levels a small plant samples a view's neighbours only at
// its sides, and empty columns between the crossed quads and the facing views, so that the
// crossed billboard's mip levels are what they were without the views: next to the views,
// meadow's crossed grass at 8 px lost twice the error in the rung tables (0.38 of its pixels
// against 0.19; the views are the plant squeezed to half the width, denser at their edges).
//
// Each quad is baked from its front side only and drawn double-sided, so its back shows the
// front image mirrored. That is deliberate for this baseline: an orthographic silhouette seen
// from behind is exactly the mirror of the front one, so coverage stays right and only which
// leaf is in front (and the colour of the surface facing away) differs; it halves the atlas.
// The back's normals must be mirrored through the quad's plane by the shader (see
// material_kind::billboard). Billboard clouds, which need true back sides, bake them with
// back_side() from models/bake/billboard_bake.h.
//
// The facing billboard (facing_billboard_mesh) always turns a view's front to the eye, so it
// needs no back sides, but it does need the eye's elevation: a crown seen from above shows its
// sunlit top and hides its trunk, and the side view cannot. On landscape (the eye 5-20 degrees
// above the middle distance), all plants facing with one view raised by 0 / 6 / 12 / 20 degrees
// drew FLIP 0.0477 / 0.0468 / 0.0459 / 0.0480 against the crossed pair's 0.0460 (SSIM
// 0.8977 / 0.8988 / 0.8978 / 0.8932, 12 frames at 480x270), so each view is baked at four
// elevations and the shader takes the nearest to the eye's (shaders/instance.glsl face_the_eye).
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
// 2: meshes in models/cache/mesh_io.h form; 3: optional transfer pages; 4: the facing views
constexpr std::uint32_t k_crossed_billboard_format = 4;
constexpr std::size_t k_crossed_billboard_quads = 2;
// The facing views' elevations above the horizon, in degrees (the facing programs get them, and
// the layout, as defines: systems/render/program_table.cpp).
constexpr std::array<float, 4> k_facing_elevations_deg{0.0f, 8.0f, 16.0f, 30.0f};
// The atlas is this many R wide (the layout above); one elevation's two views are 1/7 of it.
constexpr std::uint32_t k_crossed_billboard_atlas_widths = 7;

struct crossed_billboard_settings {
    std::uint32_t resolution = 256;   // each quad's image is resolution x resolution texels, each
                                      // facing view half as wide (an even number)
    std::uint32_t supersampling = 4;  // s x s subsamples per texel
};

struct crossed_billboard {
    mesh_data mesh;      // 2 quads, 4 triangles, one material_kind::billboard submesh
    image_rgba8 albedo;  // (7 * resolution) x resolution, alpha = coverage
    image_rgba8 normal;  // model-space normals n * 0.5 + 0.5, alpha = coverage
    // With the plant's radiance transfer (Behrendt 2005 §4): k_transfer_pages pages of the
    // atlas's size (models/bake/transfer_pages.h), the front's transfer; else none. Seen from behind
    // a quad shows its front image mirrored, and the shader mirrors its transfer through the
    // quad's plane as it does the normals.
    std::vector<image_rgba8> transfer_pages;
};

// The texel columns at which the atlas's images begin (the crossed pair as one image, as it
// always was; the empty columns; each facing view), and its width last: a renderer building
// the atlas's mips keeps each image's alpha-test coverage apart (systems/render/textures.h).
std::vector<std::uint32_t> crossed_billboard_atlas_columns(std::uint32_t resolution);

// The quads' planes in atlas order, from the full mesh of a plant standing on the origin (y up).
std::array<billboard_plane, k_crossed_billboard_quads> crossed_billboard_planes(const mesh_data& full);

// The plane the facing billboard's view `quad` (0: seen from +z, 1: from +x) at elevation
// k_facing_elevations_deg[elevation] is baked on, from the crossed pair's planes: the quad's
// plane tilted back by the elevation about its horizontal axis through the model's middle (half
// way up; so that in perspective the tilted quad stands where the crown does), as wide as the
// wider quad (the facing quads are one square frame, whichever the plant shows) and as tall as
// the model's box |x|, |z| <= half-width w, min.y .. max.y projects along the view: (max.y -
// min.y) / 2 cos e + w sin e either side of the middle on the tilted up axis (0, cos e, -sin e)
// of quad 0. Elevation 0 is the crossed quad widened to the square frame.
billboard_plane facing_view_plane(
    const std::array<billboard_plane, k_crossed_billboard_quads>& crossed, std::size_t quad,
    std::size_t elevation);

// The facing billboard's mesh from `crossed` (a crossed billboard's pair of quads): the pair
// widened to the square frame of facing_view_plane at elevation 0, with those views' texture
// coordinates (the atlas's third and fourth columns of views), as one
// material_kind::facing_billboard submesh. Its vertex shader turns the plant about its vertical
// axis so that the quad whose baked view is nearer the eye's faces it, collapses the other, tilts
// the shown one back to the baked elevation nearest the eye's and moves its texture coordinates to
// that view (shaders/instance.glsl face_the_eye); its bounds hold every such quad. Its normals
// carry the quads' horizontal normals in x and z and the model's middle height (from which the
// eye's elevation is measured) in y.
mesh_data facing_billboard_mesh(const mesh_data& crossed);

// Bakes lods[0] with the model's leaf and bark textures, and with `transfer` (lods[0]'s, one
// receiver per vertex) its transfer pages. Deterministic.
crossed_billboard bake_crossed_billboard(const plant_model& model,
                                         const crossed_billboard_settings& settings = {},
                                         const radiance_transfer* transfer = nullptr);

}  // namespace sylva
