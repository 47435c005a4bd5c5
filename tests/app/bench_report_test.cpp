// The outputs of `sylva bench` (issue 4, item 3) on a hand-built report: the Pareto front,
// bench.json's schema, bench.csv's columns and quoting, the SVG plot and the markdown summary.
#include "app/bench_report.h"
#include "app/bench_verdict.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace sylva {
namespace {

namespace fs = std::filesystem;

constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();
constexpr double k_inf = std::numeric_limits<double>::infinity();

fs::path temp_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() /
                         ("sylva_bench_report_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

bench_configuration configuration(const std::string& name, const std::string& family, double median,
                                  double min, double max, double flip, double ssim) {
    bench_configuration c;
    c.name = name;
    c.family = family;
    c.description = "the " + family + " configuration";
    c.frames = 120;
    c.frame_ms_median = median;
    c.frame_ms_min = min;
    c.frame_ms_max = max;
    c.frame_ms_rounds = {median};
    c.cpu_ms = {{"select_representation", 0.5}, {"total", median * 0.5}};
    c.gpu_ms = {{"opaque", median * 0.25}, {"total", median * 0.75}};
    c.primitives = {{"triangles", 150000}, {"points", 0}, {"lines", 0}};
    c.upload_bytes = 4096;
    c.peak_memory_mb = 512;
    c.error.perceptual = flip;
    c.error.ssim = ssim;
    c.error.psnr_db = 30.0;
    c.error.rmse = 0.03;
    c.error.coverage_iou = 0.99;
    c.lighting = "normal";
    return c;
}

// FLIP front (by hand): lod_scale_0.5 (4 ms, 0.018) and reference (500 ms, 0). Everything else is
// slower and worse than lod_scale_0.5, or (brute_force, 0.020) just worse.
// 1 - SSIM front: lod_scale_0.5 (0.020), mesh_lod (0.015), brute_force (0.010), reference (0).
bench_report fixture() {
    bench_report r;
    r.scenario = "meadow <dense>";
    r.source = "scenarios/meadow.json";
    r.machine = "Test CPU, 2 hardware threads";
    r.gl_renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    r.threads = 2;
    r.width = 640;
    r.height = 360;
    r.frames = 120;
    r.reference_samples_per_pixel = 9;
    r.lighting_families = {{"normal", "every species lit by its normals", 500, {}}};

    bench_configuration brute =
        configuration("brute_force", "brute_force", 50, 48, 55, 0.020, 0.990);
    brute.cpu_ms = {{"total", 30.5}};
    brute.gpu_ms = {{"total", 45.25}};
    brute.primitives = {{"triangles", 2000000}, {"points", 0}, {"lines", 0}};
    brute.upload_bytes = 1048576;
    brute.peak_memory_mb = 812.5;
    brute.frame_ms_vs_baseline = 8.25;
    brute.error.psnr_db = 38.5;
    brute.error.coverage_iou = 0.999;
    brute.error.popping = 0.1;
    r.configurations.push_back(brute);

    bench_configuration baseline = configuration("baseline", "baseline", 6, 5.5, 7, 0.090, 0.930);
    baseline.quality = 50;  // the named baseline's switch distance
    baseline.error.psnr_db = 27.1;
    baseline.error.transitions = 42;
    baseline.error.transitions_by_kind = {{"switch", 42}};
    baseline.error.transition_frames = 42;
    baseline.error.lighting_jump = 7.5;
    r.configurations.push_back(baseline);

    r.configurations.push_back(configuration("mesh_lod", "mesh_lod", 8, 7.5, 9, 0.025, 0.985));
    bench_configuration lod =
        configuration("lod_scale_0.5", "lod_scale", 4, 3.8, 4.4, 0.018, 0.980);
    lod.quality = 0.5;
    r.configurations.push_back(lod);
    r.configurations.push_back(
        configuration("points \"dense\", far", "points", 5, 4.5, 6, 0.060, 0.950));
    r.configurations.push_back(
        configuration("clouds <&> more", "billboard_cloud", 12, 11, 14, 0.030, 0.970));

    bench_configuration reference =
        configuration("reference", "reference", 500, 490, 520, 0.0, 1.0);
    reference.error.psnr_db = k_inf;
    reference.error.rmse = 0.0;
    reference.error.coverage_iou = 1.0;
    r.configurations.push_back(reference);
    return r;
}

// --- pareto_front ------------------------------------------------------------------------------

TEST(bench_report_pareto_front, keeps_undominated_points_sorted_by_frame_time) {
    //                                 0     1     2     3     4     5      6     7     8
    const std::vector<double> ms = {10.0, 5.0, 20.0, 10.0, 12.0, 3.0, 20.0, 30.0, 50.0};
    const std::vector<double> err = {0.5, 0.8, 0.1, 0.5, 0.6, k_nan, 0.3, 0.1, 0.0};
    // 3 equals 0 (first by index kept); 4 is dominated by 0; 5 has no error; 6 is as fast as 2 but
    // worse; 7 is as good as 2 but slower.
    EXPECT_EQ(pareto_front(ms, err), (std::vector<std::size_t>{1, 0, 2, 8}));
}

TEST(bench_report_pareto_front, equal_points_keep_the_first_by_index_wherever_it_stands) {
    EXPECT_EQ(pareto_front({1.0, 1.0}, {2.0, 2.0}), (std::vector<std::size_t>{0}));
    EXPECT_EQ(pareto_front({9.0, 4.0, 1.0, 4.0}, {0.0, 1.0, 5.0, 1.0}),
              (std::vector<std::size_t>{2, 1, 0}));
    // Same frame time: only the lower error survives, whatever its index.
    EXPECT_EQ(pareto_front({10.0, 10.0}, {0.5, 0.4}), (std::vector<std::size_t>{1}));
}

TEST(bench_report_pareto_front, nan_is_excluded_infinity_is_not_and_sizes_must_match) {
    EXPECT_TRUE(pareto_front({}, {}).empty());
    EXPECT_TRUE(pareto_front({1.0, 2.0}, {k_nan, k_nan}).empty());
    EXPECT_EQ(pareto_front({k_nan, 2.0}, {0.0, 1.0}), (std::vector<std::size_t>{1}));
    // The fastest point is undominated even with an infinite error.
    EXPECT_EQ(pareto_front({1.0, 2.0}, {k_inf, 1.0}), (std::vector<std::size_t>{0, 1}));
    EXPECT_THROW(pareto_front({1.0, 2.0}, {1.0}), std::invalid_argument);
}

// --- bench.json --------------------------------------------------------------------------------

std::set<std::string> keys_of(const nlohmann::json& j) {
    std::set<std::string> keys;
    for (const auto& [key, value] : j.items()) keys.insert(key);
    return keys;
}

TEST(bench_report_json, has_exactly_the_documented_keys_and_inf_psnr_as_a_string) {
    const fs::path dir = temp_dir("json");
    write_bench_json(dir / "bench.json", fixture());
    const nlohmann::json j = nlohmann::json::parse(read_text(dir / "bench.json"));
    EXPECT_EQ(keys_of(j),
              (std::set<std::string>{"scenario", "source", "machine", "gl_renderer", "threads",
                                     "width", "height", "frames", "timing_rounds", "reference",
                                     "lighting_families", "primitive_costs", "configurations",
                                     "verdicts", "partial", "path_frames", "options", "shard", "shards"}));
    EXPECT_EQ(j["timing_rounds"], 1);
    EXPECT_EQ(j["partial"], false);
    EXPECT_EQ(j["scenario"], "meadow <dense>");
    EXPECT_EQ(j["reference"], (nlohmann::json{{"samples_per_pixel", 9}}));
    EXPECT_EQ(j["lighting_families"],
              (nlohmann::json::array({{{"name", "normal"},
                                       {"reference_lit", "every species lit by its normals"},
                                       {"reference_frame_ms_median", 500.0},
                                       {"reference_frame_ms", nlohmann::json::array()}}})));
    ASSERT_EQ(j["configurations"].size(), 7u);
    std::map<std::string, nlohmann::json> by_name;
    for (const auto& c : j["configurations"]) {
        EXPECT_EQ(keys_of(c),
                  (std::set<std::string>{"name", "family", "lighting", "description", "quality", "frames",
                                         "frame_ms", "cpu_ms", "gpu_ms", "primitives",
                                         "upload_bytes", "peak_memory_mb", "primitive_costs",
                                         "error", "on_pareto_front", "selection_inputs_hash", "records"}));
        EXPECT_EQ(keys_of(c["frame_ms"]), (std::set<std::string>{"median", "min", "max", "round_medians",
                                                                  "vs_baseline", "vs_baseline_by_host"}));
        EXPECT_EQ(keys_of(c["records"]), (std::set<std::string>{"frames", "transitions", "transitions_cut_off"}));
        EXPECT_EQ(keys_of(c["error"]),
                  (std::set<std::string>{"psnr", "ssim", "perceptual", "coverage_iou", "popping",
                                         "lighting_jump", "rmse", "transitions"}));
        EXPECT_EQ(c["lighting"], "normal");
        by_name[c["name"]] = c;
    }
    ASSERT_TRUE(by_name.count("brute_force"));
    ASSERT_TRUE(by_name.count("baseline"));
    const nlohmann::json& brute = by_name["brute_force"];
    EXPECT_EQ(brute["frame_ms"], (nlohmann::json{{"median", 50.0},
                                                 {"min", 48.0},
                                                 {"max", 55.0},
                                                 {"round_medians", {50.0}},
                                                 {"vs_baseline", 8.25},
                                                 {"vs_baseline_by_host", nlohmann::json::object()}}));
    EXPECT_TRUE(by_name["mesh_lod"]["frame_ms"]["vs_baseline"].is_null());  // NaN: not measured
    EXPECT_EQ(brute["cpu_ms"], (nlohmann::json{{"total", 30.5}}));
    EXPECT_EQ(brute["primitives"]["triangles"], 2000000.0);
    EXPECT_EQ(brute["upload_bytes"], 1048576.0);
    EXPECT_EQ(brute["error"]["psnr"], 38.5);
    EXPECT_EQ(by_name["baseline"]["error"]["transitions"],
              (nlohmann::json{{"measured", 42},
                              {"by_kind", {{"switch", 42}}},
                              {"mean_frames", 1.0},
                              {"too_few_pixels", 0},
                              {"cut_off_by_path", 0}}));
    EXPECT_EQ(by_name["baseline"]["error"]["lighting_jump"], 7.5);
    // No transition measured: null, never a flattering 0.
    EXPECT_TRUE(by_name["mesh_lod"]["error"]["lighting_jump"].is_null());
    EXPECT_EQ(by_name["lod_scale_0.5"]["quality"], 0.5);
    EXPECT_EQ(by_name["reference"]["error"]["psnr"], "inf");
    for (const auto& [name, c] : by_name)
        EXPECT_EQ(c["on_pareto_front"], name == "lod_scale_0.5" || name == "reference") << name;
    EXPECT_FALSE(fs::exists(dir / "bench.json.tmp"));
    fs::remove_all(dir);
}

TEST(bench_report_json, numbers_keep_six_significant_digits) {
    const fs::path dir = temp_dir("precision");
    bench_report r = fixture();
    r.configurations[0].frame_ms_median = 0.1 + 0.2;  // 0.30000000000000004
    r.configurations[0].error.ssim = 0.123456789;
    write_bench_json(dir / "bench.json", r);
    const std::string text = read_text(dir / "bench.json");
    EXPECT_EQ(text.find("0.30000000000000004"), std::string::npos);
    EXPECT_NE(text.find("\"median\": 0.3,"), std::string::npos);
    EXPECT_NE(text.find("\"ssim\": 0.123457,"), std::string::npos);
    fs::remove_all(dir);
}

TEST(bench_report_json, failure_names_the_path) {
    const fs::path path = fs::path("/nonexistent_sylva_dir") / "bench.json";
    try {
        write_bench_json(path, fixture());
        FAIL() << "expected an exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    }
}

// --- bench.csv ---------------------------------------------------------------------------------

TEST(bench_report_csv, header_rows_and_rfc4180_quoting) {
    const fs::path dir = temp_dir("csv");
    write_bench_csv(dir / "bench.csv", fixture());
    const std::vector<std::string> lines = lines_of(read_text(dir / "bench.csv"));
    ASSERT_EQ(lines.size(), 8u);
    EXPECT_EQ(lines[0],
              "name,family,lighting,quality,frames,frame_ms_median,frame_ms_min,frame_ms_max,"
              "frame_ms_vs_baseline,cpu_ms_total,gpu_ms_total,triangles,points,lines,upload_bytes,"
              "peak_memory_mb,psnr_db,ssim,perceptual,coverage_iou,popping,lighting_jump,transitions,"
              "on_pareto_front");
    EXPECT_EQ(lines[1],
              "brute_force,brute_force,normal,0,120,50,48,55,8.25,30.5,45.25,2000000,0,0,1048576,812.5,"
              "38.5,0.99,0.02,0.999,0.1,n/a,0,false");
    EXPECT_EQ(lines[2],
              "baseline,baseline,normal,50,120,6,5.5,7,n/a,3,4.5,150000,0,0,4096,512,27.1,0.93,0.09,"
              "0.99,0,7.5,42,false");
    EXPECT_EQ(lines[4],
              "lod_scale_0.5,lod_scale,normal,0.5,120,4,3.8,4.4,n/a,2,3,150000,0,0,4096,512,30,0.98,"
              "0.018,0.99,0,n/a,0,true");
    EXPECT_EQ(lines[5],
              "\"points \"\"dense\"\", far\",points,normal,0,120,5,4.5,6,n/a,2.5,3.75,150000,0,0,4096,"
              "512,30,0.95,0.06,0.99,0,n/a,0,false");
    EXPECT_EQ(lines[7].substr(0, 18), "reference,referenc");
    EXPECT_NE(lines[7].find(",inf,1,0,1,"), std::string::npos) << lines[7];
    fs::remove_all(dir);
}

TEST(bench_report_csv, unmeasured_values_read_n_a) {
    const fs::path dir = temp_dir("csv_empty");
    bench_report r = fixture();
    r.configurations.resize(1);
    r.configurations[0].gpu_ms.clear();
    r.configurations[0].primitives.erase("lines");
    r.configurations[0].error.lighting_jump = k_nan;
    write_bench_csv(dir / "bench.csv", r);
    EXPECT_EQ(lines_of(read_text(dir / "bench.csv"))[1],
              "brute_force,brute_force,normal,0,120,50,48,55,8.25,30.5,n/a,2000000,0,n/a,1048576,812.5,"
              "38.5,0.99,0.02,0.999,0.1,n/a,0,true");
    fs::remove_all(dir);
}

// --- the plot ----------------------------------------------------------------------------------

// Tags nest and close by name, and every '&' starts an entity: enough XML for a browser.
std::string well_formedness_problem(const std::string& svg) {
    std::vector<std::string> open;
    for (std::size_t i = 0; i < svg.size(); ++i) {
        if (svg[i] == '&') {
            const std::size_t semicolon = svg.find(';', i);
            const std::string entity =
                svg.substr(i, semicolon == std::string::npos ? 8 : semicolon - i + 1);
            if (entity != "&amp;" && entity != "&lt;" && entity != "&gt;" && entity != "&quot;" &&
                entity != "&apos;")
                return "bad entity at " + std::to_string(i) + ": " + entity;
        }
        if (svg[i] != '<') continue;
        const std::size_t end = svg.find('>', i);
        if (end == std::string::npos) return "unclosed tag at " + std::to_string(i);
        const std::string tag = svg.substr(i + 1, end - i - 1);
        if (tag.find('<') != std::string::npos) return "'<' inside a tag at " + std::to_string(i);
        const std::string name = tag.substr(0, tag.find_first_of(" \n/", tag[0] == '/' ? 1 : 0));
        if (tag.back() == '/') {
        } else if (tag[0] == '/') {
            if (open.empty() || open.back() != name.substr(1))
                return "mismatched </" + name.substr(1) + ">";
            open.pop_back();
        } else {
            open.push_back(name);
        }
        i = end;
    }
    return open.empty() ? "" : "unclosed <" + open.back() + ">";
}

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

TEST(bench_report_svg, is_well_formed_labels_every_configuration_and_draws_both_fronts) {
    const fs::path dir = temp_dir("svg");
    write_bench_plot_svg(dir / "plot.svg", fixture());
    const std::string svg = read_text(dir / "plot.svg");
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
    EXPECT_EQ(well_formedness_problem(svg), "");
    for (const char* name :
         {"brute_force", "baseline", "mesh_lod", "lod_scale_0.5", "points &quot;dense&quot;, far",
          "clouds &lt;&amp;&gt; more", "reference"})
        EXPECT_NE(svg.find(std::string(">") + name + "</text>"), std::string::npos) << name;
    EXPECT_EQ(svg.find("<&>"), std::string::npos);
    EXPECT_NE(svg.find("meadow &lt;dense&gt;"), std::string::npos);
    EXPECT_NE(svg.find("640×360"), std::string::npos);
    EXPECT_EQ(count_of(svg, "<polyline class=\"pareto\""), 2u);
    // Frame times span 3.8..520 ms: a log axis with decade ticks.
    EXPECT_NE(svg.find("log scale"), std::string::npos);
    EXPECT_NE(svg.find(">100</text>"), std::string::npos);
    // Markers: brute force a square, baseline a diamond; filled on the front (FLIP: 2, 1-SSIM: 4).
    EXPECT_EQ(count_of(svg, "width=\"10\" height=\"10\""),
              2u + 1u);  // one per panel, one in the legend
    EXPECT_EQ(count_of(svg, "<g class=\"configuration\">"), 14u);
    EXPECT_EQ(count_of(svg, ", on the Pareto front</title>"), 6u);
    fs::remove_all(dir);
}

TEST(bench_report_svg, pareto_polyline_steps_through_the_front_points) {
    const fs::path dir = temp_dir("svg_front");
    write_bench_plot_svg(dir / "plot.svg", fixture());
    const std::string svg = read_text(dir / "plot.svg");
    const std::size_t at = svg.find("id=\"pareto-ssim-normal\"");
    ASSERT_NE(at, std::string::npos);
    const std::size_t begin = svg.find("points=\"", at) + 8;
    const std::string points = svg.substr(begin, svg.find('"', begin) - begin);
    // Four front points make a staircase of 4 + 3 corners.
    EXPECT_EQ(count_of(points, ","), 7u) << points;
    fs::remove_all(dir);
}

TEST(bench_report_svg, is_deterministic_and_linear_for_a_narrow_range) {
    const fs::path dir = temp_dir("svg_det");
    write_bench_plot_svg(dir / "a.svg", fixture());
    write_bench_plot_svg(dir / "b.svg", fixture());
    EXPECT_EQ(read_text(dir / "a.svg"), read_text(dir / "b.svg"));
    bench_report narrow = fixture();
    narrow.configurations.resize(3);  // 5.5 .. 55 ms is 10x, so drop brute force too
    narrow.configurations.erase(narrow.configurations.begin());
    write_bench_plot_svg(dir / "narrow.svg", narrow);
    const std::string svg = read_text(dir / "narrow.svg");
    EXPECT_EQ(svg.find("log scale"), std::string::npos);
    EXPECT_EQ(well_formedness_problem(svg), "");
    fs::remove_all(dir);
}

// --- summary.md --------------------------------------------------------------------------------

TEST(bench_report_summary, table_sorted_by_frame_time_with_hand_computed_speed_ups) {
    const fs::path dir = temp_dir("md");
    write_bench_summary_md(dir / "summary.md", fixture());
    const std::string md = read_text(dir / "summary.md");
    const std::vector<std::string> lines = lines_of(md);
    EXPECT_EQ(lines[0], "# sylva bench: meadow <dense>");
    // 50 / 4 = 12.5; 50 / 6 = 8.33; 50 / 50 = 1; 50 / 500 = 0.1.
    const std::string lod =
        "| lod_scale_0.5 | 4.00 [3.80–4.40] | 12.5× | 30.0 | 0.9800 | 0.0180 | 0.9900 | 0.00 | "
        "n/a | 0 | 150,000 | 0 | 0 | ★ |";
    const std::string baseline =
        "| baseline | 6.00 [5.50–7.00] | 8.33× | 27.1 | 0.9300 | 0.0900 | 0.9900 | 0.00 | "
        "7.50 | 42 | 150,000 | 0 | 0 |  |";
    const std::string brute =
        "| brute_force | 50.0 [48.0–55.0] | 1.00× | 38.5 | 0.9900 | 0.0200 | 0.9990 | 0.10 | "
        "n/a | 0 | 2,000,000 | 0 | 0 |  |";
    const std::string reference =
        "| reference | 500 [490–520] | 0.10× | ∞ | 1.0000 | 0.0000 | 1.0000 | 0.00 | n/a | 0 | "
        "150,000 | 0 | 0 | ★ |";
    for (const std::string& row : {lod, baseline, brute, reference})
        EXPECT_NE(md.find(row + "\n"), std::string::npos) << row << "\n---\n" << md;
    EXPECT_LT(md.find(lod), md.find(baseline));
    EXPECT_LT(md.find(baseline), md.find(brute));
    EXPECT_LT(md.find(brute), md.find(reference));
    EXPECT_NE(md.find("| points \"dense\", far |"), std::string::npos);
    fs::remove_all(dir);
}

TEST(bench_report_summary, sentences_follow_the_data) {
    const fs::path dir = temp_dir("md_sentences");
    write_bench_summary_md(dir / "summary.md", fixture());
    std::string md = read_text(dir / "summary.md");
    EXPECT_NE(md.find("with error no worse than brute_force's is lod_scale_0.5: FLIP 0.0180 "
                      "against 0.0200, at "
                      "4.00 ms against 50.0 ms (12.5× faster)"),
              std::string::npos)
        << md;
    // Within 1.1 x 6 ms: lod_scale_0.5 (FLIP 0.018) and points (0.060); 0.090 / 0.018 = 5.
    EXPECT_NE(md.find("lod_scale_0.5 reaches FLIP 0.0180 at 4.00 ms against baseline (FLIP "
                      "0.0900 at 6.00 ms): "
                      "5.00× lower error"),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("identical images"), std::string::npos) << md;

    // Make lod_scale_0.5 worse than brute force and the reference imperfect: the sentences change.
    bench_report r = fixture();
    r.configurations[3].error.perceptual = 0.021;
    r.configurations[6].error.perceptual = 0.001;
    write_bench_summary_md(dir / "summary.md", r);
    md = read_text(dir / "summary.md");
    // Front candidates now: lod_scale_0.5 (0.021) only; brute_force and reference do not count.
    EXPECT_NE(md.find("No configuration on the FLIP Pareto front has error no worse than "
                      "brute_force's (FLIP 0.0200 "
                      "at 50.0 ms); the closest is lod_scale_0.5 at FLIP 0.0210, 12.5× faster."),
              std::string::npos)
        << md;
    EXPECT_NE(md.find("NOT identical"), std::string::npos) << md;

    // Without brute force, baseline and reference there is nothing to compare: no sentences.
    r.configurations = {r.configurations[2], r.configurations[3]};
    write_bench_summary_md(dir / "summary.md", r);
    md = read_text(dir / "summary.md");
    EXPECT_EQ(md.find("brute_force's"), std::string::npos) << md;
    EXPECT_EQ(md.find("reaches FLIP"), std::string::npos) << md;
    EXPECT_EQ(md.find("Verdict"), std::string::npos) << md;
    EXPECT_EQ(md.find("against itself"), std::string::npos) << md;
    EXPECT_NE(md.find("| mesh_lod | 8.00 [7.50–9.00] | n/a |"), std::string::npos) << md;
    fs::remove_all(dir);
}

// With timing rounds, "similar frame time" is judged by the median of the round-by-round ratios
// to the baseline, and the summary lists them.
TEST(bench_report_summary, timing_rounds_judge_similar_time_by_the_round_ratios) {
    const fs::path dir = temp_dir("md_rounds");
    bench_report r = fixture();
    r.timing_rounds = 3;
    r.configurations[0].frame_ms_rounds = {49.5, 49.5, 49.5};  // brute force: 8.25x
    r.configurations[1].frame_ms_rounds = {6.0, 6.0, 6.0};     // baseline
    r.configurations[1].frame_ms_vs_baseline = 1.0;
    // lod_scale_0.5: faster by its median, not by its rounds (1.2, 1.25, 1.3).
    r.configurations[3].frame_ms_rounds = {7.2, 7.5, 7.8};
    r.configurations[3].frame_ms_vs_baseline = 1.25;
    r.configurations[4].frame_ms_rounds = {5.4, 5.4, 5.4};  // points "dense", far: 0.9x
    r.configurations[4].frame_ms_vs_baseline = 0.9;
    write_bench_summary_md(dir / "summary.md", r);
    const std::string md = read_text(dir / "summary.md");
    EXPECT_NE(md.find("Frame times are medians over 3 timing rounds of every frame"), std::string::npos) << md;
    EXPECT_NE(md.find("Time against baseline: brute_force 8.25×, lod_scale_0.5 1.25×, points "
                      "\"dense\", far 0.90×."),
              std::string::npos)
        << md;
    // lod_scale_0.5 is out (1.25 > 1.1); points is in, FLIP 0.090 / 0.060 = 1.5 lower.
    EXPECT_NE(md.find("points \"dense\", far reaches FLIP 0.0600 at 5.00 ms against baseline (FLIP "
                      "0.0900 at 6.00 ms): 1.50× lower error"),
              std::string::npos)
        << md;

    r.timing_rounds = 1;
    write_bench_summary_md(dir / "summary.md", r);
    EXPECT_EQ(read_text(dir / "summary.md").find("timing rounds"), std::string::npos);
    fs::remove_all(dir);
}

// --- lighting families -------------------------------------------------------------------------

// Two SH-lit configurations beside the fixture's normal-lit ones. Their errors are against
// another reference: far lower FLIP than anything normal-lit, which must knock nothing of the
// normal family off its front, win none of its sentences, and beat none of its baselines.
bench_report with_sh_family() {
    bench_report r = fixture();
    r.lighting_families.push_back({"sh", "every species lit by SH transfer", 800, {}});
    bench_configuration brute = configuration("brute_force_sh", "brute_force", 60, 58, 62, 0.004, 0.999);
    brute.lighting = "sh";
    r.configurations.push_back(brute);
    bench_configuration baseline = configuration("baseline_sh", "baseline", 7, 6.5, 8, 0.050, 0.960);
    baseline.lighting = "sh";
    baseline.quality = 50;
    r.configurations.push_back(baseline);
    bench_configuration lod = configuration("mesh_lod_sh", "mesh_lod", 3, 2.9, 3.1, 0.001, 0.999);
    lod.lighting = "sh";
    r.configurations.push_back(lod);
    return r;
}

TEST(bench_report_lighting_families, fronts_tables_and_sentences_never_mix_references) {
    const fs::path dir = temp_dir("families");
    const bench_report r = with_sh_family();
    write_bench_json(dir / "bench.json", r);
    const nlohmann::json j = nlohmann::json::parse(read_text(dir / "bench.json"));
    std::map<std::string, bool> front;
    for (const auto& c : j["configurations"]) front[c["name"]] = c["on_pareto_front"];
    // Normal: lod_scale_0.5 and reference, as without the SH family. SH: mesh_lod_sh dominates.
    EXPECT_TRUE(front["lod_scale_0.5"]);
    EXPECT_TRUE(front["reference"]);
    EXPECT_TRUE(front["mesh_lod_sh"]);
    EXPECT_FALSE(front["brute_force_sh"]);
    EXPECT_FALSE(front["baseline_sh"]);

    write_bench_summary_md(dir / "summary.md", r);
    const std::string md = read_text(dir / "summary.md");
    const std::size_t sh = md.find("## Lighting: sh");
    ASSERT_NE(md.find("## Lighting: normal"), std::string::npos) << md;
    ASSERT_NE(sh, std::string::npos) << md;
    const std::string normal_part = md.substr(0, sh);
    const std::string sh_part = md.substr(sh, md.find("## Configurations") - sh);
    EXPECT_EQ(normal_part.find("_sh"), std::string::npos) << normal_part;
    EXPECT_EQ(sh_part.find("lod_scale_0.5 |"), std::string::npos) << sh_part;
    EXPECT_NE(sh_part.find("speed-up vs brute_force_sh"), std::string::npos) << sh_part;
    // 60 / 3 = 20: the SH family's own brute force.
    EXPECT_NE(sh_part.find("than brute_force_sh's is mesh_lod_sh: FLIP 0.0010 against 0.0040, at 3.00 ms "
                           "against 60.0 ms (20.0× faster)"),
              std::string::npos)
        << sh_part;
    EXPECT_NE(normal_part.find("than brute_force's is lod_scale_0.5"), std::string::npos) << normal_part;

    write_bench_plot_svg(dir / "plot.svg", r);
    const std::string svg = read_text(dir / "plot.svg");
    EXPECT_EQ(well_formedness_problem(svg), "");
    EXPECT_EQ(count_of(svg, "<polyline class=\"pareto\""), 4u);  // two panels per family
    EXPECT_NE(svg.find("id=\"pareto-flip-sh\""), std::string::npos);
    fs::remove_all(dir);
}

// --- the verdict against the baseline's sweep (issue 18 item 9) -------------------------------

TEST(bench_report_verdict, a_sweep_beats_a_baseline_point_only_when_as_fast_and_no_worse_in_ssim_and_flip) {
    bench_report r;
    r.lighting_families = {{"normal", "", 100, {}}};
    auto add = [&](const std::string& name, const std::string& family, double quality, std::vector<double> rounds,
                   double ssim, double flip) {
        bench_configuration c = configuration(name, family, rounds[0], rounds[0], rounds[0], flip, ssim);
        c.quality = quality;
        c.frame_ms_rounds = rounds;
        r.configurations.push_back(c);
    };
    //    baseline points: time rounds            SSIM   FLIP
    add("crossed_billboard_only", "baseline", 0, {10, 10, 10}, 0.70, 0.13);
    add("baseline_25m", "baseline", 25, {12, 12, 12}, 0.72, 0.12);
    add("baseline", "baseline", 50, {20, 20, 20}, 0.75, 0.11);
    // Sweep A: a beats the first two points (9/10 and 9/12 fast enough, 0.73 >= 0.72, 0.115 <=
    // 0.12); b (20.4/20 = 1.02 by rounds, though its first round is faster) is too slow for the
    // third; c is as fast but its FLIP is worse.
    add("a", "sweep", 1, {9, 9, 9}, 0.73, 0.115);
    add("b", "sweep", 2, {19, 20.4, 21}, 0.80, 0.10);
    add("c", "sweep", 3, {18, 18, 18}, 0.80, 0.111);
    const std::vector<family_verdict> verdicts = baseline_verdicts(r);
    ASSERT_EQ(verdicts.size(), 1u);
    const family_verdict& v = verdicts[0];
    EXPECT_EQ(v.family, "sweep");
    EXPECT_EQ(v.configurations, (std::vector<std::string>{"a", "b", "c"}));
    ASSERT_EQ(v.points.size(), 3u);
    EXPECT_EQ(v.points[0].baseline, "crossed_billboard_only");
    EXPECT_EQ(v.points[0].beaten_by, "a");
    EXPECT_DOUBLE_EQ(v.points[0].time_ratio, 0.9);
    EXPECT_EQ(v.points[1].beaten_by, "a");
    EXPECT_DOUBLE_EQ(v.points[1].time_ratio, 0.75);
    EXPECT_EQ(v.points[2].beaten_by, "");
    EXPECT_EQ(v.points[2].why_not, "as fast: c (0.90x) has FLIP 0.1110 > 0.1100");
    EXPECT_FALSE(v.beats_every_point());
    EXPECT_EQ(v.summary(), "no: not baseline");
    // With b a little faster (ratio exactly 1 counts as fast enough) the sweep beats them all.
    r.configurations[4].frame_ms_rounds = {19, 20, 21};
    EXPECT_EQ(baseline_verdicts(r)[0].summary(), "yes");
    EXPECT_EQ(baseline_verdicts(r)[0].points[2].beaten_by, "b");
}

}  // namespace
}  // namespace sylva
