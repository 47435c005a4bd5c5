#pragma once
// What the device spends on each unit of shader work, so the auto ladder can cost a rung from
// what it makes the device do (issue 21 item 3: "each rung's cost comes from the device
// calibration"). A rung's table (app/rung_tables.h) counts, per projected size, the vertex and
// fragment shader invocations it adds to the view passes and to the shadow pass; its cost is
//
//     t = c_v · (vertices + shadow vertices) + c_f · fragments + c_s · shadow fragments
//
// Why invocations and not triangles and covered pixels: on llvmpipe a plant's cost is mostly
// shader work, and its count differs from the primitives a rung draws by large, rung-dependent
// factors. A full oak at 512 px shades 1.6 M fragments for the 65,000 pixels it covers (its
// leaves overlap and are alpha-tested, so depth does not spare them); its 6,640 triangles run
// 12,200 vertex invocations; a crossed billboard 8 vertices and 120,000 fragments. Costed by
// triangles alone (the device calibration's triangle path, 0.69 µs each), a frame of the auto
// ladder was predicted at 986 ms and took 293; one of crossed billboards at 46 and took 57.
//
// The three coefficients come from timing frames of calibration triangles whose invocations the
// device counts (systems/render/shader_work_calibration.h): tiny, small and large triangles in
// the view, large ones into a shadow map.
#include <stdexcept>
#include <vector>

namespace sylva {

struct shader_work_costs {
    double vertex_us = 0.0;           // c_v: per vertex shader invocation, view or shadow
    double fragment_us = 0.0;         // c_f: per fragment shader invocation in the view passes
    double shadow_fragment_us = 0.0;  // c_s: per fragment shader invocation in the shadow pass

    double cost_us(double vertices, double fragments, double shadow_vertices, double shadow_fragments) const {
        return vertex_us * (vertices + shadow_vertices) + fragment_us * fragments +
               shadow_fragment_us * shadow_fragments;
    }
};

// One calibration measurement: what drawing a batch of primitives more added to a frame, its
// time (µs, with the standard error of that time) and the invocations it added.
struct work_sample {
    double us = 0.0;
    double error_us = 0.0;
    double vertices = 0.0;  // view and shadow
    double fragments = 0.0;
    double shadow_fragments = 0.0;
};

struct work_calibration_refused : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Least squares of t = c_v·V + c_f·F + c_s·S through the samples (at least three whose counts
// are independent), each residual relative to its sample's time. Refuses (work_calibration_refused, naming the figures) when a sample's time
// is not 5 standard errors above zero, when the counts cannot separate the three coefficients,
// or when a coefficient comes out negative (a timer that cannot be trusted; the caller then costs
// rungs by their triangles).
shader_work_costs fit_shader_work(const std::vector<work_sample>& samples);

}  // namespace sylva
