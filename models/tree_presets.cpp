#include <stdexcept>
#include <string>

#include "models/tree_params.h"

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

}  // namespace

tree_params tree_preset(std::string_view generator) {
    if (generator == "broadleaf") return broadleaf_preset();
    if (generator == "conifer") return conifer_preset();
    std::string valid;
    for (const std::string_view name : k_tree_preset_names) valid += (valid.empty() ? "" : ", ") + std::string(name);
    throw std::invalid_argument("unknown tree generator \"" + std::string(generator) + "\" (valid: " + valid + ")");
}

}  // namespace sylva
