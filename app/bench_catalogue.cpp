#include "app/bench_catalogue.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace sylva {
namespace {

bench_configuration_spec brute_force() {
    bench_configuration_spec c;
    c.name = "brute_force";
    c.family = k_family_brute_force;
    c.description = "every plant at full geometry, one sample per pixel";
    c.options.geometry = geometry_mode::full;
    return c;
}

bench_configuration_spec mesh_lod(double factor) {
    bench_configuration_spec c;
    std::ostringstream name;
    name << "mesh_lod";
    if (factor != 1.0) name << "_x" << factor;
    c.name = name.str();
    c.family = "mesh_lod";
    std::ostringstream description;
    description << "the runtime's mesh levels (full, reduced, far) by distance";
    if (factor != 1.0) description << ", switch distances x" << factor;
    c.description = description.str();
    c.quality = factor;
    c.lod_scale_factor = float(factor);
    return c;
}

bench_configuration_spec single(representation r, std::string description) {
    bench_configuration_spec c;
    c.name = std::string(representation_name(r)) + "_only";
    c.family = "single_representation";
    c.description = std::move(description);
    c.options.policy = {lod_policy::kind::single, r, r, 0.0f};
    return c;
}

// The engine baseline's sweep point at `distance_m` (0: the crossed billboard everywhere, which
// is where the sweep ends: every plant as one crossed-quad billboard).
bench_configuration_spec baseline(float distance_m) {
    if (distance_m <= 0.0f) {
        bench_configuration_spec c = single(representation::crossed_billboard, "");
        c.family = k_family_baseline;
        c.description =
            "engine baseline at switch distance 0: every plant as one crossed-quad billboard";
        return c;
    }
    bench_configuration_spec c;
    const bool named = double(distance_m) == k_named_baseline_distance_m;
    c.name = named ? "baseline" : "baseline_" + std::to_string(int(distance_m)) + "m";
    c.family = k_family_baseline;
    c.description = "engine baseline: full mesh nearer than " + std::to_string(int(distance_m)) +
                    " m x plant scale, one crossed-quad billboard beyond, hard switch";
    c.quality = distance_m;
    c.options.policy = {lod_policy::kind::hard_switch, representation::mesh_full,
                        representation::crossed_billboard, distance_m};
    return c;
}

// Deussen 2002: every plant as prefixes of its random-order triangles, points and lines, with
// sample distance d' (pixels); the sweep trades error for time (§5.4). Soft splats, fog-weighted,
// by default; `_opaque` draws the paper's opaque squares, `_uniform` spaces samples d' apart
// however much fog lies between them and the eye (point_line_lod.h fog_sample_distance).
// A splat factor other than the catalogue's c_p = 1.3 is named `_cp<c_p>`.
bench_configuration_spec points_lines(float sample_distance_px,
                                      splat_style splats = splat_style::soft,
                                      bool fog_weighted = true, float splat_factor = 1.3f) {
    bench_configuration_spec c;
    std::ostringstream name;
    name << "points_lines";
    if (sample_distance_px != 1.0f) name << "_d" << sample_distance_px;
    if (splat_factor != 1.3f) name << "_cp" << splat_factor;
    if (splats == splat_style::opaque) name << "_opaque";
    if (!fog_weighted) name << "_uniform";
    c.name = name.str();
    c.family = "points_lines";
    std::ostringstream description;
    description << "points and lines (Deussen 2002), d' = " << sample_distance_px
                << " px, c_p = " << splat_factor << ", "
                << (splats == splat_style::soft ? "soft splats" : "opaque splats (the paper's)")
                << (fog_weighted ? ", fog-weighted" : ", d' everywhere (no fog weighting)");
    c.description = description.str();
    c.quality = sample_distance_px;
    c.options.policy.mode = lod_policy::kind::points_lines;
    c.options.policy.points = {sample_distance_px, splat_factor, true, splats, fog_weighted};
    return c;
}

// Behrendt 2005 §2.3: meshes near, billboard clouds from 30 m x plant scale, crossed billboards
// beyond the species' far distance, each switch cross-faded without sorting.
// `lighting`: every species lit as "normal_mapped", "pre_lit" or "sh" (§2.3, §4).
bench_configuration_spec billboard_clouds(const std::string& lighting,
                                          float cloud_distance_m = 30.0f) {
    bench_configuration_spec c;
    c.name = lighting == "normal_mapped" ? "billboard_clouds" : "billboard_clouds_" + lighting;
    if (cloud_distance_m != 30.0f) {
        std::ostringstream suffix;
        suffix << "_c" << cloud_distance_m << "m";
        c.name += suffix.str();
    }
    c.family = "billboard_clouds";
    std::ostringstream description;
    description << "billboard clouds (Behrendt 2005), " << lighting << ": full mesh nearer than "
                << cloud_distance_m
                << " m x plant scale, cloud beyond, crossed billboard beyond the far distance, "
                   "sort-free fades";
    c.description = description.str();
    c.options.policy.mode = lod_policy::kind::billboard_clouds;
    c.options.policy.cloud_distance_m = cloud_distance_m;
    c.options.lighting = lighting;
    return c;
}

// DESIGN §1.5: each species drawn by its ladder (the scenario's, else the papers', lod/ladder.h),
// rungs switched by projected size with a fade across each band; `factor` scales every switch
// size down (as lod_scale does distances), so smaller factors are cheaper.
bench_configuration_spec ladder_configuration(double factor = 1.0) {
    bench_configuration_spec c;
    std::ostringstream name;
    name << "ladder";
    if (factor != 1.0) name << "_x" << factor;
    c.name = name.str();
    c.family = "ladder";
    std::ostringstream description;
    description << "each species' representation ladder (the scenario's, else the papers': full mesh, reduced "
                   "mesh, billboard cloud, points and lines, crossed billboard) by projected size, faded "
                   "across each band";
    if (factor != 1.0) description << ", projected sizes x" << factor;
    c.description = description.str();
    c.quality = factor;
    c.options.policy.mode = lod_policy::kind::ladder;
    c.options.policy.ladder_size_scale = float(factor);
    return c;
}

// Rebollo 2006 as a rung: each species' ladder with LoDF in the reduced mesh's place, so a near
// plant's foliage thins leaf by leaf from the full mesh down to where the next rung takes over,
// instead of jumping to the reduced mesh. Its own family, scaled as `ladder` is, so that its
// popping and error can be read against the ladder's at equal frame time (issue 23).
bench_configuration_spec ladder_lodf(double factor = 1.0) {
    bench_configuration_spec c = ladder_configuration(factor);
    c.name.insert(std::string_view("ladder").size(), "_lodf");  // ladder_x2 -> ladder_lodf_x2
    c.family = "ladder_lodf";
    const std::size_t scaled = c.description.find(", projected sizes");
    c.description = "each species' ladder with LoDF (Rebollo 2006) for its reduced mesh: the foliage thinned "
                    "continuously from the full mesh to the next rung" +
                    (scaled == std::string::npos ? std::string() : c.description.substr(scaled));
    c.options.policy.lodf_for_reduced = true;
    return c;
}

// Behrendt 2005 §3: the shell rung against what it replaces, each a `ladder` configuration of
// the "shells" family drawn another way (on a scenario without shells each is `ladder` again).
bench_configuration_spec shells_variant(std::string name, std::string description) {
    bench_configuration_spec c = ladder_configuration();
    c.name = std::move(name);
    c.family = "shells";
    c.description = std::move(description);
    return c;
}

// `ladder_no_shells`: each species' ladder with its shell rung dropped, so the rung before draws
// the far field (the same Wang-tiled plants, one by one).
bench_configuration_spec ladder_without_shells() {
    bench_configuration_spec c = shells_variant(
        "ladder_no_shells", "each species' ladder with its shell rung dropped: the far field's plants drawn one by one "
                            "by the rung before (Behrendt 2005 §3's alternative)");
    c.options.policy.without_shells = true;
    return c;
}

// `ladder_shells_f<f>`: the shells slanted by f (Eq. 2; the scenario's own is in `ladder`).
bench_configuration_spec ladder_shells_slanted(double slant) {
    std::ostringstream value;
    value << slant;
    bench_configuration_spec c = shells_variant("ladder_shells_f" + value.str(),
                                                "each species' ladder, its shells slanted toward the viewer by f = " +
                                                    value.str() + " (Behrendt 2005 Eq. 2, limited; 0: flat slices)");
    c.quality = slant;
    c.options.shell_slant = slant;
    return c;
}

// §3.3's claim, measured: the same ladder with the shells' pyramid built and blended with the
// standard equation, which shifts colours where a level replaces its slices.
bench_configuration_spec ladder_shells_standard_blending() {
    bench_configuration_spec c = shells_variant(
        "ladder_shells_standard_blending", "each species' ladder, its shells' slice pyramid merged and blended with the "
                                           "standard equation instead of Behrendt 2005 §3.3's premultiplied one "
                                           "(measurement only)");
    c.options.shell_blending = "standard";
    return c;
}

// Behrendt 2005 §4 and Luft 2007 on the shells, measured: the same ladder with its shells lit by
// their normals as plain ones even where the tiled plants are lit by SH transfer or by the
// implicit surface (otherwise the same image as `ladder`).
bench_configuration_spec ladder_shells_normal_lit() {
    bench_configuration_spec c = shells_variant(
        "ladder_shells_normal_lit",
        "each species' ladder, its shells lit by the slices' normals as plain ones even where "
        "the plants are lit by SH transfer or the implicit surface (measurement only)");
    c.options.shell_lighting = "normal_mapped";
    return c;
}

// The same ladder with its shells blended straight into the frame at full resolution instead of
// the half-size layer: what the layer's resolution costs in error, and saves in time. Its plants
// then write no IDs, so its coverage IoU is not measured (n/a).
bench_configuration_spec ladder_shells_full_resolution() {
    bench_configuration_spec c = shells_variant(
        "ladder_shells_full_resolution", "each species' ladder, its shells blended straight into the frame at full "
                                         "resolution instead of the half-size layer (measurement only)");
    c.options.shell_full_resolution = true;
    return c;
}

// A value as the bench names and describes it (shortest form: 40, 0.25).
std::string value_text(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

// An auto ladder configuration of sweep `family`, named `<prefix><value>` (the value its quality).
bench_configuration_spec auto_configuration(const std::string& prefix, std::string family,
                                            double value, std::string description) {
    bench_configuration_spec c = ladder_configuration();
    c.name = prefix + value_text(value);
    c.family = std::move(family);
    c.description = std::move(description);
    c.quality = value;
    return c;
}

// What a gain asks of a plant's rung, in a configuration's description.
std::string gain_clause(double gain_per_ms) {
    return "a dearer rung only where each ms of it puts right " + value_text(gain_per_ms) +
           " pixels' worth of error";
}

// DESIGN §1.5 `auto`: each species' ladder with every plant's rung chosen per frame from the
// species' measured rung tables so that the plants' predicted cost stays within `budget_ms`.
bench_configuration_spec auto_ladder(double budget_ms) {
    bench_configuration_spec c =
        auto_configuration("auto_", "auto", budget_ms,
                           "each species' ladder, every plant's rung chosen per frame by the "
                           "budget solver from measured error and cost tables, plants' "
                           "predicted cost within " +
                               value_text(budget_ms) + " ms");
    c.options.plant_budget_ms = budget_ms;
    return c;
}

// The auto ladder at a fixed gain: a plant buys a dearer rung only where each ms of it puts right
// `gain_per_ms` of error, in every frame alike, so the frames where plants are near and large
// take more time than those where they are far (as the engine baseline's do), instead of every
// frame spending one budget.
bench_configuration_spec auto_gain(double gain_per_ms) {
    bench_configuration_spec c =
        auto_configuration("auto_gain_", "auto_gain", gain_per_ms,
                           "each species' ladder, every plant's rung chosen per frame from "
                           "measured error and cost tables: " +
                               gain_clause(gain_per_ms));
    c.options.gain_per_ms = gain_per_ms;
    return c;
}

// `c` with every species lit by SH transfer (Behrendt 2005 §4), named `<name>_sh`: measured
// against the SH-lit reference, beside the other SH configurations.
bench_configuration_spec lit_by_transfer(bench_configuration_spec c) {
    c.name += "_sh";
    c.description += ", every species lit by SH transfer (Behrendt 2005 §4)";
    c.options.lighting = "sh";
    return c;
}

// `c` with every species lit by Luft 2007's implicit-surface normals and density ambient, named
// `<name>_implicit`: measured against the implicit-lit reference; its time beside `c`'s says what
// the lighting costs at run time (issue 22: nothing).
bench_configuration_spec lit_implicitly(bench_configuration_spec c) {
    c.name += "_implicit";
    c.description += ", every species lit by Luft 2007's implicit surface (realigned normals, density ambient)";
    c.options.lighting = "implicit";
    return c;
}

// Species lit by SH transfer.
std::size_t sh_species(const scenario& s) {
    return std::size_t(std::count_if(s.species.begin(), s.species.end(), [&](const species_settings& sp) {
        return (sp.lighting == "scenario" ? s.lod.lighting : sp.lighting) == "sh";
    }));
}

}  // namespace

std::string lighting_family(const scenario& s, const std::string& lighting) {
    if (lighting == "sh") return "sh";
    if (lighting == "implicit" || lighting == "sh_implicit") return lighting;
    if (lighting == "normal_mapped" || lighting == "pre_lit") return "normal";
    const std::size_t sh = sh_species(s);
    if (sh == s.species.size() && sh > 0) return "sh";
    if (sh == 0) return "normal";
    return "scenario";
}

std::string lighting_family_description(const std::string& family) {
    if (family == "sh") return "every species lit by SH transfer (Behrendt 2005 §4)";
    if (family == "normal") return "every species lit by its normals (normal-mapped; pre-lit clouds compare here too)";
    if (family == "implicit")
        return "every species lit by Luft 2007's implicit-surface normals and density ambient";
    if (family == "sh_implicit")
        return "every species lit by SH transfer baked from Luft 2007's implicit-surface normals";
    return "every species lit as the scenario says (its species are lit in different ways)";
}

bench_configuration_spec reference_configuration(const scenario& s, const std::string& family) {
    bench_configuration_spec spec;
    spec.options.geometry = geometry_mode::full;
    if (family != lighting_family(s, ""))
        spec.options.lighting =
            family == "sh" || family == "implicit" || family == "sh_implicit" ? family : "normal_mapped";
    spec.samples = k_bench_reference_samples;
    return spec;
}

std::vector<bench_configuration_spec> default_bench_configurations() {
    std::vector<bench_configuration_spec> list;
    bench_configuration_spec reference;
    reference.name = "reference";
    reference.family = k_family_reference;
    reference.description =
        "the reference rendered again (full geometry, 3x3 samples): must give zero error";
    reference.options.geometry = geometry_mode::full;
    reference.samples = k_bench_reference_samples;
    list.push_back(reference);
    list.push_back(brute_force());

    // Luft 2007's implicit lighting (lit_implicitly) right after its normal-lit twin, so that the
    // two are timed next to each other in every timing round.
    for (double factor : {1.0, 0.25, 0.5, 2.0}) {
        list.push_back(mesh_lod(factor));
        if (factor == 1.0) list.push_back(lit_implicitly(mesh_lod(factor)));
    }
    list.push_back(single(representation::mesh_reduced, "every plant as its reduced mesh"));
    list.push_back(single(representation::mesh_far, "every plant as its far mesh"));
    list.push_back(single(representation::billboard_cloud,
                          "every plant as its billboard cloud (Behrendt 2005)"));
    for (float d : {0.0f, 50.0f, 25.0f, 100.0f}) {
        list.push_back(baseline(d));
        if (double(d) == k_named_baseline_distance_m) list.push_back(lit_implicitly(baseline(d)));
    }
    list.push_back(billboard_clouds("normal_mapped"));
    list.push_back(billboard_clouds("pre_lit"));
    for (double factor : {1.0, 0.5, 0.25, 0.125, 2.0, 4.0}) {
        list.push_back(ladder_configuration(factor));
        if (factor == 1.0) list.push_back(lit_implicitly(ladder_configuration(factor)));
    }
    for (double factor : {1.0, 0.5, 1.125, 1.25, 1.5, 1.75, 2.0, 4.0}) list.push_back(ladder_lodf(factor));
    list.push_back(ladder_without_shells());
    for (double slant : {0.0, 0.25}) list.push_back(ladder_shells_slanted(slant));
    list.push_back(ladder_shells_standard_blending());
    list.push_back(ladder_shells_normal_lit());
    list.push_back(ladder_shells_full_resolution());
    // About 1.25x apart from 30 to 500 ms (1.5x below), where the engine baseline's sweep falls
    // on the shipped scenarios, so that a baseline point has an auto point near its frame time:
    // on `forest` auto_60 and auto_90 fell at 0.83x and 1.03x of `baseline`, and at f4a8978
    // auto_30 and auto_45 at 0.89x (SSIM 0.0009 short) and 1.05x, where auto_38 beat it at 0.95x.
    for (double budget_ms : {4.0, 8.0, 15.0, 20.0, 30.0, 38.0, 45.0, 60.0, 75.0, 90.0, 105.0, 120.0,
                             150.0, 180.0, 210.0, 250.0, 300.0, 350.0, 420.0, 500.0, 700.0, 1000.0,
                             2000.0})
        list.push_back(auto_ladder(budget_ms));
    // From what buys a near tree's mesh (a few hundred pixels' worth a ms) down to what buys
    // every plant its best rung; dense from 250 to 160, where `time_of_day`'s `baseline_25m`
    // lies (when they were added, gain 200 fell short of its SSIM by 0.0009 at 0.89x of its time
    // and 180 beat it at 0.96x).
    for (double gain : {500.0, 300.0, 250.0, 200.0, 180.0, 160.0, 120.0, 80.0, 60.0, 50.0, 40.0,
                        30.0, 20.0, 15.0, 10.0, 7.0, 5.0, 3.0})
        list.push_back(auto_gain(gain));
    for (float d : {1.0f, 0.5f, 2.0f, 2.25f, 2.5f, 3.0f, 4.0f}) {
        list.push_back(points_lines(d));
        if (d == 1.0f) list.push_back(lit_implicitly(points_lines(d)));
    }
    for (float d : {1.0f, 2.0f}) list.push_back(points_lines(d, splat_style::opaque));
    for (float d : {1.0f, 2.0f, 2.5f, 3.0f})
        list.push_back(points_lines(d, splat_style::soft, false));
    // §5.4: d' adapted every frame to hold a budget (the paper's Table 1 draws 10 M triangles
    // with about 1 M primitives).
    bench_configuration_spec budget = points_lines(1.0f);
    budget.name = "points_lines_budget_1m";
    budget.description =
        "points and lines, d' adapted every frame to 1 M triangle equivalents (Deussen 2002 §5.4)";
    budget.options.budget.primitives = 1e6;
    list.push_back(budget);
    // The same without §6.2's tile sets: every plant drawn on its own, to measure what they do.
    bench_configuration_spec plants_only = points_lines(1.0f);
    plants_only.name = "points_lines_no_tile_sets";
    plants_only.description =
        "points and lines, d' = 1 px, every plant on its own (no eco-tile point sets, §6.2)";
    plants_only.options.policy.tile_sets = false;
    list.push_back(plants_only);
    // Behrendt 2005 §4: SH-lit configurations, each family with its own brute force and baseline
    // sweep, measured against the SH-lit reference.
    list.push_back(lit_by_transfer(brute_force()));
    for (float d : {0.0f, 50.0f, 25.0f, 100.0f}) list.push_back(lit_by_transfer(baseline(d)));
    list.push_back(lit_by_transfer(mesh_lod(1.0)));
    list.push_back(billboard_clouds("sh"));
    list.push_back(lit_by_transfer(ladder_configuration()));
    list.push_back(lit_by_transfer(points_lines(1.0f)));
    list.push_back(lit_by_transfer(points_lines(2.0f)));
    return list;
}

bool applies_to(const bench_configuration_spec& c, const scenario& s) {
    if (c.family != "shells") return true;
    return std::any_of(s.populations.begin(), s.populations.end(),
                       [](const population_settings& p) { return p.placement == "wang_tiles"; });
}

std::optional<bench_configuration_spec> command_line_configuration(const scenario& s,
                                                                   const scenario_options& o) {
    const std::string& representation = s.lod.representation;
    // With a ladder a frame-time target drives the auto ladder's budget, not d'.
    const bool points_options = o.sample_distance_px || o.splats || o.primitive_budget ||
                                (o.target_frame_ms && representation != "ladder");
    if (!o.representation && !points_options && !o.plant_budget_ms && !o.max_error &&
        !o.target_frame_ms && !o.gain_per_ms)
        return std::nullopt;
    if (points_options && representation != "points_lines") {
        const char* option = o.sample_distance_px ? "--sample-distance"
                             : o.splats           ? "--splats"
                             : o.primitive_budget ? "--primitive-budget"
                                                  : "--target-frame-ms";
        throw std::invalid_argument(
            std::string(option) + " sets points and lines (Deussen 2002), but scenario '" + s.name +
            "' draws " + representation + ": add --representation points_lines");
    }
    bench_configuration_spec c;
    if (representation == "mesh_levels") {
        c = mesh_lod(1.0);
    } else if (representation == "ladder") {
        const lod_settings& lod = s.lod;
        c = lod.plant_budget_ms > 0.0 ? auto_ladder(lod.plant_budget_ms) : ladder_configuration();
        std::ostringstream value;
        if (lod.max_error > 0.0) {
            value << lod.max_error;
            c.name = "auto_error_" + value.str();
            c.family = "auto";
            c.description = "each species' ladder, every plant on the cheapest rung whose measured error per plant "
                            "pixel is at most " + value.str();
            c.options.max_error = lod.max_error;
        } else if (lod.target_frame_ms > 0.0) {
            value << lod.target_frame_ms;
            c.name = "auto_target_" + value.str() + "ms";
            c.family = "auto";
            c.description = "each species' ladder chosen by the budget solver, the plant budget adapted every frame "
                            "to a GPU frame time of " + value.str() + " ms (timing-dependent: its errors vary from "
                            "run to run)";
            c.options.target_frame_ms = lod.target_frame_ms;
        }
        if (lod.gain_per_ms > 0.0) {
            if (c.family == "auto") {
                c.name += "_gain_" + value_text(lod.gain_per_ms);
                c.description += ", " + gain_clause(lod.gain_per_ms);
                c.options.gain_per_ms = lod.gain_per_ms;
            } else {
                c = auto_gain(lod.gain_per_ms);
            }
        }
    } else if (representation == "billboard_clouds") {
        c = billboard_clouds(s.lod.lighting, s.lod.cloud_distance_m);
        c.options.lighting.clear();  // the scenario's own lighting, as `play` draws it
    } else {
        const lod_settings& lod = s.lod;
        c = points_lines(lod.sample_distance_px,
                         lod.splats == "opaque" ? splat_style::opaque : splat_style::soft,
                         lod.fog_weighted_samples, lod.splat_factor);
        std::ostringstream value;
        if (lod.primitive_budget > 0.0) {
            value << lod.primitive_budget;
            c.name += "_budget_" + value.str();
            c.options.budget.primitives = lod.primitive_budget;
            c.description += ", d' adapted every frame to " + value.str() +
                             " triangle equivalents (Deussen 2002 §5.4)";
        } else if (lod.target_frame_ms > 0.0) {
            value << lod.target_frame_ms;
            c.name += "_target_" + value.str() + "ms";
            c.options.budget.frame_ms = lod.target_frame_ms;
            c.description += ", d' adapted every frame to a GPU frame time of " + value.str() +
                             " ms (timing-dependent: its errors vary from run to run)";
        }
    }
    c.description += " (from the command line)";
    return c;
}

}  // namespace sylva
