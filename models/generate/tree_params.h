#pragma once
// Parameters of the procedural tree, after Weber & Penn 1995, "Creation and rendering of
// realistic trees", SIGGRAPH (W&P below). Names follow the paper's parameter list (Shape,
// BaseSize, Ratio, RatioPower, Flare, nLength, nDownAngle, nCurve, ...);
// `sides` and the reduced-detail settings are ours (W&P render stems as cones at any resolution).
#include <array>
#include <cstdint>
#include <string_view>

namespace sylva {

// W&P Shape 0..7: how the length of the first-level branches varies up the trunk (the crown
// silhouette). See shape_ratio in tree_skeleton.cpp.
enum class crown_shape : std::uint8_t {
    conical,
    spherical,
    hemispherical,
    cylindrical,
    tapered_cylindrical,
    flame,
    inverse_conical,
    tend_flame,
};

enum class leaf_shape : std::uint8_t {
    broad,           // one leaf card per leaf (texture: ovate leaves)
    needle_cluster,  // narrow cards of needle sprays along the twigs (conifers)
};

// One recursion level of stems: level 0 is the trunk, level 1 its branches, and so on.
struct stem_level_params {
    int branches = 0;                 // W&P nBranches: children per stem of this level's parent
    float length = 1.0f;              // W&P nLength: max child length relative to the parent
    float length_variation = 0.0f;    // W&P nLengthV
    float down_angle_deg = 0.0f;      // W&P nDownAngle: angle from the parent's axis
    float down_angle_variation_deg = 0.0f;  // W&P nDownAngleV; < 0 spreads it along the parent
    float rotate_variation_deg = 0.0f;      // W&P nRotateV, around the phyllotaxis angle
    float curve_deg = 0.0f;           // W&P nCurve: total bend over the stem (+ up, - down)
    float curve_back_deg = 0.0f;      // W&P nCurveBack: bend of the second half (S-curves)
    float curve_variation_deg = 0.0f; // W&P nCurveV
    float taper = 1.0f;               // W&P nTaper in 0..1: radius shrinks linearly to (1 - taper)
    int segments = 4;                 // W&P nCurveRes: segments along the stem
    int sides = 6;                    // vertices around the stem
};

struct tree_params {
    float height_m = 12.0f;             // W&P Scale: trunk length before variation
    float trunk_radius_ratio = 0.02f;   // W&P Ratio: trunk base radius / trunk length
    float ratio_power = 1.3f;           // W&P RatioPower: child radius falls off as length^p
    float base_size = 0.3f;             // W&P BaseSize: bare fraction of the trunk
    float flare = 0.5f;                 // W&P Flare: widening of the trunk base
    float attraction_up = 0.0f;         // W&P AttractionUp: stems bend towards (+) the sky
    // Ours, for shrubs: several level-0 stems rise from the ground instead of one trunk, leaning
    // out by ground_stem_lean_deg (± a third) and starting within ground_stem_spread_m of the origin.
    int ground_stems = 1;
    float ground_stem_lean_deg = 0.0f;
    float ground_stem_spread_m = 0.0f;
    crown_shape shape = crown_shape::spherical;
    int levels = 3;                     // W&P Levels, 2..4 including the trunk
    std::array<stem_level_params, 4> level{};
    float phyllotaxis_deg = 137.5f;     // golden angle between successive children and leaves
    int leaves_per_stem = 8;            // W&P Leaves: per stem of the last level
    float leaf_length_m = 0.15f;        // W&P LeafScale
    float leaf_width_ratio = 0.6f;      // W&P LeafScaleX
    float leaf_down_angle_deg = 50.0f;  // angle of a leaf from its stem
    float leaf_tilt_variation_deg = 30.0f;  // random roll of the leaf card around its own axis
    leaf_shape leaf = leaf_shape::broad;
    // Stem levels meshed as bark (trunk = 1). Finer stems get no geometry of their own: they only
    // carry the leaf cards, which hide them anyway (the budget goes to leaves instead).
    int bark_levels = 4;

    // Reduced detail: fewer sides and segments, no geometry for the last stem level, and
    // leaf_quality times the leaves at 1/sqrt(leaf_quality) the size (W&P's "degradation at
    // range": fewer, larger leaves at constant total leaf area).
    float reduced_leaf_quality = 0.25f;
    float reduced_segment_ratio = 0.4f;  // fraction of each level's segments kept
    float reduced_sides_ratio = 0.5f;    // fraction of each level's sides kept (>= 3)
    int reduced_bark_levels = 4;         // stem levels meshed as bark at reduced detail

    // Far detail: the same rule taken further (trunk only, a few dozen large cards).
    float far_leaf_quality = 0.05f;
    float far_segment_ratio = 0.15f;
    float far_sides_ratio = 0.0f;  // clamped to 3 sides
    int far_bark_levels = 1;
};

// The names generate_tree accepts as presets.
inline constexpr std::array<std::string_view, 4> k_tree_preset_names = {"broadleaf", "broadleaf_hd", "conifer",
                                                                         "shrub"};

// Parameters of a named generator (one of k_tree_preset_names); throws std::invalid_argument
// naming the unknown generator and the valid names.
tree_params tree_preset(std::string_view generator);

}  // namespace sylva
