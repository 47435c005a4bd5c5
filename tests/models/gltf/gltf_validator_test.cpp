// Exported plants against the Khronos glTF validator (npm gltf-validator, installed into
// tests/tools by `./sylva test`): every level must have 0 errors. Skips, saying why, when Node
// or the package is missing.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "models/bake/billboard_cloud.h"
#include "models/gltf/gltf_export.h"
#include "models/generate/plant_library.h"
#include "models/generate/textures.h"
#include "models/generate/tree_generator.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

struct run_result {
    int exit_code = -1;
    std::string output;
};

run_result run(const std::string& command) {
    run_result r;
    FILE* pipe = popen(command.c_str(), "r");
    std::array<char, 4096> buffer{};
    while (pipe && fgets(buffer.data(), int(buffer.size()), pipe)) r.output += buffer.data();
    const int status = pipe ? pclose(pipe) : -1;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

const fs::path k_tools = fs::path(SYLVA_SOURCE_DIR) / "tests" / "tools";

TEST(gltf_validator, exported_plant_levels_have_no_errors) {
    if (run("node --version > /dev/null 2>&1").exit_code != 0)
        GTEST_SKIP() << "node is not installed";
    if (!fs::exists(k_tools / "node_modules" / "gltf-validator"))
        GTEST_SKIP() << "gltf-validator is not installed: run `./sylva test` or `cd tests/tools && "
                        "npm install`";
    plant_model plant;
    plant.name = "broadleaf";
    plant.lods = {generate_tree(tree_preset("broadleaf"), 5, tree_detail::full),
                  generate_tree(tree_preset("broadleaf"), 5, tree_detail::reduced),
                  generate_tree(tree_preset("broadleaf"), 5, tree_detail::far)};
    plant.leaf_texture = generate_leaf_texture("broadleaf", 128);
    plant.bark_texture = generate_bark_texture("broadleaf", 128);
    const fs::path dir =
        fs::temp_directory_path() / ("sylva_gltf_validator_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (const plant_lod lod : {plant_lod::full, plant_lod::reduced, plant_lod::far}) {
        const fs::path file = dir / ("broadleaf_" + std::to_string(int(lod)) + ".glb");
        export_plant_glb(plant, lod, file);
        const run_result r =
            run("node " + (k_tools / "validate_gltf.mjs").string() + " " + file.string() + " 2>&1");
        ASSERT_NE(r.exit_code, 2) << r.output;
        const auto report = nlohmann::json::parse(r.output, nullptr, false);
        ASSERT_FALSE(report.is_discarded()) << r.output;
        EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"].dump(2);
        EXPECT_EQ(r.exit_code, 0);
        EXPECT_EQ(report["info"]["totalTriangleCount"],
                  plant.lods[std::size_t(lod)].triangle_count());
        EXPECT_EQ(report["info"]["materialCount"], 2);
    }
    fs::remove_all(dir);
}

// The billboard cloud export (`sylva export-cloud`): 0 errors, the quads' triangles, one
// material, and both atlas pages embedded (colour and normal).
TEST(gltf_validator, exported_billboard_cloud_has_no_errors) {
    if (run("node --version > /dev/null 2>&1").exit_code != 0) GTEST_SKIP() << "node is not installed";
    if (!fs::exists(k_tools / "node_modules" / "gltf-validator"))
        GTEST_SKIP() << "gltf-validator is not installed: run `./sylva test` or `cd tests/tools && npm install`";
    const plant_model plant = generate_plant_model("shrub", 2, 64);
    billboard_cloud_settings settings = default_billboard_cloud_settings(plant);
    settings.supersampling = 1;
    const billboard_cloud cloud = bake_billboard_cloud(plant, settings);
    const fs::path file = fs::temp_directory_path() / ("sylva_cloud_validator_" + std::to_string(::getpid()) + ".glb");
    export_billboard_cloud_glb(cloud, "shrub", file);
    const run_result r = run("node " + (k_tools / "validate_gltf.mjs").string() + " " + file.string() + " 2>&1");
    fs::remove(file);
    ASSERT_NE(r.exit_code, 2) << r.output;
    const auto report = nlohmann::json::parse(r.output, nullptr, false);
    ASSERT_FALSE(report.is_discarded()) << r.output;
    EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"].dump(2);
    EXPECT_EQ(report["issues"]["numWarnings"], 0) << report["issues"].dump(2);
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_EQ(report["info"]["totalTriangleCount"], cloud.mesh.triangle_count());
    EXPECT_EQ(report["info"]["materialCount"], 1);
    EXPECT_EQ(report["info"]["resources"].size(), 3u) << report["info"]["resources"].dump(2);  // buffer, 2 PNGs
}

}  // namespace
}  // namespace sylva
