#pragma once
// Importance from colour (Deussen 2002 §4.3, future work: colour analysis). The paper sets a
// part's importance by hand and suggests automating it: "objects seem to be important if their
// color is clearly distinguishable from the majority of element colors in a plant". We measure
// that distinction as the CIE 1976 colour difference ΔE*ab between a part's mean texture colour
// and the plant's area-weighted mean colour, in CIELAB because equal ΔE are roughly equally
// visible whatever the hue.
#include <glm/vec3.hpp>
#include <span>

namespace sylva {

// Below this ΔE*ab a part is ordinary; above k_distinct_high it is as important as a petal.
// Measured on the generated plants: leaves differ from their plant's majority colour by under 6,
// brown bark by 25-29, the flower's magenta petals by about 72; a just noticeable difference is
// about 2.3.
constexpr float k_distinct_low = 35.0f;
constexpr float k_distinct_high = 70.0f;
constexpr float k_majority_bin_de = 4.0f;

// Linear sRGB (D65) to CIELAB: the generated textures store linear albedo.
glm::vec3 linear_rgb_to_lab(glm::vec3 rgb);
// CIE76 ΔE*ab between two linear sRGB colours.
float colour_difference(glm::vec3 linear_a, glm::vec3 linear_b);

// "The majority of element colors" (Deussen 2002 §4.3): the weighted medoid of the colours
// (the one with the least weighted ΔE to all others, over colours binned to k_majority_bin_de so
// thousands of leaf cards cost little), then the weighted mean of the colours within
// k_distinct_low of it. A plain mean would not do: a flower's petals, a third of its foliage,
// pull it so far that the leaves sit 28 from it and the petals only 47. Black when every weight
// is 0.
glm::vec3 majority_colour(std::span<const glm::vec3> colours, std::span<const float> weights);

// Deussen 2002 §4.3 (future work: colour analysis):
//   importance = 1 + max(0, petal_importance - 1) * s,
//   s = smoothstep(k_distinct_low, k_distinct_high, ΔE)
// so a part coloured like the plant's majority stays at 1 and a clearly different one (red,
// yellow or white petals on green) reaches petal_importance.
float colour_importance(float delta_e, float petal_importance);

}  // namespace sylva
