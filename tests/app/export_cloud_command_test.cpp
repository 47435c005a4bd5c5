// `sylva export-cloud` (issue 6 item 3): a preset and an imported .glb both export a billboard
// cloud the Khronos validator accepts, the report names what was baked, the same input gives the
// same bytes, and bad models or options exit 2 naming the problem.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "run_sylva.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

using result = test::command_result;

result run(const std::string& arguments) { return test::run_sylva(arguments); }

using test::bytes_of;

TEST(export_cloud_command, exports_a_preset_and_reports_the_bake) {
    const fs::path dir = test::fresh_temp_dir("export_cloud_preset");
    const fs::path out = dir / "shrub_cloud.glb";
    const result r = run("export-cloud shrub --seed 2 --texture-size 64 --clusters 12 --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    ASSERT_TRUE(fs::exists(out));
    for (const char* what : {"clusters (hierarchy", "billboards", "atlas 512 x 256", "min-volume/PCA", "bake"})
        EXPECT_NE(r.output.find(what), std::string::npos) << what << " in " << r.output;
    if (const auto report = test::validate_gltf(out)) {
        EXPECT_EQ((*report)["issues"]["numErrors"], 0) << report->dump(2);
        EXPECT_EQ((*report)["info"]["materialCount"], 1);
    }
    const fs::path again = dir / "again.glb";
    ASSERT_EQ(run("export-cloud shrub --seed 2 --texture-size 64 --clusters 12 --out " + again.string()).exit_code, 0);
    EXPECT_EQ(bytes_of(out), bytes_of(again));
    fs::remove_all(dir);
}

TEST(export_cloud_command, exports_an_imported_glb_with_the_geometric_clustering) {
    const fs::path dir = test::fresh_temp_dir("export_cloud_import");
    const fs::path plant = dir / "broadleaf.glb";
    ASSERT_EQ(run("plant broadleaf --texture-size 64 --out " + plant.string()).exit_code, 0);
    const fs::path out = dir / "cloud.glb";
    const result r = run("export-cloud " + plant.string() + " --texture-size 64 --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("clusters (geometric)"), std::string::npos) << r.output;
    if (const auto report = test::validate_gltf(out)) {
        EXPECT_EQ((*report)["issues"]["numErrors"], 0) << report->dump(2);
    }
    fs::remove_all(dir);
}

TEST(export_cloud_command, bad_models_and_options_exit_2_and_name_the_problem) {
    const fs::path dir = test::fresh_temp_dir("export_cloud_bad");
    const std::string out = " --out " + (dir / "x.glb").string();
    result r = run("export-cloud oak" + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("'oak'"), std::string::npos) << r.output;
    r = run("export-cloud " + (dir / "missing.glb").string() + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("missing.glb"), std::string::npos) << r.output;
    EXPECT_EQ(run("export-cloud shrub").exit_code, 2);  // no --out
    EXPECT_EQ(run("export-cloud shrub --clusters 0" + out).exit_code, 2);
    EXPECT_EQ(run("export-cloud shrub --method octree" + out).exit_code, 2);
    r = run("export-cloud grass --method hierarchy --texture-size 16" + out);
    EXPECT_EQ(r.exit_code, 0) << r.output;  // generated plants have a hierarchy
    r = run("export-cloud --help");
    EXPECT_EQ(r.exit_code, 0);
    for (const char* option : {"--clusters", "--method", "--level", "--out"})
        EXPECT_NE(r.output.find(option), std::string::npos) << option;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
