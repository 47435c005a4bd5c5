#pragma once
// How a shell fragment reads its slice at a grazing view (shaders/shell.frag mirrors these; they
// are its reference for tests). Not from Behrendt 2005, whose slanting (Eq. 2,
// lod/shell_slanting.h) answers the same problem with geometry; measured on
// docs/measure_shells.py's far fields, the two below raised SSIM and lowered FLIP at every angle,
// with or without slanting.
//
// 1. Opacity along the view (Engel et al. 2006, "Real-Time Volume Graphics" §9.1, opacity
//    correction): a slice holds what its slab covers seen from above, α over the slab's
//    vertical thickness h, a layer of foliage of optical depth −ln(1 − α). A slice slanted by
//    Eq. 2 stands for its slab tilted with it, h·n_y thick across its plane (n the plane's unit
//    normal), so a ray along unit v crosses h·n_y / |v · n| of foliage and the slice shows
//      α' = 1 − (1 − α)^p,   p = n_y / |v · n|
//    A flat slice seen from straight above keeps its α (p = 1), one seen 5° above takes
//    p = 1 / sin 5° = 11.5. Without it the far field seen grazing is too thin: its slices let
//    through what the crowns hide. (The slab taken horizontal under a slanted slice, p = 1 / |v_y|,
//    measured SSIM 0.957 against 0.958 at 5°.)
//
// 2. Anisotropic filtering by hand: at a grazing view a pixel's footprint on a slice is a long
//    thin ellipse (about 1 : 1/sin e), and one trilinear fetch takes the mip of its long axis,
//    blurring the crowns across the view as much as along it. The long axis is cut into n =
//    ⌈long / short⌉ pieces (at most a maximum), each fetched at the mip of a piece and averaged
//    (the sampling GL's anisotropic filter does). Why by hand: llvmpipe (Mesa 22.3) samples 16
//    taps at any GL_TEXTURE_MAX_ANISOTROPY above 1, which made the shell pass at 5° four times
//    slower (12.7 -> 50 ms) where four taps by hand cost about 1.5x.
//
// 3. The slices' normals seen from the view's elevation: a slice's normal is the mean of its
//    leaves' normals each turned to the side seen from above (models/bake/shell_bake.h), lit as it
//    comes (Toksvig 2005: the shorter, the more evenly spread the leaves' light). Seen from β above
//    the horizontal, a tilted leaf shows whichever side faces the eye, so the sides seen agree less
//    than from above; lit with the from-above mean, the far field came out brighter than its plants
//    (5° above valley's canopy +5 to +7 of 255 in its rows, 20° +2; in tests/gl/shell_gl_test.cpp's
//    shrubs seen from 25°, 1.34 and 1.21 times the meshes' luminance). The mean keeps its direction
//    and is shortened by sin β, from the bake's own from straight above to an even spread edge-on:
//      n' = n · |v_y| / |v|
//    Measured, not derived (docs/representations/shells.md): on docs/measure_shells.py's far fields
//    (1 frame, 480x270) FLIP 0.050/0.051/0.047 became 0.040/0.039/0.041 at 5°/10°/20°, SSIM
//    +0.001, and landscape's 0.0237/0.0226 became 0.0226/0.0214; the far field's mean colour came
//    within 1-2 of 255 of the reference's. The mean of the seen sides for leaves of one tilt about
//    the vertical (exact without shadows, M·v / E|n·v| with M the normals' second moments) keeps a
//    long normal toward the eye and measured worse than the bake's own (FLIP 0.044/0.050/0.055);
//    |v_y|^0.5 instead of |v_y| measured within 0.001 of it.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace sylva {

// The most a slab's path is lengthened: a ray within 1.8° of the slice's plane.
inline constexpr float k_shell_max_path = 32.0f;
// The most fetches a fragment cuts its footprint into (shaders/shell.frag k_max_taps).
inline constexpr int k_shell_max_taps = 4;

// p above for a slice of unit normal `slice_normal` (either side) seen along `view` (any length),
// held to k_shell_max_path; a slice seen edge-on gets the most.
float slab_path(const glm::vec3& view, const glm::vec3& slice_normal);

// α' = 1 − (1 − α)^p, α held below 0.999 so an opaque texel stays finite in the power.
float opacity_along(float alpha, float path);

// 3 above: the slice's filtered normal `from_above` (as the bake averaged it, length <= 1) as it
// lights a fragment seen along `view` (any length, eye to fragment or back): shortened by the
// sine of the view's elevation, |view_y| / |view|.
glm::vec3 seen_normal(const glm::vec3& from_above, const glm::vec3& view);

// The number of fetches for a footprint of texture-space derivatives dx, dy: ⌈long / short⌉
// within [1, max_taps].
int footprint_taps(const glm::vec2& dx, const glm::vec2& dy, int max_taps = k_shell_max_taps);

}  // namespace sylva
