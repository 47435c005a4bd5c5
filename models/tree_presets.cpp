#include <stdexcept>
#include <string>

#include "models/tree_params.h"

namespace sylva {
namespace {

// Values are in the ranges of W&P's example trees (their Quaking Aspen and Black Tupelo for the
// broadleaf, a conical-shape fir for the conifer), with stem counts, sides and segments chosen
// for the triangle budget: about 7k triangles at full detail, about a tenth when reduced.
tree_params broadleaf_preset() {
    tree_params p;
    p.height_m = 12.0f;
    p.trunk_radius_ratio = 0.025f;
    p.ratio_power = 1.3f;
    p.base_size = 0.35f;
    p.flare = 0.6f;
    p.attraction_up = 0.4f;
    p.shape = crown_shape::spherical;
    p.levels = 3;
    //            branches length lengthV down downV rotV  curve back curveV taper segs sides
    p.level[0] = {0,       1.0f,  0.05f,  0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 20.0f, 0.85f, 8, 10};
    p.level[1] = {26,      0.42f, 0.05f,  55.0f, -25.0f, 15.0f, -25.0f, 0.0f, 40.0f, 0.9f, 5, 6};
    p.level[2] = {12,      0.55f, 0.1f,   45.0f, 10.0f, 20.0f, -20.0f, 0.0f, 50.0f, 0.95f, 2, 3};
    p.leaves_per_stem = 7;
    p.leaf_length_m = 0.32f;  // a card holding a small spray of leaves (see the leaf texture)
    p.leaf_width_ratio = 0.85f;
    p.leaf_down_angle_deg = 55.0f;
    p.leaf_tilt_variation_deg = 35.0f;
    p.leaf = leaf_shape::broad;
    p.reduced_leaf_quality = 0.22f;
    return p;
}

tree_params conifer_preset() {
    tree_params p;
    p.height_m = 16.0f;
    p.trunk_radius_ratio = 0.018f;
    p.ratio_power = 1.2f;
    p.base_size = 0.2f;
    p.flare = 0.3f;
    p.attraction_up = -0.3f;  // twigs hang slightly
    p.shape = crown_shape::conical;
    p.levels = 3;
    //            branches length lengthV down downV rotV  curve back curveV taper segs sides
    p.level[0] = {0,       1.0f,  0.03f,  0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 6.0f, 1.0f, 10, 8};
    p.level[1] = {52,      0.22f, 0.03f,  82.0f, -15.0f, 10.0f, 15.0f, 0.0f, 20.0f, 1.0f, 3, 4};
    p.level[2] = {10,      0.45f, 0.05f,  50.0f, 10.0f, 15.0f, 0.0f, 0.0f, 20.0f, 1.0f, 1, 3};
    p.leaves_per_stem = 6;
    p.leaf_length_m = 0.42f;  // needle spray cards
    p.leaf_width_ratio = 0.45f;
    p.leaf_down_angle_deg = 35.0f;
    p.leaf_tilt_variation_deg = 90.0f;
    p.leaf = leaf_shape::needle_cluster;
    p.reduced_leaf_quality = 0.18f;
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
