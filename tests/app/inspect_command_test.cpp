// `sylva inspect` (issue 3 item 4): triangles, leaves, branches, materials, bounds and units per
// level of a glTF plant; a missing or broken file exits 2 naming it.
#include <gtest/gtest.h>

#include "run_sylva.h"
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace sylva {
namespace {

namespace fs = std::filesystem;

using result = test::command_result;

result run(const std::string& arguments) { return test::run_sylva(arguments); }

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(inspect_command, prints_every_level_of_an_exported_plant) {
    const fs::path dir = test::fresh_temp_dir("inspect");
    const fs::path file = dir / "tree.glb";
    ASSERT_EQ(run("plant broadleaf --seed 2 --texture-size 64 --out " + file.string()).exit_code,
              0);
    const result r = run("inspect " + file.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* part : {"tree.glb", "units: metres", "branches: none", "materials: 2", "bark",
                             "leaf", "triangles", "leaves", "bounds", "full", "reduced", "far"})
        EXPECT_TRUE(has(r.output, part)) << part << "\n" << r.output;
    fs::remove_all(dir);
}

TEST(inspect_command, missing_broken_and_foreign_files_exit_2_naming_the_file) {
    const fs::path dir = test::fresh_temp_dir("inspect_bad");
    const result missing = run("inspect " + (dir / "absent.glb").string());
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_TRUE(has(missing.output, "absent.glb")) << missing.output;
    std::ofstream(dir / "garbage.glb") << "glTF this is not";
    const result garbage = run("inspect " + (dir / "garbage.glb").string());
    EXPECT_EQ(garbage.exit_code, 2);
    EXPECT_TRUE(has(garbage.output, "garbage.glb")) << garbage.output;
    std::ofstream(dir / "tree.obj") << "v 0 0 0\n";
    EXPECT_EQ(run("inspect " + (dir / "tree.obj").string()).exit_code, 2);
    EXPECT_EQ(run("inspect").exit_code, 2);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
