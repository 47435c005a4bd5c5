#pragma once
// The point and line bake (Deussen, Colditz, Stamminger, Drettakis 2002, §4 and §6.1): a plant's
// full mesh turned into the parts of a point_line_model (models/bake/point_line_model.h), each with
// its triangles in a random order and a point list (compact parts, §4.1) or a line list (long
// thin parts, §4.2), an importance (§4.3) and, for big plants, an octree cell (§6.1).
//
// Which triangles become lines: needles and grass blades; the bark of thin stems (a stem whose
// length is at least line_elongation times its mean diameter, and that is a twig: level >= 2,
// or nowhere thicker than k_thin_stem_fraction of the plant's size); for an imported model
// that does not know its parts, every connected element that long and thin (bark ones also
// thin against the plant). Everything else (leaves, petals, fronds, trunks, boughs) becomes
// points.
#include <cstdint>

#include "models/plant_model.h"
#include "models/bake/point_line_model.h"

namespace sylva {

// A stem counts as thin against its plant when its diameter is at most this fraction of the
// plant's largest extent: it is about a pixel wide when the plant is 50 pixels tall, where the
// point representation starts to pay.
constexpr float k_thin_stem_fraction = 0.02f;

struct point_line_settings {
    std::uint64_t seed = 1;
    // Largest/smallest opaque triangle area within a part, after dropping the 5 % tails at
    // either end, below which a part is sampled with two points per triangle (stratified, §4.1).
    float similar_area_ratio = 4.0f;
    // Length over width above which an element counts as long and thin (§4.2).
    float line_elongation = 6.0f;
    // §6.1: 0 = one cell; d = up to 8^d cells (the bounds halved d times along every axis);
    // 0..3.
    int octree_depth = 0;
    // Importance of petals (§4.3), and the most colour analysis gives any part.
    float petal_importance = 4.0f;
    // §4.3 future work done: importance from colour distinctiveness, and, for imported models
    // without part kinds, foliage elements of a distinct colour are classed as petals.
    bool automatic_importance = true;
};

// Bakes model.lods[0] with model.leaf_texture and model.bark_texture. Deterministic: the same
// model and settings give the same result on every platform. Triangles with no opaque area
// (degenerate, or cut away entirely by the alpha test) are dropped; triangles outside every
// submesh are skipped. Throws std::invalid_argument on an index out of range or an
// octree_depth outside 0..3.
point_line_model bake_point_lines(const plant_model& model,
                                  const point_line_settings& settings = {});

}  // namespace sylva
