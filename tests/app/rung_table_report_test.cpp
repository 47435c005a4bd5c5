// `sylva bake --print-tables`' text (app/rung_table_report.h) from hand-made tables.
#include "app/rung_table_report.h"

#include <gtest/gtest.h>

#include <vector>

namespace sylva {
namespace {

TEST(rung_table_report, prints_error_per_plant_pixel_and_both_costs_per_rung) {
    rung_budget budget;
    species_rung_tables oak;
    oak.plant_pixels.fill(400.0f);
    oak.plant_pixels[0] = 0.0f;  // the plant covers no pixel at 2 px
    rung_table mesh;
    mesh.rung = representation::mesh_full;
    mesh.error.fill(10.0f);  // 10 over 400 pixels: 0.0250 a pixel
    mesh.cost_us.fill(1234.5f);
    mesh.shadow_cost_us.fill(220.3f);
    rung_table crossed;
    crossed.rung = representation::crossed_billboard;
    crossed.error.fill(60.0f);  // 0.1500 a pixel
    crossed.cost_us.fill(1.3f);
    crossed.shadow_cost_us.fill(24.0f);
    oak.rungs = {mesh, crossed};
    budget.tables = {oak, oak};
    const std::vector<std::string> names{"oak"};
    const std::string text = rung_table_report("woods", names, budget);
    EXPECT_NE(text.find("\noak: error per plant pixel"), std::string::npos) << text;
    EXPECT_NE(text.find("\nspecies 1: error per plant pixel"), std::string::npos)
        << text;  // past the names
    EXPECT_NE(text.find("        2px"), std::string::npos) << text;
    EXPECT_NE(text.find("      512px"), std::string::npos) << text;
    const auto row = [&](const std::string& label) {
        const std::size_t at = text.find(label);
        return at == std::string::npos ? std::string() : text.substr(at, text.find('\n', at) - at);
    };
    EXPECT_EQ(row("mesh_full          error"),
              "mesh_full          error          n/a      0.0250      0.0250      0.0250      "
              "0.0250      0.0250      0.0250      0.0250      0.0250");
    EXPECT_NE(row("crossed_billboard  error").find("0.1500"), std::string::npos) << text;
    EXPECT_NE(text.find("view        1234.5"), std::string::npos) << text;
    EXPECT_NE(text.find("shadow       220.3"), std::string::npos) << text;
    EXPECT_NE(text.find("view           1.3"), std::string::npos) << text;
}

TEST(rung_table_report, a_ladder_switching_by_size_has_no_tables) {
    EXPECT_EQ(rung_table_report("tiny", {}, rung_budget{}),
              "'tiny' switches its rungs by projected size: no rung tables\n");
}

}  // namespace
}  // namespace sylva
