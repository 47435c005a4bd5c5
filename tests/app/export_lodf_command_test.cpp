// `sylva export-lodf` and the LoDF part of `sylva inspect` (issue 23 item 4): a plant's foliage at
// any leaf count as glTF the Khronos validator accepts, with its trunk; the same input gives the
// same bytes; bad models and leaf counts exit 2 naming the problem.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "run_sylva.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

using result = test::command_result;

result run(const std::string& arguments) { return test::run_sylva(arguments); }

using test::bytes_of;

// The number after `label` in a report line ("2274 triangles" -> 2274).
long number_before(const std::string& text, const std::string& label) {
    std::smatch m;
    if (!std::regex_search(text, m, std::regex("([0-9]+) " + label))) return -1;
    return std::stol(m[1]);
}

TEST(export_lodf_command, writes_the_foliage_at_a_leaf_count_with_the_trunk) {
    const fs::path dir = test::fresh_temp_dir("export_lodf");
    const fs::path half = dir / "half.glb", all = dir / "all.glb";
    const result r = run("export-lodf broadleaf --texture-size 64 --leaves 50% --out " + half.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("written (50.0 %)"), std::string::npos) << r.output;
    const result whole = run("export-lodf broadleaf --texture-size 64 --leaves 100% --out " + all.string());
    ASSERT_EQ(whole.exit_code, 0) << whole.output;
    // Half the leaves, each a two-triangle card or made quad: fewer triangles, the trunk kept.
    const long half_triangles = number_before(r.output, "triangles"), all_triangles = number_before(whole.output, "triangles");
    ASSERT_GT(all_triangles, 0) << whole.output;
    EXPECT_LT(half_triangles, all_triangles);
    const result inspected = run("inspect broadleaf --texture-size 64");
    ASSERT_EQ(inspected.exit_code, 0) << inspected.output;
    std::smatch full;
    ASSERT_TRUE(std::regex_search(inspected.output, full, std::regex("full +([0-9]+)"))) << inspected.output;
    EXPECT_EQ(all_triangles, std::stol(full[1])) << "100 % is the full mesh, triangle for triangle";
    for (const fs::path& file : {half, all}) {
        if (const auto report = test::validate_gltf(file)) {
            EXPECT_EQ((*report)["issues"]["numErrors"], 0) << report->dump(2);
        }
    }
    const fs::path again = dir / "again.glb";
    ASSERT_EQ(run("export-lodf broadleaf --texture-size 64 --leaves 50% --out " + again.string()).exit_code, 0);
    EXPECT_EQ(bytes_of(half), bytes_of(again));
    fs::remove_all(dir);
}

TEST(export_lodf_command, inspect_prints_the_structure_and_its_storage_against_eq_9) {
    const result r = run("inspect conifer --texture-size 64");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* what : {"LoDF (Rebollo 2006)", "leaves L", "collapses", "clusters G", "Eq. 9's 6.25 V"})
        EXPECT_NE(r.output.find(what), std::string::npos) << what << " in " << r.output;
}

TEST(export_lodf_command, bad_models_and_leaf_counts_exit_2_naming_the_problem) {
    const fs::path dir = test::fresh_temp_dir("export_lodf_bad");
    const std::string out = " --out " + (dir / "x.glb").string();
    result r = run("export-lodf broadleaf --texture-size 64 --leaves 120%" + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("--leaves '120%'"), std::string::npos) << r.output;
    r = run("export-lodf broadleaf --texture-size 64 --leaves many" + out);
    EXPECT_EQ(r.exit_code, 2);
    r = run("export-lodf oak_tree" + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("'oak_tree' is neither a preset"), std::string::npos) << r.output;
    r = run("export-lodf " + (dir / "missing.glb").string() + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("file not found"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "x.glb"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
