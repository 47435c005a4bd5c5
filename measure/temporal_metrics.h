#pragma once
// Error measures along a camera path, which a single frame's error cannot show:
//
// - popping: how much the error image changes from one frame to the next. With E_t = Y(test_t)
//   - Y(reference_t) per pixel (Rec. 709 luma of the stored 8-bit values), a frame's score is
//   the mean of |E_t - E_(t-1)|. This is "the frame-to-frame change of the LOD image minus that
//   of the reference" (issue 4): motion that the reference shows too cancels, a representation
//   switch or a flickering far plant does not.
// - lighting jump: how a plant's colour changes over a transition between representations,
//   beyond the reference's change over the same frames. Per plant, the mean colour of the pixels
//   its ID covers; over a window from frame a to frame b, |(C_test,b - C_test,a) - (C_ref,b -
//   C_ref,a)|, the Euclidean RGB distance in 8-bit units. Which frames bound a transition is
//   measure/transition_windows.h's business; lighting_jump() is the formula.
//
// Pure CPU, deterministic; all inputs of one call have the same size (std::invalid_argument
// otherwise).
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "models/image/image.h"

namespace sylva {

// Mean |E_t - E_(t-1)| in 8-bit luma units (0..255).
double popping_score(const image_rgba8& test, const image_rgba8& test_previous, const image_rgba8& reference,
                     const image_rgba8& reference_previous);

// The mean colour of each ID's pixels (0 = no plant, not included).
struct plant_color {
    double r = 0.0, g = 0.0, b = 0.0;  // mean, 8-bit units
    std::uint32_t pixels = 0;
};
using plant_colors = std::unordered_map<std::uint32_t, plant_color>;
plant_colors mean_plant_colors(const image_rgba8& image, const std::vector<std::uint32_t>& ids);

// The lighting jump of one plant between two frames (see above); the caller decides which
// frames bound a transition and requires enough pixels in all four colours.
double lighting_jump(const plant_color& test_before, const plant_color& test_after, const plant_color& reference_before,
                     const plant_color& reference_after);

// A 0/1 mask of the nonzero IDs (for coverage_iou).
std::vector<std::uint8_t> plant_mask(const std::vector<std::uint32_t>& ids);

}  // namespace sylva
