// `sylva lodf-quality` (issue 23's image quality at equal leaf count): one row per leaf share and
// size, and at 100 % LoDF and leaf shrink both draw the whole plant, so their figures agree and
// stand at the rendering's own distance from the supersampled reference; bad input exits 2.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "run_sylva.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

TEST(lodf_quality_command, at_every_leaf_lodf_and_leaf_shrink_are_the_full_plant) {
    const fs::path dir = test::fresh_temp_dir("lodf_quality");
    const fs::path json = dir / "q.json";
    const test::command_result r = test::run_sylva("lodf-quality shrub --leaves 50,100 --json " + json.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(json);
    std::stringstream text;
    text << in.rdbuf();
    const auto rows = nlohmann::json::parse(text.str());
    ASSERT_EQ(rows.size(), 2u * 2 + 2u * 2) << rows.dump(2);  // 2 shares and 2 mesh levels, at 2 sizes
    for (const auto& row : rows) {
        if (row["level"] != "100 %") continue;
        // The same triangles in another order (clusters against a random order): equal but for
        // which of two overlapping leaves the depth test keeps.
        for (const char* metric : {"flip", "ssim", "iou"})
            EXPECT_NEAR(row["lodf"][metric].get<double>(), row["rival_quality"][metric].get<double>(), 1e-4)
                << metric << "\n" << row.dump(2);
        EXPECT_GT(row["lodf"]["iou"].get<double>(), 0.9) << row.dump(2);
    }
    for (const auto& row : rows) {
        if (row["level"] == "50 %") {
            EXPECT_LT(row["lodf"]["iou"].get<double>(), 0.999) << "half the leaves do change the plant";
        }
    }
    EXPECT_EQ(test::run_sylva("lodf-quality shrub --leaves 0").exit_code, 2);
    EXPECT_EQ(test::run_sylva("lodf-quality no_such_plant").exit_code, 2);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
