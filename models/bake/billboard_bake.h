#pragma once
// Bake-time billboard textures: a deterministic CPU orthographic rasterizer that renders a
// plant's triangles (all of them, or one cluster's) onto a rectangle in model space, with
// supersampling, a depth test, the leaf alpha test and per-texel colour, normal, depth and
// coverage. The crossed billboards (models/bake/crossed_billboard.h) and Behrendt 2005 §2.2 billboard
// clouds (each billboard rendered from its cluster's geometry into an atlas) both bake with it.
//
// Written by hand: no Debian library rasterizes into CPU arrays with a custom resolve (albedo
// average over covered subsamples, nearest-surface normal, coverage as alpha).
#include <cstdint>
#include <limits>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "models/image/image.h"
#include "models/mesh.h"
#include "models/bake/radiance_transfer.h"

namespace sylva {

// A rectangle in model space seen from one side.
//
//          origin + axis_v  +-----------------+  origin + axis_u + axis_v
//            (image row 0)  |                 |
//                           |   viewer on     |     normal = normalize(cross(axis_u, axis_v)),
//                   axis_v  |   the +normal   |     pointing toward the viewer
//                      ^    |   side          |
//                      |    +-----------------+
//                   origin  ---> axis_u          origin + axis_u
//
// axis_u and axis_v are the full width and height and must be orthogonal. Seen from the viewer's
// side, axis_u points right and axis_v up, so a quad with these four corners, that normal and
// counter-clockwise winding (front-facing in GL) shows the image upright and unmirrored when its
// uvs put texel column 0 at `origin` and image row 0 (the top, t = 0 as GL uploads rows) at
// `origin + axis_v`.
struct billboard_plane {
    glm::vec3 origin{0.0f};
    glm::vec3 axis_u{1.0f, 0.0f, 0.0f};
    glm::vec3 axis_v{0.0f, 1.0f, 0.0f};

    glm::vec3 normal() const;
};

// The same rectangle seen from behind (the other side of a two-sided billboard, Behrendt 2005
// §2.2): origin moves to the right-hand corner and axis_u flips, so that image is unmirrored too.
billboard_plane back_side(const billboard_plane& plane);

struct billboard_bake_settings {
    std::uint32_t width = 256;
    std::uint32_t height = 256;
    std::uint32_t supersampling = 4;  // s x s subsamples per texel, on a regular grid; 1..255
    std::uint32_t dilation_texels = 8;  // how far covered colours grow into uncovered texels
};

// What to bake: a mesh with its textures and, optionally, a subset of its triangles.
// Submeshes say each triangle's material: leaf and billboard sample `leaf_texture` and are
// alpha-tested at 0.5 and double-sided; bark and ground sample `bark_texture`, are opaque and
// back-face culled (as the renderer draws them). Both textures wrap like GL_REPEAT and are
// sampled bilinearly, texel row 0 at v = 0. Triangles outside every submesh are skipped.
struct billboard_source {
    const mesh_data* mesh = nullptr;
    const image_rgba8* leaf_texture = nullptr;
    const image_rgba8* bark_texture = nullptr;
    std::span<const std::uint32_t> triangles;  // triangle indices; empty: every triangle
    // Optional: the mesh's precomputed radiance transfer, one receiver per vertex (Behrendt
    // 2005 §4: "we store the Gouraud-interpolated vectors in an extra texture").
    const radiance_transfer* transfer = nullptr;
    // Only surfaces whose signed distance along the plane's normal lies in [slab_min, slab_max)
    // are drawn (a shell's slab, Behrendt 2005 §3.1: models/bake/shell_bake.h); the default
    // keeps everything.
    float slab_min = -std::numeric_limits<float>::infinity();
    float slab_max = std::numeric_limits<float>::infinity();
};

// Every image is width x height, rows top (along +axis_v) to bottom.
struct billboard_image {
    // rgb: mean texture colour of the covered subsamples (straight, not premultiplied);
    // uncovered texels take their covered neighbours' colour up to dilation_texels away, then
    // the mean covered colour, so filtering and mipmaps never pull in a dark halo.
    // a: covered fraction of the texel's subsamples, round(255 * covered / s²).
    image_rgba8 albedo;
    // rgb: n * 0.5 + 0.5 of the mean model-space normal of the nearest surface per subsample,
    // turned toward the viewer where a double-sided leaf is seen from its back (as the leaf
    // shader does with gl_FrontFacing); dilated like albedo. a: the same coverage.
    image_rgba8 normal;
    // Signed distance along normal() from the plane to the nearest covered subsample's surface
    // (positive toward the viewer), 0 where nothing is covered.
    std::vector<float> depth;
    // Covered subsamples per texel (0 .. s²), exact; albedo.a is its 8-bit rounding.
    std::vector<std::uint16_t> covered;
    // Luft 2007's k_a per texel, the mean over its covered subsamples (1 for a plain model's
    // unit normals and where nothing is covered): the pre-lit page's ambient term reads it.
    std::vector<float> ambient;
    // With billboard_source::transfer: per texel, the transfer interpolated over its covered
    // subsamples, 9 coefficients of the side the viewer sees then 9 of the other side
    // (k_billboard_transfer_floats; 2-band transfer leaves 4..8 zero); uncovered texels take the
    // mean covered value. Empty otherwise.
    std::vector<float> transfer;
};
constexpr std::size_t k_billboard_transfer_floats = 18;

// Deterministic: single-threaded, integer edge functions with a top-left fill rule (a subsample
// on an edge shared by two triangles belongs to exactly one); triangles are drawn nearest first
// (by nearest vertex, then index) and a tie in depth keeps the one drawn first. Throws
// std::invalid_argument on a missing mesh or texture, a zero size, non-orthogonal or degenerate
// axes, or a triangle index out of range.
billboard_image bake_billboard(const billboard_source& source, const billboard_plane& plane,
                               const billboard_bake_settings& settings = {});

}  // namespace sylva
