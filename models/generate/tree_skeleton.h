#pragma once
// The stem hierarchy of a tree before it becomes triangles: every stem as a polyline of nodes
// with a frame and a radius. Both detail levels of a tree are meshed from the same skeleton, so
// the reduced mesh keeps the crown of the full one.
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "models/generate/tree_params.h"

namespace sylva {

struct stem_node {
    glm::vec3 position{0.0f};
    glm::vec3 tangent{0.0f, 1.0f, 0.0f};  // unit, along the stem
    glm::vec3 normal{1.0f, 0.0f, 0.0f};   // unit, perpendicular to tangent (parallel-transported)
    float radius = 0.0f;
};

struct stem {
    int level = 0;
    int parent = -1;              // index into tree_skeleton::stems, -1 for the trunk
    float length = 0.0f;          // metres along the path
    float offset_in_parent = 0.0f;  // metres from the parent's base to where this stem starts
    std::uint64_t seed = 0;       // this stem's own random stream (leaves derive from it)
    std::vector<stem_node> nodes;  // segments + 1, equally spaced along the path
};

struct tree_skeleton {
    std::vector<stem> stems;  // every parent before its children; the first params.ground_stems
                              // stems (parent -1) rise from the ground; stems[0] is the trunk
};

// W&P ShapeRatio(shape, ratio): branch length factor for a position `ratio` (0 at the top of the
// trunk, 1 at the base of the crown). Values from W&P's shape list.
float shape_ratio(crown_shape shape, float ratio);

// The frame at fraction t in [0, 1] of the way along the stem (linear between nodes).
stem_node sample_stem(const stem& s, float t);

// Recursive stem generation after W&P (stem lengths, radii, child counts, down angles, curves,
// taper and flare). Throws std::invalid_argument for parameters out of range.
tree_skeleton build_tree_skeleton(const tree_params& params, std::uint64_t seed);

}  // namespace sylva
