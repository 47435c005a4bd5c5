#pragma once
// The level-of-detail rules of Deussen, Colditz, Stamminger, Drettakis 2002 (§5): how many
// points a part needs (Eq. 1), whether a long thin part is drawn as lines and how many (Eq. 2),
// and how triangles and points blend (§5.3). Pure functions of plain numbers, so every rule has
// a unit test with hand-computed values (tests/lod/point_line_lod_test.cpp).
//
// Units. The paper puts the image plane at distance one from the eye, so projected areas and
// the sample distance d' are in image-plane units. Users set d' in pixels; image_plane_units()
// converts (a pixel at distance one is 2·tan(fov_y / 2) / viewport height wide).
#include <cstdint>
#include <span>

namespace sylva {

// Opaque: §5.1's splats, squares of side d'·√c_p drawn opaque with depth writes. Soft (our
// extension, see soft_splat_peak_alpha): Gaussian splats that each deposit the projected leaf
// area they stand for, composited over a visibility pass.
enum class splat_style : std::uint8_t { soft, opaque };

// What the viewer asks of the point/line representation.
struct point_line_quality {
    float sample_distance_px = 1.0f;  // d': mean distance between neighbouring samples on screen
    float splat_factor = 1.3f;        // c_p (§5.1: "values from 1.2 to 1.5 are usually sufficient")
    // Round each plant's counts with its own offset (sample_dither) instead of down: a field of
    // small plants then draws the samples Eq. 1 asks for in total, not fewer.
    bool dither = true;
    // How a splat is drawn: soft (our extension, below) or opaque squares as in the paper.
    splat_style splats = splat_style::soft;
    // Space a fogged plant's samples by what the fog leaves of it (fog_sample_distance).
    bool fog_weighted = true;
};

// d' in image-plane units (the image plane at distance one) from d' in pixels.
double image_plane_units(double pixels, double fov_y_radians, double viewport_height_px);

// Deussen 2002 Eq. 1, left: A'_p = ½·A_p / r². The projected area of a part of world area
// `area_m2` whose leaves are randomly oriented (the ½) seen from distance r.
double projected_area(double area_m2, double distance_m);

// Fog-weighted sampling (our extension of Eq. 1). Through fog a plant r metres away keeps only
// T(r) = exp(−ρ·r) of its contrast against the fog (lighting/fog.h), and so does any
// error its representation makes: coarser samples there cost T(r) times less in the image. Its
// parts are therefore sampled with d'/√T(r) = d'·exp(ρ·r/2) in place of d', so that Eq. 1's
// count falls with T(r) (p ∝ 1/d'²) and the samples spent follow the contrast they buy; at most
// k_fog_sample_growth_max·d' (T = 1/16, 3 km in the default fog), so the farthest splats stay
// small. Splats grow by the same factor (shaders/surface.vert, per splat from its own distance),
// so each still covers, or deposits, what Eq. 1 assigns it and coverage is unchanged. Points and
// lines drawn as splats only: a real line keeps d' (it is drawn d' wide). ρ = 0: plain d'.
inline constexpr double k_fog_sample_growth_max = 4.0;
double fog_sample_distance(double sample_distance, double distance_m, double fog_density_per_m);

// Deussen 2002 Eq. 1, right: p = c_p·(A'_p / A'_sp)·n_p with A'_sp = d'². The paper multiplies
// by n_p while writing A_p for the part's area; the product is dimensionally a count only when
// A_p is read as the area per point sample (A_p / n_p), and then it equals c_p·A'/A'_sp with A'
// the whole part's projected area. We take that reading: p is the number of splats of area
// d'² that cover the part c_p times over. Returns +inf for r = 0 (draw polygons).
double required_points(double area_m2, double distance_m, double sample_distance, double splat_factor);

// What one primitive of each kind costs to draw on the device (any common unit: only ratios
// matter). The paper assumes
// "a separate triangle requires about as much time for rendering as three points" (§4.1), which
// is where its 3k threshold comes from; on llvmpipe a point costs about half a triangle and a
// line several. systems/render/primitive_cost_calibration measures them where Sylva runs.
struct primitive_costs {
    double triangle = 3.0;
    double point = 1.0;
    double line = 2.0;  // two vertices (the paper counts vertices)

    // ρ: how many points one triangle costs.
    double points_per_triangle() const { return triangle / point; }
};

// What a part draws this frame: a prefix of its triangles and a prefix of its points or lines.
struct part_draw {
    std::uint32_t triangles = 0;
    std::uint32_t primitives = 0;  // points or lines, by the part's primitive; splats when `splats`
    // A line part whose lines are shorter than d' on screen draws its lines' end points as
    // splats instead (select_lines); `primitives` then counts splats, a prefix of those ends.
    bool splats = false;

    friend bool operator==(const part_draw&, const part_draw&) = default;
};

// Deussen 2002 §5.3 blending for a part of k triangles whose points are stored in reverse
// triangle order (models/bake/point_line_model.h), points_after[t] = points of triangles t..k-1
// (k + 1 entries, points_after[0] = n_p):
//   p >= 3k       every triangle ("p > n_p → polygons" of Eq. 1 for n_p = 2k, taken at 3k
//                 where a triangle, about three points' cost, is as cheap as the points)
//   p <  2k       the first p points (at most n_p)
//   2k <= p < 3k  the first p − 2k triangles plus the points of the remaining triangles
// so that the cost (points + 3·triangles) is always about p points. With the device's own
// costs, 3 becomes ρ (points per triangle): for ρ > 2 the blend runs from 2k to ρk with
// t = (p − 2k) / (ρ − 2) triangles; for ρ <= 2 a triangle is no dearer than its two points and
// the part turns polygonal at p >= ρk with no blend. The paper's costs give the paper's rule.
// A NaN p draws nothing; an infinite one draws every triangle.
//
// §4.3 importance m (>= 1) makes a part "reduced more slowly": it blends and turns polygonal as
// if it needed m·p samples, so it keeps its triangles m times farther; once it is points only
// it draws the p its coverage needs (m·p splats of the same size would paint it m times over).
part_draw blend_points(double p, std::uint32_t k, std::span<const std::uint32_t> points_after,
                       const primitive_costs& costs = {}, double importance = 1.0);

// Deussen 2002 §5.2, Eq. 2, for a line part of world area A_l approximated by n_l lines of total
// length l within ε_l. ε_l / r >= d' → triangles (the lines would be visibly off); else
// q = A'_l / A'_sl with A'_l = ½·A_l / r² (as Eq. 1) and A'_sl = l·d' / (2r); q <= 1 draws the
// first q·n_l lines (rounded to nearest, at least one), q > 1 draws every triangle. Lines that
// would cost more on the device than the part's k triangles are drawn as the triangles.
// Importance m (§4.3) turns the part polygonal at q > 1/m; as lines it draws q·n_l (see above).
//
// Short lines (our extension; the paper's lines are "about the same length" and long on
// screen). A line drawn d' wide covers l'·d' only while its image l' = l / (2r·n_l) is at least
// d' long; shorter, it still fills about one d'-sized footprint and costs a whole primitive, so
// Eq. 2 would draw n_l·q lines that cover a fraction of A'_l (on llvmpipe a line under a pixel
// long lights a pixel only when it leaves the pixel's diamond). Below l' = d' the part is drawn
// as Eq. 1 splats at its lines' end points (two per line, so the first p ends are a prefix of
// the line list): p = c_p·A'_l / d'², rounded down after adding `dither` in [0, 1) (0.5:
// nearest; a per-plant value keeps the expected coverage of many small plants exact); every
// triangle when p > 2·n_l or when the splats would cost more than the k triangles.
part_draw select_lines(double area_m2, double length_m, double error_m, std::uint32_t n_lines, std::uint32_t k,
                       double distance_m, double sample_distance, const primitive_costs& costs = {},
                       double importance = 1.0, double splat_factor = 1.3, double dither = 0.5);

// select_lines with fog-weighted sampling (fog_sample_distance): a part whose short lines are
// drawn as splats is decided and counted with the splats' spacing `splat_distance`, as points
// are; otherwise with d' itself, since a line is drawn d' wide. Equal distances: select_lines.
part_draw select_lines_fogged(double area_m2, double length_m, double error_m,
                              std::uint32_t n_lines, std::uint32_t k, double distance_m,
                              double sample_distance, double splat_distance,
                              const primitive_costs& costs = {}, double importance = 1.0,
                              double splat_factor = 1.3, double dither = 0.5);

// A plant's own rounding offset in [0, 1) for part `part` (a fixed hash of its seed): counts are
// rounded down after adding it, so the expected count of many small plants is exact while each
// plant's count still changes only where its distance crosses a threshold (no flicker).
double sample_dither(std::uint32_t seed, std::uint32_t part);

// Point and line samples cast shadows spaced this many shadow-map texels apart (at least): the
// receiver filters the shadow over 3x3 texels (four bilinear PCF taps, shaders/shading.glsl),
// so casters sampled every texel draw four times the splats for detail the filter removes.
// A shadow splat is s wide for samples s apart, with c_p = 1 (compute_shadow_prefix): the
// casters together cover exactly the parts' projected leaf area, as the leaves they stand for
// do, so the light the crown lets through is randomly placed leaves' gap fraction. The view's
// c_p (splats c_p·d'² for c_p·A'/d'² of them) would shade with c_p² = 1.69 times the leaves.
inline constexpr double k_shadow_sample_texels = 2.0;
// ... and at least this many times the viewer's own sample distance (d'·r), splats growing to
// match: a shadow is seen through that filter and cast at a slant, and on forest twice the
// spacing cut the shadow pass from 0.9 to 0.33 of the point pass's time while SSIM moved by
// 0.0007 and FLIP by 0.0004 (splat fill stays the same; llvmpipe pays per splat).
inline constexpr double k_shadow_sample_spacing = 2.0;
// A shadow splat w wide stands for leaves spread over about w in every direction, depth
// included; drawn at its sample's depth, it would shade every leaf beside it that lies a little
// farther from the sun, a blur of the crown's depth that darkens its sunlit side the more, the
// larger the splats. Each splat is therefore moved away from the sun by this many of its own
// widths (the light's version of the visibility pass's ε, k_soft_splat_depth_offset). It moves
// along the light's rays, so where its shadow falls is unchanged. On landscape (2 frames, soft
// splats) with exact-area casters, pushing 0, ½, 1 and 2 widths gave popping 3.16, 3.13, 3.11,
// 3.11 at d' = 2 and 3.54, 3.50, 3.50, 3.52 at d' = 3, FLIP 0.0546, 0.0521, 0.0503, 0.0491 at
// d' = 2, SSIM 0.8950, 0.8941, 0.8939, 0.8930; the mid-field crowns' mean luma error (image
// rows 180-225) went from -2.95 to -2.42, -2.01 and -1.52 (too dark; 0 is right). The price:
// a layer of samples less than w above what it would shade (grass over the ground, with w the
// shadow splat of the viewer's sample distance there) casts no shadow on it.
inline constexpr double k_shadow_splat_push = 1.0;

// Splat side in pixels: each splat covers c_p·d'² (the splat factor enlarges splats so the
// random samples leave no holes, §5.1 and §5.4, Fig. 5c).
float splat_size_px(const point_line_quality& q);

// Soft splats (our extension of §5.1). An opaque splat of c_p·d'² pixels stands for only d'²/c_p
// of projected leaf area (Eq. 1: p = c_p·A'/d'²), so an opaque far crown is a hard-edged
// binary pattern of whichever leaf each splat landed on, and it flickers as splats snap to pixel
// centres. A soft splat instead spreads exactly its own leaf area, d'²/c_p, over a Gaussian
// footprint K times the opaque side (σ = a quarter of the footprint), as opacity. Composited
// "over" each other, n such splats leave 1 − Π(1 − α_i) ≈ 1 − exp(−Σα_i) of a pixel covered:
// the gap fraction of randomly placed leaves (Beer–Lambert), which is what the pixel's
// supersampled reference averages. Which splats composite is decided first by a depth-only
// visibility pass of opaque splats (every second one) pushed back by ε along the view ray, as in
// two-pass surface splatting (Pfister et al. 2000 "Surfels" §5.1; Botsch, Hornung, Zwicker, Kobbelt
// 2005 §3): splats within ε of the nearest surface blend, those behind it do not.
inline constexpr float k_soft_splat_footprint = 2.0f;     // K: soft splat side / opaque splat side
inline constexpr float k_soft_splat_depth_offset = 5.0f;  // ε, in opaque splat sides
// The visibility pass draws every second splat of a prefix (a uniform half: prefixes are in
// random order). Its opaque splats then cover c_p/2 times the leaf area rather than c_p times,
// about a crown's outer layer, and it sets up half the splats. Against every splat, on
// landscape (2 frames) and forest (6): SSIM 0.9215 against 0.9194 and 0.7846 against 0.7755,
// popping 2.63 against 2.66 and 6.27 against 6.51; the full set hid leaves the reference sees.
// Every second rather than the first half: consecutive samples are one triangle's two points or
// one line's two ends, so every second takes one of each, a stratified half. The first half
// (whole triangles, half as many; its vertex shader would run on half the splats) lowered the
// coverage IoU on landscape at d' = 2 from 0.799 to 0.756.
inline constexpr int k_soft_splat_visibility_stride = 2;
// ∫∫ exp(−2(u² + v²)) du dv over u, v in [−1, 1] divided by its square's area 4: the Gaussian's
// mean over its square footprint, (√(π/8)·erf(√2))², as the shader evaluates it (point.frag).
inline constexpr double k_soft_splat_kernel_mean = 0.3577763;

// Soft splats narrower than this (on screen, pixels) are drawn straight into the frame: in the
// half-size splat layer (systems/render/splat_layer.h) they would be under 2 texels wide and
// lose the detail they carry. At d' = 1 (2.3 px) the layer raised forest's popping from 6.37 to
// 6.51 (fog-weighted) and 6.34 to 6.64 (uniform); from d' = 2 (4.6 px) it lowered it on
// landscape, forest and meadow alike.
inline constexpr float k_splat_layer_min_side_px = 4.0f;
// Lines up to this width (pixels) are drawn as GL's one-pixel lines, wider ones as quads by
// shaders/line.geom.
inline constexpr float k_native_line_width_px = 1.25f;

// Soft splat side in pixels: K·d'·√c_p.
float soft_splat_size_px(const point_line_quality& q);

// The Gaussian's peak opacity such that a soft splat deposits d'²/c_p pixels of coverage:
// α₀ = (d'²/c_p) / (k_soft_splat_kernel_mean·S²) with S = K·d'·√c_p, i.e. 1/(mean·K²·c_p²)
// (0.4135 for K = 2, c_p = 1.3), at most 1.
float soft_splat_peak_alpha(const point_line_quality& q);

}  // namespace sylva
