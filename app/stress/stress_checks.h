#pragma once
// The numerical stress suite (issue 4): each check pushes one part of Sylva to the edge of its
// number range and reports rows of {what, measured, limit, passed}. `sylva stress` prints them as
// a table; tests/stress/ runs the same functions under CTest (label `stress`) and adds
// hand-checkable assertions on the values.
//
// Six families, one file each in app/stress/ (the tests in tests/stress/ are named alike):
//
//   world offsets     the tiny scene 1e4, 1e5, 1e6 m from the origin renders like the origin;
//                     a camera path there is the origin's path shifted (no jitter)
//                     world_offset_checks.cpp
//   degenerate input  NaN / infinite glTF positions rejected with a named error; zero-area
//                     triangles dropped at import; the presets have none
//                     degenerate_input_checks.cpp
//   point clusters    eco tiles over plants all at one point or on a line: bounded depth, every
//                     plant in one leaf, hierarchical culling equal to flat culling
//                     plant_cluster_checks.cpp
//   extreme light     sun and sky intensity 0 .. 1e12, sun below / on the horizon / at the
//                     zenith, turbidity at its limits: finite SH, finite uniforms, sane images
//                     extreme_light_checks.cpp
//   time              a million and ten million frames: clock, camera and sun without drift
//                     time_drift_checks.cpp
//   extreme LOD       lod_scale 0.01 .. 100, distances 0 .. inf and NaN, scale 0
//                     extreme_lod_checks.cpp
//
// stress_checks.cpp runs them all and prints the table; check_support.h is what they share.
//
// Every check is fast (scenarios/tiny.json-sized scenes at 160x90): the whole suite runs in
// well under a minute on two llvmpipe cores.
#include <filesystem>
#include <string>
#include <vector>

#include "systems/render/gl_context.h"

namespace sylva {

struct stress_row {
    std::string check;     // what was tried, e.g. "world offset 1e6 m: image vs origin"
    std::string measured;  // what came out, as printed
    double value = 0.0;    // the main measured number (for tests); 0 when the row has none
    std::string limit;     // what it must meet, e.g. "> 45 dB, < 1 % px off by > 16"
    bool passed = false;
    std::string detail;  // why it failed, or what else was seen
};

// The tiny scenario (embedded scenarios/tiny.json) the GL checks render, 160x90, by its mesh levels
// (stress::tiny_scenario).
inline constexpr const char* k_stress_scenario = "scenarios/tiny.json";

// Renders tiny.json at world offsets 0, 1e4, 1e5, 1e6 m (x and z) and compares each with the
// origin render: PSNR > 45 dB and < 1 % of pixels with a channel off by more than 16 (only the
// world-pinned shadow texel grid may move; see tests/stress/world_offset_stress_test.cpp).
std::vector<stress_row> check_world_offset_renders(render::gl_context& context, int threads);

// The tiny camera path evaluated for 2,400 frames at offsets 1e4, 1e5, 1e6 m: position minus the
// offset equals the origin path's within 1e-6 m, and the camera-relative view matrices agree
// within 1e-6 (per element; they are rotations, so that is relative).
std::vector<stress_row> check_camera_path_offsets();

// Writes glTF files into `scratch_dir` (from the grass preset through the exporter, one vertex
// made NaN, +inf or -inf, or zero-area triangles appended) and imports them; checks every preset
// at every level for zero-area triangles (models/gltf/gltf_import.h is_zero_area_triangle).
std::vector<stress_row> check_degenerate_models(const std::filesystem::path& scratch_dir);

// Eco tiles (lod/eco_tiles.h) over 2,000 plants at one point, on an axis-parallel line, on a
// diagonal line, and on a tile split line: bounded depth and node count, every plant in exactly
// one leaf; culling with the tiles equals flat culling for every plant.
std::vector<stress_row> check_plant_clusters(int threads);

// Sky model and SH projection with sky intensity 0 .. 1e12, sun elevation -90 .. 90 and
// turbidity 1.7 and 10: every coefficient finite, zero sky gives zero SH, and the SH scales
// linearly with the intensity (relative error < 1e-5).
std::vector<stress_row> check_extreme_sky();

// Renders tiny.json with sun and sky intensity 0 and 1e6 (the scenario's limits) and 1e12
// (through the sun and environment directly), the sun below the horizon, on it and at the
// zenith, turbidity 1.7 and 10: SH, sun colour and radiance finite; the black scene black and
// the 1e6 scene saturated (a NaN in the shader would write black).
std::vector<stress_row> check_extreme_light_renders(render::gl_context& context, int threads);

// A million and ten million frames at 24 fps: the playback clock stepped frame by frame equals
// frame / fps exactly; camera and sun paths evaluated at those times equal direct evaluation;
// a 1 m/s straight path is at t metres with per-frame steps of 1/24 m; beyond the last key the
// pose holds.
std::vector<stress_row> check_time_drift(int threads);

// choose_representation at lod_scale 0.01 .. 100, distances 0, 1e-30, 1e30, inf, NaN and plant
// scale 0: never finer as the distance grows, NaN and inf give the far mesh; the scenario
// loader rejects lod_scale 0.009 and 101 and plays 0.01 and 100.
std::vector<stress_row> check_extreme_lod(int threads);

struct stress_options {
    int threads = 2;
    render::gl_context* context = nullptr;  // null: the GL checks fail with "no GL context"
    std::filesystem::path scratch_dir;      // empty: a folder under the system temp folder
};

// Every check above, in that order.
std::vector<stress_row> run_stress_checks(const stress_options& options);

// The rows as an aligned text table: check, measured, limit, result (and detail for failures).
std::string format_stress_table(const std::vector<stress_row>& rows);

}  // namespace sylva
