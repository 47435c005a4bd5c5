// `sylva stress` runs every check, prints the table and exits 0 when all pass.
#include <gtest/gtest.h>

#include <regex>

#include "../app/run_sylva.h"
#include "../gl/gl_test_support.h"

namespace sylva {
namespace {

TEST(stress_command, runs_every_check_and_prints_a_table) {
    SYLVA_REQUIRE_GL();  // the render checks fail without a context
    const auto r = test::run_sylva("stress --threads 2");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(std::regex_search(
        r.output, std::regex(R"((^|\n)check +measured +limit +result\n-+ +-+ +-+ +------\n)")))
        << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex(R"(\n(\d+) checks, \1 passed, 0 failed\n)")))
        << r.output;
    EXPECT_NE(r.output.find("world offset 1e+06 m: frame vs origin"), std::string::npos);
    EXPECT_NE(r.output.find("player at frames 1e6, 1e7"), std::string::npos);
}

TEST(stress_command, help_names_the_checks_and_the_exit_codes) {
    const auto r = test::run_sylva("stress --help");
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.output.find("--threads"), std::string::npos);
    EXPECT_NE(r.output.find("Exit 0 when every check"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace sylva
