#pragma once
// Measures what one vertex shader invocation, one view fragment and one shadow-map fragment cost
// on this GL device (lod/shader_work_costs.h), through the renderer's own passes.
//
// Four shapes are drawn as in the primitive calibration (primitive_cost_calibration.h: N and
// then 2N leaf-sized triangles facing the eye, the difference taken, repetitions interleaved
// and N alternating with 2N): small triangles (4 px legs) and large ones (24 px legs) in the
// view, the large ones into one shadow cascade that covers them, and tiny ones (0.4 px legs)
// in the view. The tiny shape is what most leaf triangles of a plant in a frame are: with
// only the first three a vertex also carried the raster set-up of a 4 px triangle, and came
// out 2.8 times dearer, against a shadow fragment, than frames of mixed rungs showed. The device counts the
// invocations each frame added (render::pass_timer::read_work), so the fit needs no assumption
// about how many fragments a triangle of a size shades. Timed with the device's frame timer
// (process CPU time on a CPU rasteriser, as the primitive calibration, and for its reasons).
#include <optional>
#include <string>

#include "lod/shader_work_costs.h"
#include "systems/render/primitive_cost_calibration.h"
#include "systems/render/renderer.h"

namespace sylva::render {

struct work_calibration_result {
    std::optional<shader_work_costs> costs;  // none when refused
    std::string refusal;                     // why (also when the device cannot count)
    std::vector<work_sample> samples;        // small view, large view, large shadow, tiny view
    double seconds = 0.0;
};

// Adds its two meshes to the renderer's pool and renders into its target (overwriting its last
// image). Refuses without pipeline statistics or without shadow maps (renderer_settings::shadows).
// GL thread only.
work_calibration_result calibrate_shader_work(renderer& r, const calibration_settings& settings = {});

}  // namespace sylva::render
