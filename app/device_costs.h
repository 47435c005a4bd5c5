#pragma once
// The primitive cost model of the GL device Sylva draws on (lod/primitive_cost_model.h),
// calibrated once per device and kept in the bake cache: the selection of points, lines and
// triangles (Deussen 2002 §4.1, §5.3) then weighs them by what they cost here, for any d'.
//
// A device is the CPU model and its hardware threads, llvmpipe's rasteriser threads
// (LP_NUM_THREADS) when set, the GL renderer and version, and the frame size (on a CPU
// rasteriser a pixel costs more in a frame that does not fit the caches: a triangle took 0.5 µs
// at 320x180 and 1.1 µs at 960x540): the cache key names them all. A
// calibration the fit refused (a timer it cannot trust) is kept too, with its reason, so a run
// does not measure again every time; it falls back to the paper's costs and says so. `sylva
// calibrate --force` measures again.
#include <optional>
#include <string>

#include "models/cache/bake_cache.h"
#include "lod/primitive_cost_model.h"
#include "lod/shader_work_costs.h"
#include "systems/render/gl_context.h"
#include "systems/render/primitive_cost_calibration.h"
#include "systems/render/renderer.h"
#include "systems/render/shader_work_calibration.h"

namespace sylva {

// What the device is, as the cache key's text (also printed by `sylva calibrate`).
std::string describe_cost_device(const render::gl_context& context, const render::renderer& r,
                                 float splat_factor);

struct device_calibration {
    std::optional<primitive_cost_model> model;  // none: refused
    std::string refusal;                        // why, when refused
    bool measured_now = false;
    std::optional<render::calibration_result> measurement;  // when measured now

    // The model's costs for quality `q`, or the paper's (primitive_costs{}) when refused.
    primitive_costs costs_for(const point_line_quality& q) const;
};

// From the cache, or measured on `r` now (and stored) when absent or when `force`, with
// `settings` (its timer: the device's, render::device_frame_timer, when empty). The renderer's
// target is overwritten when it measures. GL thread only.
device_calibration device_cost_model(render::renderer& r, const render::gl_context& context,
                                     bake_cache& cache, float splat_factor, bool force = false,
                                     const render::calibration_settings& settings = {});

// What shader work costs on this device (lod/shader_work_costs.h), from the cache or measured on
// `r` now (and stored) when absent or when `force`; the auto ladder costs its rungs with it. A
// refusal (no invocation counts, a timer it cannot trust) is cached too, with its reason, and
// the rungs are then costed by their triangles; a renderer without shadow maps measures nothing
// and caches nothing (the refusal is its own, not the device's). GL thread only.
struct device_work_calibration {
    std::optional<shader_work_costs> costs;
    std::string refusal;
    bool measured_now = false;
    std::optional<render::work_calibration_result> measurement;  // when measured now
};
device_work_calibration device_work_costs(render::renderer& r, const render::gl_context& context, bake_cache& cache,
                                          bool force = false, const render::calibration_settings& settings = {});

}  // namespace sylva
