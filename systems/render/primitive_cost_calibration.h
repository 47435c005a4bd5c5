#pragma once
// What a triangle, a point and a line cost on this GL device, measured (issue 5, item 6). The
// paper's point/line selection assumes a triangle costs about three points (Deussen 2002 §4.1);
// on llvmpipe a point costs about half a triangle and a wide line several triangles, so a
// selection that trusted the paper would pick representations that are slower where Sylva runs.
//
// The calibration draws the same number of leaf-sized triangles, d'-sized splats and d'-wide
// lines through the renderer's own opaque pass (the programs every frame uses; soft splats add
// their visibility and blend passes, drawn after the sky), in front of a
// camera like the scenario's, times each on the GPU timer, subtracts an empty frame, and takes
// the median of a few repetitions. Ratios are rounded to quarter steps so noise does not move
// thresholds from run to run; the result is cached per device and setting by the caller.
#include "systems/point_line_lod.h"
#include "systems/render/renderer.h"

namespace sylva::render {

struct calibration_settings {
    std::uint32_t primitives = 40000;  // of each kind per draw
    int repetitions = 5;
    float sample_distance_px = 1.0f;  // d': splat and line size
    float splat_factor = 1.3f;
    splat_style splats = splat_style::soft;  // soft splats are timed with their two passes
    float triangle_px = 4.0f;  // edge length of the calibration triangles on screen
};

// Raw medians, milliseconds per million primitives (for the report), and the rounded costs.
struct calibration_result {
    double triangle_ms_per_million = 0.0;
    double point_ms_per_million = 0.0;
    double line_ms_per_million = 0.0;
    primitive_costs costs;
};

// Adds its three meshes to the renderer's pool, renders 4 × repetitions frames into the
// renderer's target (overwriting its last image) and returns the costs. GL thread only.
calibration_result calibrate_primitive_costs(renderer& r, const calibration_settings& settings);

// Rounds a measured cost ratio to the nearest quarter in [0.25, 64] (the cached form).
double quantize_cost_ratio(double ratio);

}  // namespace sylva::render
