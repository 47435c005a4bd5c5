// The viewer's tuning panel writes Luft 2007's parameters back into the scenario file
// (app/implicit_tuning.h): only the tuned species' implicit object changes, the other keys keep
// their values and their order, the file still loads, and a bad file or index is named.
#include "app/implicit_tuning.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scenarios/scenario_loader.h"

namespace sylva {
namespace {

std::string read_all(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

TEST(implicit_tuning, write_back_changes_only_the_species_implicit_object) {
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "sylva_tuning_test.json";
    {
        std::ofstream out(file);
        out << R"({"name": "t", "fps": 12, "species": [
  {"name": "b", "generator": "broadleaf", "lighting": "implicit"},
  {"name": "a", "generator": "conifer", "implicit": {"rho_m": 2}}],
 "populations": [{"species": "b", "count": 3}], "frames": 4})";
    }
    implicit_lighting_settings v;
    v.rho_m = 1.25f;
    v.tau = 3.5f;
    v.ka_min = 0.1f;
    v.exponent = 2.0f;
    v.population = true;
    v.ambient_from = "density";
    v.depth_min_m = 0.75f;
    write_implicit_settings(file, 1, v);
    const std::string text = read_all(file);
    // Key order kept: "fps" before "frames" (a sorted writer would swap them).
    EXPECT_LT(text.find("\"fps\""), text.find("\"frames\""));
    const scenario s = load_scenario_file(file);
    EXPECT_EQ(s.species[0].implicit, implicit_lighting_settings{});  // untouched
    EXPECT_EQ(s.species[1].implicit, v);
    EXPECT_EQ(s.species[1].generator, "conifer");
    EXPECT_EQ(s.populations[0].count, 3u);
    EXPECT_EQ(s.frames, 4u);

    try {
        write_implicit_settings(file, 5, v);
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/species/5"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
    EXPECT_EQ(read_all(file), text);  // a refused write changes nothing
    std::filesystem::remove(file);
    EXPECT_THROW(write_implicit_settings(file, 0, v), std::runtime_error);
}

}  // namespace
}  // namespace sylva
