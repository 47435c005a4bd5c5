// Stress: degenerate model input through the importer (NaN and infinite positions rejected,
// zero-area triangles dropped) and the generated presets (no zero-area triangles). The glTF
// fixture tests of the same rules are in tests/models/degenerate_input_test.cpp.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "app/stress/stress_checks.h"
#include "models/generate/plant_library.h"
#include "stress_support.h"

namespace sylva {
namespace {

TEST(degenerate_input_stress, non_finite_positions_are_rejected_and_zero_area_triangles_dropped) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("sylva_stress_degenerate_" + std::to_string(::getpid()));
    const auto rows = check_degenerate_models(dir);
    std::filesystem::remove_all(dir);
    ASSERT_EQ(rows.size(), 4u + k_plant_presets.size());  // NaN, +inf, -inf, zero area, presets
    testing::expect_all_pass(rows);
    // The error names the vertex and its value; the three added zero-area triangles are dropped.
    EXPECT_NE(testing::row_named(rows, "glTF vertex y = nan")
                  .detail.find("nan_vertex.glb: mesh 'grass' primitive 0: vertex "),
              std::string::npos);
    EXPECT_NE(testing::row_named(rows, "glTF vertex y = -inf").detail.find(", -inf, "),
              std::string::npos);
    EXPECT_EQ(testing::row_named(rows, "glTF zero-area").value, 3.0);
    for (const auto preset : k_plant_presets)
        EXPECT_EQ(testing::row_named(rows, "preset " + std::string(preset)).value, 0.0);
}

}  // namespace
}  // namespace sylva
