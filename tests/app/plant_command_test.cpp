// `sylva plant` (issue 3 item 4): --list names the presets, every preset exports a .glb the
// Khronos validator accepts, bad species or options exit 2.
#include <gtest/gtest.h>

#include "run_sylva.h"
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "models/gltf/gltf_tinygltf.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

using result = test::command_result;
using test::run_command;

result run(const std::string& arguments) { return test::run_sylva(arguments); }

std::vector<std::string> presets() {
    std::vector<std::string> names;
    std::istringstream lines(run("plant --list").output);
    for (std::string line; std::getline(lines, line);)
        if (!line.empty()) names.push_back(line);
    return names;
}

TEST(plant_command, list_names_the_presets) {
    const result r = run("plant --list");
    EXPECT_EQ(r.exit_code, 0);
    for (const char* name : {"broadleaf", "conifer"})
        EXPECT_NE(r.output.find(name), std::string::npos) << r.output;
    EXPECT_GE(presets().size(), 6u) << r.output;
}

TEST(plant_command, writes_a_glb_per_level_and_the_same_seed_gives_the_same_bytes) {
    const fs::path dir = test::fresh_temp_dir("plant_levels");
    std::uintmax_t previous = 0;
    for (const char* lod : {"far", "reduced", "full"}) {
        const fs::path out = dir / (std::string(lod) + ".glb");
        const result r = run("plant broadleaf --seed 4 --texture-size 64 --lod " +
                             std::string(lod) + " --out " + out.string());
        ASSERT_EQ(r.exit_code, 0) << r.output;
        ASSERT_TRUE(fs::exists(out));
        EXPECT_GT(fs::file_size(out), previous) << lod;  // finer levels are bigger
        previous = fs::file_size(out);
    }
    ASSERT_EQ(
        run("plant broadleaf --seed 4 --texture-size 64 --out " + (dir / "again.glb").string())
            .exit_code,
        0);
    const auto bytes = [](const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    EXPECT_EQ(bytes(dir / "again.glb"), bytes(dir / "full.glb"));
    fs::remove_all(dir);
}

TEST(plant_command, bad_species_and_options_exit_2) {
    const result unknown = run("plant baobab --out /tmp/x.glb");
    EXPECT_EQ(unknown.exit_code, 2);
    EXPECT_NE(unknown.output.find("baobab"), std::string::npos) << unknown.output;
    EXPECT_NE(unknown.output.find("broadleaf"), std::string::npos) << unknown.output;
    EXPECT_EQ(run("plant broadleaf").exit_code, 2);  // no --out
    EXPECT_EQ(run("plant broadleaf --lod medium --out /tmp/x.glb").exit_code, 2);
    EXPECT_EQ(run("plant broadleaf --seed minus --out /tmp/x.glb").exit_code, 2);
}

TEST(plant_command, every_preset_exports_valid_gltf) {
    const fs::path tools = fs::path(SYLVA_SOURCE_DIR) / "tests" / "tools";
    if (run_command("node --version").exit_code != 0) GTEST_SKIP() << "node is not installed";
    if (!fs::exists(tools / "node_modules" / "gltf-validator"))
        GTEST_SKIP() << "gltf-validator is not installed: run `./sylva test` or `cd tests/tools && "
                        "npm install`";
    const fs::path dir = test::fresh_temp_dir("plant_valid");
    for (const std::string& species : presets()) {
        SCOPED_TRACE(species);
        const fs::path out = dir / (species + ".glb");
        const result r = run("plant " + species + " --texture-size 64 --out " + out.string());
        ASSERT_EQ(r.exit_code, 0) << r.output;
        const result v =
            run_command("node " + (tools / "validate_gltf.mjs").string() + " " + out.string());
        const auto report = nlohmann::json::parse(v.output, nullptr, false);
        ASSERT_FALSE(report.is_discarded()) << v.output;
        EXPECT_EQ(report["issues"]["numErrors"], 0) << report["issues"].dump(2);
        EXPECT_EQ(v.exit_code, 0);
    }
    fs::remove_all(dir);
}

// Luft 2007 exported (issue 22 item 6): --implicit bakes the illumination; the file keeps unit
// normals (the validator checks them) and carries k_a as a grey COLOR_0 on every vertex, some
// of it darker than white (the crown's inside) and none above.
TEST(plant_command, implicit_writes_unit_normals_and_the_ambient_as_colour_0) {
    const fs::path dir = test::fresh_temp_dir("plant_implicit");
    const fs::path out = dir / "oak.glb";
    const result r = run("plant broadleaf --implicit --texture-size 64 --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("mean k_a"), std::string::npos) << r.output;
    if (const auto report = test::validate_gltf(out)) {
        EXPECT_EQ((*report)["issues"]["numErrors"], 0) << report->dump(2);
    }
    tinygltf::TinyGLTF loader = make_gltf_loader();
    tinygltf::Model model;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, out.string())) << error;
    ASSERT_FALSE(model.meshes.empty());
    for (const tinygltf::Primitive& p : model.meshes[0].primitives) {
        ASSERT_TRUE(p.attributes.count("COLOR_0")) << "every primitive carries the ambient";
        const tinygltf::Accessor& colour = model.accessors[std::size_t(p.attributes.at("COLOR_0"))];
        const tinygltf::Accessor& position = model.accessors[std::size_t(p.attributes.at("POSITION"))];
        EXPECT_EQ(colour.count, position.count);
        EXPECT_EQ(colour.type, TINYGLTF_TYPE_VEC3);
        const tinygltf::BufferView& view = model.bufferViews[std::size_t(colour.bufferView)];
        const auto* grey = reinterpret_cast<const float*>(&model.buffers[0].data[view.byteOffset + colour.byteOffset]);  // NOLINT
        float lowest = 1.0f, highest = 0.0f;
        for (std::size_t i = 0; i < colour.count * 3; ++i) lowest = std::min(lowest, grey[i]), highest = std::max(highest, grey[i]);
        EXPECT_LT(lowest, 0.9f);
        EXPECT_LE(highest, 1.0f);
    }
    // Without --implicit there is no ambient to carry.
    const fs::path plain = dir / "plain.glb";
    ASSERT_EQ(run("plant broadleaf --texture-size 64 --out " + plain.string()).exit_code, 0);
    tinygltf::Model plain_model;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&plain_model, &error, &warning, plain.string())) << error;
    EXPECT_FALSE(plain_model.meshes[0].primitives[0].attributes.count("COLOR_0"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
