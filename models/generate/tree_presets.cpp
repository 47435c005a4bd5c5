#include <stdexcept>
#include <string>

#include "models/generate/tree_params.h"

namespace sylva {
namespace {

// Values are in the ranges of W&P's example trees (their Quaking Aspen and Black Tupelo for the
// broadleaf, a Norway-spruce-like conical crown for the conifer). The triangle budget (<= 8k at
// full detail, ~a tenth reduced, for a CPU rasterizer) goes mostly to leaf cards: the trunk and
// first-level branches are coarse prisms, the last stem level has no bark at all (bark_levels)
// and only carries the cards, each a whole clump of leaves or a needle shoot (see textures.cpp).
tree_params broadleaf_preset() {
    tree_params p;
    p.height_m = 12.0f;
    p.trunk_radius_ratio = 0.028f;
    p.ratio_power = 1.3f;
    p.base_size = 0.3f;
    p.flare = 0.6f;
    p.attraction_up = 0.5f;
    p.shape = crown_shape::spherical;
    p.levels = 3;
    p.bark_levels = 2;
    //            branches length lengthV down downV rotV  curve back curveV taper segs sides
    p.level[0] = {0,       0.9f,  0.05f,  0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 20.0f, 0.85f, 6, 8};
    p.level[1] = {24,      0.45f, 0.05f,  55.0f, -25.0f, 15.0f, -20.0f, 0.0f, 40.0f, 0.9f, 4, 4};
    p.level[2] = {13,      0.5f,  0.1f,   45.0f, 15.0f, 20.0f, -20.0f, 0.0f, 50.0f, 0.95f, 2, 3};
    p.leaves_per_stem = 16;
    p.leaf_length_m = 0.85f;  // a card holding a clump of leaves (see the leaf texture)
    p.leaf_width_ratio = 0.9f;
    p.leaf_down_angle_deg = 50.0f;
    p.leaf_tilt_variation_deg = 70.0f;  // clumps face every way, so the crown is full from the side
    p.leaf = leaf_shape::broad;
    p.reduced_leaf_quality = 0.12f;
    p.reduced_segment_ratio = 0.25f;
    return p;
}

tree_params conifer_preset() {
    tree_params p;
    p.height_m = 16.0f;
    p.trunk_radius_ratio = 0.017f;
    p.ratio_power = 1.2f;
    p.base_size = 0.2f;
    p.flare = 0.3f;
    p.attraction_up = -0.3f;  // twigs hang slightly
    p.shape = crown_shape::conical;
    p.levels = 3;
    p.bark_levels = 2;
    //            branches length lengthV down downV rotV  curve back curveV taper segs sides
    p.level[0] = {0,       1.0f,  0.03f,  0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 6.0f, 1.0f, 8, 6};
    p.level[1] = {64,      0.24f, 0.03f,  90.0f, -12.0f, 10.0f, 10.0f, 0.0f, 20.0f, 1.0f, 2, 3};
    p.level[2] = {9,       0.5f,  0.05f,  55.0f, 10.0f, 25.0f, 0.0f, 0.0f, 20.0f, 1.0f, 1, 3};
    p.leaves_per_stem = 11;
    p.leaf_length_m = 0.75f;  // needle shoot cards
    p.leaf_width_ratio = 0.75f;
    p.leaf_down_angle_deg = 45.0f;
    p.leaf_tilt_variation_deg = 90.0f;
    p.leaf = leaf_shape::needle_cluster;
    p.reduced_leaf_quality = 0.12f;
    p.reduced_bark_levels = 1;  // the branches are hidden in the needles: trunk only
    p.reduced_segment_ratio = 0.25f;
    return p;
}

// The broadleaf at film detail (issue 3: >= 100,000 triangles at full detail): the same crown
// with a fourth stem level, round smooth stems at every level (all meshed as bark) and many
// smaller leaf cards, so the hierarchy and leaf records are rich enough for the papers' LOD
// methods. The reduced and far levels keep the ~10% and ~4% ratios of the game-ready tree.
tree_params broadleaf_hd_preset() {
    tree_params p = broadleaf_preset();
    p.levels = 4;
    p.bark_levels = 4;
    //            branches length lengthV down downV rotV  curve back curveV taper segs sides
    p.level[0] = {0,       0.9f,  0.05f,  0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 20.0f, 0.85f, 16, 24};
    p.level[1] = {30,      0.45f, 0.05f,  55.0f, -25.0f, 15.0f, -20.0f, 0.0f, 40.0f, 0.9f, 10, 10};
    p.level[2] = {12,      0.55f, 0.1f,   45.0f, 15.0f, 20.0f, -20.0f, 0.0f, 50.0f, 0.95f, 5, 6};
    p.level[3] = {10,      0.5f,  0.1f,   45.0f, 15.0f, 30.0f, 0.0f, 0.0f, 30.0f, 1.0f, 3, 4};
    p.leaves_per_stem = 20;
    p.leaf_length_m = 0.45f;
    p.reduced_leaf_quality = 0.2f;
    p.reduced_segment_ratio = 0.3f;
    p.reduced_sides_ratio = 0.4f;
    p.reduced_bark_levels = 3;
    p.far_leaf_quality = 0.07f;
    p.far_segment_ratio = 0.15f;
    p.far_bark_levels = 2;
    return p;
}

// A multi-stemmed bush (hazel, dogwood): a clump of leaning stems from the ground, ~2.5 m,
// no trunk, leafy twigs down to the ground.
tree_params shrub_preset() {
    tree_params p;
    p.height_m = 2.1f;
    p.ground_stems = 7;
    p.ground_stem_lean_deg = 22.0f;
    p.ground_stem_spread_m = 0.25f;
    p.trunk_radius_ratio = 0.012f;
    p.ratio_power = 1.2f;
    p.base_size = 0.15f;
    p.flare = 0.0f;
    p.attraction_up = 0.3f;
    p.shape = crown_shape::tapered_cylindrical;
    p.levels = 3;
    p.bark_levels = 2;
    //            branches length lengthV down downV rotV  curve back curveV taper segs sides
    p.level[0] = {0,       0.9f,  0.15f,  0.0f, 0.0f, 0.0f, 15.0f, 0.0f, 25.0f, 0.9f, 5, 5};
    p.level[1] = {9,       0.5f,  0.1f,   40.0f, 15.0f, 20.0f, -10.0f, 0.0f, 30.0f, 0.9f, 3, 3};
    p.level[2] = {6,       0.5f,  0.1f,   45.0f, 15.0f, 30.0f, 0.0f, 0.0f, 30.0f, 1.0f, 1, 3};
    p.leaves_per_stem = 7;
    p.leaf_length_m = 0.32f;
    p.leaf_width_ratio = 0.9f;
    p.leaf_down_angle_deg = 50.0f;
    p.leaf_tilt_variation_deg = 70.0f;
    p.leaf = leaf_shape::broad;
    p.reduced_leaf_quality = 0.1f;
    p.reduced_segment_ratio = 0.34f;
    p.reduced_bark_levels = 1;
    p.far_leaf_quality = 0.05f;
    p.far_segment_ratio = 0.2f;
    p.far_bark_levels = 1;
    return p;
}

}  // namespace

tree_params tree_preset(std::string_view generator) {
    if (generator == "broadleaf") return broadleaf_preset();
    if (generator == "broadleaf_hd") return broadleaf_hd_preset();
    if (generator == "conifer") return conifer_preset();
    if (generator == "shrub") return shrub_preset();
    std::string valid;
    for (const std::string_view name : k_tree_preset_names) valid += (valid.empty() ? "" : ", ") + std::string(name);
    throw std::invalid_argument("unknown tree generator \"" + std::string(generator) + "\" (valid: " + valid + ")");
}

}  // namespace sylva
