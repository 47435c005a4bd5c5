// The numerical stress suite (app/stress_checks.h). Each check builds its own small inputs,
// runs the real code path (importer, eco tiles, cull, sky and SH, player, LOD choice) and
// states its limit next to what it measured.
#include "app/stress_checks.h"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vector_relational.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <numeric>
#include <stdexcept>

#include "app/scenario_player.h"
#include "components/camera.h"
#include "components/environment.h"
#include "components/lod_state.h"
#include "components/sun.h"
#include "ecs/executor.h"
#include "ecs/schedule.h"
#include "measure/image_metrics.h"
#include "models/gltf/gltf_export.h"
#include "models/gltf/gltf_import.h"
#include "models/generate/plant_library.h"
#include "models/terrain/terrain.h"
#include "scenarios/camera_path.h"
#include "scenarios/scenario_loader.h"
#include "systems/cull_system.h"
#include "lod/eco_tiles.h"
#include "scenarios/embedded_files.h"
#include "lighting/sky_model.h"
#include "lighting/spherical_harmonics.h"
#include "resources/playback.h"
#include "systems/select_representation_system.h"
#include "systems/update_camera_system.h"
#include "systems/update_sun_system.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;
using rows = std::vector<stress_row>;
constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();
constexpr double k_inf = std::numeric_limits<double>::infinity();

template <class... Args>
std::string text(const char* format, Args... args) {
    char buffer[256];
    std::snprintf(buffer, sizeof(buffer), format, args...);
    return buffer;
}

stress_row row(std::string check, std::string measured, double value, std::string limit,
               bool passed, std::string detail = {}) {
    return {std::move(check), std::move(measured), value, std::move(limit),
            passed,           std::move(detail)};
}

bool finite(glm::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finite(const std::array<glm::vec3, 9>& sh) {
    return std::all_of(sh.begin(), sh.end(), [](glm::vec3 c) { return finite(c); });
}

scenario tiny_scenario() {
    const auto json = embedded_file(k_stress_scenario);
    if (!json) throw std::runtime_error(std::string(k_stress_scenario) + " is not embedded");
    return load_scenario_text(*json, k_stress_scenario);
}

// Plays frames 0 and 1 (the first frame has no previous LOD state) and captures frame 1.
image_rgba8 render_frames(scenario_player& player) {
    player.step();
    player.step();
    return player.capture();
}

// Share of pixels with any of R, G, B off by more than `threshold` (of 255).
double fraction_off(const image_rgba8& a, const image_rgba8& b, int threshold) {
    const std::size_t pixels = std::size_t(a.width) * a.height;
    std::size_t off = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
        bool any = false;
        for (std::size_t c = 0; c < 3; ++c)
            any = any || std::abs(int(a.texels[4 * p + c]) - int(b.texels[4 * p + c])) > threshold;
        off += any ? 1 : 0;
    }
    return pixels ? double(off) / double(pixels) : 1.0;
}

// --- world offsets ---------------------------------------------------------------------------

// A 100 s flight circling the origin at 30-60 m, rising and falling (2,400 frames at 24 fps).
std::vector<camera_keyframe> circling_path(glm::dvec3 offset) {
    std::vector<camera_keyframe> keys;
    for (int k = 0; k <= 8; ++k) {
        const double a = 0.8 * k, radius = 30.0 + 30.0 * (k % 3) / 2.0;
        camera_keyframe key;
        key.time_s = 12.5 * k;
        key.position =
            offset + glm::dvec3(radius * std::cos(a), 4.0 + 3.0 * (k % 2), radius * std::sin(a));
        key.target = offset + glm::dvec3(5.0 * std::sin(a), 2.0, -5.0 * std::cos(a));
        key.fov_deg = 50.0f + float(k);
        keys.push_back(key);
    }
    return keys;
}

camera camera_at(const camera_pose& pose, glm::dvec3 offset) {
    camera cam;
    cam.position = pose.position - offset;
    cam.forward = glm::vec3(glm::normalize(pose.target - pose.position));
    cam.fov_y = glm::radians(pose.fov_deg);
    derive_camera_matrices(cam);
    return cam;
}

double max_abs_difference(const glm::mat4& a, const glm::mat4& b) {
    double d = 0.0;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) d = std::max(d, double(std::abs(a[c][r] - b[c][r])));
    return d;
}

// --- degenerate input ------------------------------------------------------------------------

std::size_t count_zero_area(const mesh_data& mesh) {
    std::size_t n = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
        n += is_zero_area_triangle(mesh.vertices[mesh.indices[t]].position,
                                   mesh.vertices[mesh.indices[t + 1]].position,
                                   mesh.vertices[mesh.indices[t + 2]].position);
    return n;
}

std::string import_error(const fs::path& file) {
    try {
        import_gltf_plant(file, 32);
    } catch (const std::exception& e) {
        return e.what();
    }
    return {};
}

stress_row non_finite_vertex_row(const plant_model& grass, const fs::path& dir, float value,
                                 const std::string& stem, const std::string& token) {
    plant_model bad = grass;
    const std::uint32_t vertex = bad.lods[0].indices[4];  // used by the second triangle
    bad.lods[0].vertices[vertex].position.y = value;
    const fs::path file = dir / (stem + ".glb");
    export_plant_glb(bad, plant_lod::full, file);
    const std::string error = import_error(file);
    const std::string expected = stem + ".glb: mesh 'grass' primitive 0: vertex " +
                                 std::to_string(vertex) + " has a non-finite position (";
    const bool named =
        error.find(expected) != std::string::npos && error.find(token) != std::string::npos;
    return row("glTF vertex y = " + token + ": rejected, named",
               error.empty() ? "imported" : (named ? "rejected" : "rejected, unnamed"),
               named ? 1.0 : 0.0, "error names file, mesh, vertex, " + token, named,
               error.empty() ? "the model imported without an error" : error);
}

// Appends two repeated-index triangles and one of three collinear vertices (binary fractions,
// so collinear in float too) to the last sub-mesh; returns how many it added.
std::uint32_t add_zero_area_triangles(mesh_data& mesh) {
    const auto first = std::uint32_t(mesh.vertices.size());
    const glm::vec3 p{0.25f, 0.5f, -0.125f}, d{0.125f, 0.25f, 0.0625f};
    for (const glm::vec3 q : {p, p + d, p + 2.0f * d})
        mesh.vertices.push_back({q, glm::vec3(0.0f, 1.0f, 0.0f), glm::vec2(0.0f)});
    const std::uint32_t a = mesh.indices[0], b = mesh.indices[1];
    mesh.indices.insert(mesh.indices.end(), {a, a, b, a, b, b, first, first + 1, first + 2});
    mesh.submeshes.back().index_count += 9;
    mesh.parts.resize(mesh.triangle_count(),
                      mesh.parts.empty() ? triangle_part{} : mesh.parts.back());
    return 3;
}

// --- point clusters --------------------------------------------------------------------------

struct cluster_case {
    const char* name;
    std::function<glm::dvec2(std::size_t, std::size_t)> at;  // plant i of n
};

struct tree_stats {
    std::uint16_t depth = 0;
    std::size_t nodes = 0;
    bool one_leaf_each = false;  // every plant in exactly one leaf, inside it
};

tree_stats inspect_tree(const eco_tile_tree& tree, std::span<const glm::dvec2> xz) {
    tree_stats s;
    s.nodes = tree.nodes.size();
    std::vector<int> seen(xz.size(), 0);
    bool inside = tree.order.size() == xz.size();
    for (const eco_tile_node& n : tree.nodes) {
        s.depth = std::max(s.depth, n.depth);
        if (!n.is_leaf()) continue;
        for (std::uint32_t slot = n.first_plant; slot < n.first_plant + n.plant_count; ++slot) {
            const std::uint32_t plant = tree.order[slot];
            ++seen[plant];
            const glm::dvec2 p = xz[plant];
            inside = inside && p.x >= n.min.x && p.x <= n.min.x + n.size && p.y >= n.min.y &&
                     p.y <= n.min.y + n.size;
        }
    }
    s.one_leaf_each = inside && std::all_of(seen.begin(), seen.end(), [](int c) { return c == 1; });
    return s;
}

// The spawner's steps (lod/eco_tiles.h) for plants at `xz`, 1e6 m from the origin, with or
// without tile entities; then one cull. Returns each plant's (visible, in_shadow_range).
std::vector<lod_state> cull_plants(std::span<const glm::dvec2> xz, const eco_tile_tree* tree,
                                   const heightfield& terrain, int threads) {
    const glm::dvec3 offset{1e6, 0.0, 1e6};
    ecs::world world;
    for (std::size_t slot = 0; slot < xz.size(); ++slot) {
        const glm::dvec2 p = xz[tree ? tree->order[slot] : slot];
        const ecs::entity e = world.create();
        world.emplace<world_transform>(
            e, {glm::dvec3(p.x, terrain.height_at(p.x, p.y), p.y) + offset, 0.0f, 1.0f});
        world.emplace<bounds>(e, {3.0f, 4.0f});
        world.emplace<plant_instance>(e, {species_id(slot % 2), 0, std::uint32_t(slot)});
        world.emplace<lod_state>(e);
    }
    world.align<world_transform, bounds, plant_instance, lod_state>();
    if (tree) create_tile_entities(world, *tree, terrain, {7.0f, 1.0f, offset});
    camera cam;
    cam.position = glm::dvec3(-45.0, terrain.height_at(-45.0, 45.0) + 12.0, 45.0) + offset;
    cam.forward = glm::normalize(glm::vec3(1.0f, -0.2f, -1.0f));
    derive_camera_matrices(cam);
    world.emplace<camera>(world.create(), cam);
    species_library library;
    library.species.resize(2);
    library.species[0].max_distance_m = 80.0f;
    library.species[1].max_distance_m = 40.0f;
    world.set_resource(std::move(library));
    shadow_settings shadows;
    shadows.max_distance_m = 30.0f;
    world.set_resource(shadows);
    world.set_resource(lod_policy{});
    ecs::executor executor(threads);
    ecs::schedule schedule;
    schedule.add<cull_system>();
    schedule.run(world, executor);
    const auto& table = world.table<lod_state>();
    std::vector<lod_state> by_plant(xz.size());
    for (std::size_t slot = 0; slot < xz.size(); ++slot)
        by_plant[tree ? tree->order[slot] : slot] = table.data()[slot];
    return by_plant;
}

// --- extreme light ---------------------------------------------------------------------------

constexpr float k_sun_elevations[] = {-90.0f, -10.0f, 0.0f, 45.0f, 90.0f};
constexpr float k_turbidities[] = {1.7f, 10.0f};  // the scenario loader's range

double max_abs(const sh9_rgb& sh) {
    double m = 0.0;
    for (const glm::vec3 c : sh.c)
        m = std::max({m, double(std::abs(c.x)), double(std::abs(c.y)), double(std::abs(c.z))});
    return m;
}

sh9_rgb irradiance_sh(float sky_intensity, float elevation_deg, float turbidity) {
    sky_model sky;
    sky.sun_direction = sun_direction_from_angles(elevation_deg, 135.0f);
    sky.turbidity = turbidity;
    sky.sky_intensity = sky_intensity;
    return irradiance_from_radiance(project_sky(sky, 32, 64));
}

struct light_case {
    std::string name;
    float sun_intensity = 3.0f;
    float sky_intensity = 1.0f;
    float elevation_deg = 40.0f;
    float turbidity = 3.0f;
    enum class expect { black, white, lit, any } image = expect::any;
};

struct image_stats {
    double mean = 0.0;       // of R, G, B, 0..255
    double dark = 0.0;       // share of pixels with every channel <= 2
    double saturated = 0.0;  // share of pixels with every channel >= 250
};

image_stats stats_of(const image_rgba8& image) {
    image_stats s;
    const std::size_t pixels = std::size_t(image.width) * image.height;
    for (std::size_t p = 0; p < pixels; ++p) {
        const std::uint8_t* t = &image.texels[4 * p];
        s.mean += (double(t[0]) + t[1] + t[2]) / 3.0;
        s.dark += std::max({t[0], t[1], t[2]}) <= 2 ? 1.0 : 0.0;
        s.saturated += std::min({t[0], t[1], t[2]}) >= 250 ? 1.0 : 0.0;
    }
    if (pixels == 0) return s;
    s.mean /= double(pixels);
    s.dark /= double(pixels);
    s.saturated /= double(pixels);
    return s;
}

// --- extreme LOD -----------------------------------------------------------------------------

int rank(representation r) {
    switch (r) {
        case representation::mesh_full:
            return 0;
        case representation::mesh_reduced:
            return 1;
        case representation::mesh_far:
            return 2;
        default:
            return 3;
    }
}

std::string lod_scale_error(const std::string& tiny_json, double lod_scale) {
    nlohmann::json doc = nlohmann::json::parse(tiny_json);
    doc["camera"]["lod_scale"] = lod_scale;
    try {
        load_scenario_text(doc.dump(), "lod_scale.json");
    } catch (const scenario_error& e) {
        return e.what();
    }
    return {};
}

// Representations chosen for the plants that got one, after one CPU-only frame.
std::array<std::size_t, 4> representations_played(scenario s, float lod_scale, int threads) {
    s.camera.lod_scale = lod_scale;
    scenario_player player(std::move(s), threads, nullptr);
    player.step();
    std::array<std::size_t, 4> count{};
    const auto& table = player.world().table<lod_state>();
    for (std::size_t i = 0; i < table.size(); ++i)
        if (table.data()[i].current != representation::none)
            ++count[std::size_t(rank(table.data()[i].current))];
    return count;
}

}  // namespace

rows check_world_offset_renders(render::gl_context& context, int threads) {
    context.make_current();
    const scenario base = tiny_scenario();
    scenario_player origin_player(base, threads, &context);
    const image_rgba8 origin = render_frames(origin_player);
    const image_stats origin_stats = stats_of(origin);
    rows out;
    for (const double offset : {1e4, 1e5, 1e6}) {
        scenario s = base;
        s.world_offset = {offset, 0.0, offset};
        scenario_player player(s, threads, &context);
        const image_rgba8 image = render_frames(player);
        const double psnr = psnr_db(origin, image);
        const double off = fraction_off(origin, image, 16);
        // A blank origin would match anything: require a lit, non-uniform frame.
        const bool meaningful = origin_stats.dark < 0.5 && origin_stats.saturated < 0.5;
        out.push_back(row(text("world offset %.0e m: frame vs origin", offset),
                          text("%.1f dB, %.2f %% px", psnr, 100.0 * off), psnr,
                          "> 45 dB, < 1 % px off > 16", psnr > 45.0 && off < 0.01 && meaningful,
                          meaningful ? "" : "the origin frame is blank"));
    }
    return out;
}

rows check_camera_path_offsets() {
    constexpr int k_frames = 2400;  // 100 s at 24 fps
    const std::vector<camera_keyframe> origin_keys = circling_path(glm::dvec3(0.0));
    rows out;
    for (const double offset_m : {1e4, 1e5, 1e6}) {
        const glm::dvec3 offset{offset_m, 0.0, -offset_m};
        const std::vector<camera_keyframe> keys = circling_path(offset);
        double position_error = 0.0, view_error = 0.0;
        for (int f = 0; f <= k_frames; ++f) {
            const double t = double(f) / 24.0;
            const camera_pose at_origin = sample_camera_path(origin_keys, t);
            const camera_pose far_away = sample_camera_path(keys, t);
            position_error = std::max({position_error,
                                       glm::length(far_away.position - offset - at_origin.position),
                                       glm::length(far_away.target - offset - at_origin.target)});
            view_error = std::max(view_error, max_abs_difference(camera_at(far_away, offset).view,
                                                                 camera_at(at_origin, {}).view));
        }
        out.push_back(row(text("camera path at %.0e m, %d frames", offset_m, k_frames),
                          text("%.1e m, view %.1e", position_error, view_error), position_error,
                          "< 1e-6 m, view < 1e-6", position_error < 1e-6 && view_error < 1e-6));
    }
    return out;
}

rows check_degenerate_models(const fs::path& scratch_dir) {
    fs::create_directories(scratch_dir);
    plant_model grass = generate_plant_model("grass", 1, 32);
    grass.name = "grass";
    const float inf = std::numeric_limits<float>::infinity();
    rows out;
    out.push_back(non_finite_vertex_row(grass, scratch_dir, std::numeric_limits<float>::quiet_NaN(),
                                        "nan_vertex", "nan"));
    out.push_back(non_finite_vertex_row(grass, scratch_dir, inf, "plus_inf_vertex", "+inf"));
    out.push_back(non_finite_vertex_row(grass, scratch_dir, -inf, "minus_inf_vertex", "-inf"));

    plant_model slivers = grass;
    const std::uint32_t added = add_zero_area_triangles(slivers.lods[0]);
    export_plant_glb(slivers, plant_lod::full, scratch_dir / "zero_area.glb");
    const gltf_import_result imported = import_gltf_plant(scratch_dir / "zero_area.glb", 32);
    std::size_t left = 0;
    for (const mesh_data& level : imported.model.lods) left += count_zero_area(level);
    const bool kept_real =
        imported.model.lods[0].triangle_count() == grass.lods[0].triangle_count();
    out.push_back(
        row("glTF zero-area triangles: dropped",
            text("%u of %u dropped, %zu left", imported.dropped_degenerate_triangles, added, left),
            double(imported.dropped_degenerate_triangles), "all dropped, none left",
            imported.dropped_degenerate_triangles == added && left == 0 && kept_real,
            kept_real ? "" : "the real triangles were not all kept"));

    for (const std::string_view preset : k_plant_presets) {
        const plant_model m = generate_plant_model(preset, 1, 16);
        std::size_t triangles = 0, zero = 0;
        for (const mesh_data& level : m.lods)
            triangles += level.triangle_count(), zero += count_zero_area(level);
        out.push_back(row("preset " + std::string(preset) + ": zero-area triangles",
                          text("%zu of %zu", zero, triangles), double(zero), "0",
                          zero == 0 && triangles > 0));
    }
    return out;
}

rows check_plant_clusters(int threads) {
    constexpr std::size_t k_plants = 2000;
    constexpr std::uint32_t k_per_tile = 16;
    const std::array<double, 4> area{-50.0, -50.0, 50.0, 50.0};
    const heightfield terrain = generate_terrain(120.0, 33, 8.0f, 3, 0.015f, 11);
    const auto along = [](std::size_t i, std::size_t n) {
        return -40.0 + 80.0 * double(i) / double(n - 1);
    };
    const cluster_case cases[] = {
        {"one point", [](std::size_t, std::size_t) { return glm::dvec2(3.7, -12.1); }},
        {"two points", [](std::size_t i,
                          std::size_t) { return i % 2 ? glm::dvec2(0.0) : glm::dvec2(1e-9, 0.0); }},
        {"x-parallel line",
         [&](std::size_t i, std::size_t n) { return glm::dvec2(along(i, n), 7.3); }},
        {"diagonal line",
         [&](std::size_t i, std::size_t n) { return glm::dvec2(along(i, n), along(i, n)); }},
        {"line on the split x = 0",
         [&](std::size_t i, std::size_t n) { return glm::dvec2(0.0, along(i, n)); }},
    };
    rows out;
    for (const cluster_case& c : cases) {
        std::vector<glm::dvec2> xz(k_plants);
        for (std::size_t i = 0; i < k_plants; ++i) xz[i] = c.at(i, k_plants);
        const eco_tile_tree tree = build_eco_tiles(xz, area, k_per_tile);
        const tree_stats s = inspect_tree(tree, xz);
        const std::vector<lod_state> flat = cull_plants(xz, nullptr, terrain, threads);
        const std::vector<lod_state> tiled = cull_plants(xz, &tree, terrain, threads);
        std::size_t mismatches = 0, visible = 0;
        for (std::size_t i = 0; i < k_plants; ++i) {
            mismatches += flat[i].visible != tiled[i].visible ||
                          flat[i].in_shadow_range != tiled[i].in_shadow_range;
            visible += flat[i].visible;
        }
        // Each subdivision that makes no progress adds 4 nodes per level: 4 x depth cap + 1
        // per group of k_per_tile + 1 plants bounds a tree of coincident plants.
        const std::size_t node_limit =
            (4 * k_max_eco_tile_depth + 1) * (k_plants / (k_per_tile + 1) + 1);
        out.push_back(
            row(text("eco tiles, %zu plants: %s", k_plants, c.name),
                text("depth %u, %zu nodes, %zu cull diffs", unsigned(s.depth), s.nodes, mismatches),
                double(mismatches),
                text("depth <= %u, 1 leaf/plant, 0 diffs", unsigned(k_max_eco_tile_depth)),
                s.depth <= k_max_eco_tile_depth && s.nodes <= node_limit && s.one_leaf_each &&
                    mismatches == 0 && visible > 0,
                text("%zu plants visible%s", visible,
                     s.one_leaf_each ? "" : "; a plant is not in exactly one leaf")));
    }
    return out;
}

rows check_extreme_sky() {
    rows out;
    std::vector<sh9_rgb> unit;  // sky intensity 1, per (elevation, turbidity)
    for (const float e : k_sun_elevations)
        for (const float t : k_turbidities) unit.push_back(irradiance_sh(1.0f, e, t));
    for (const float intensity : {0.0f, 1e-6f, 1.0f, 1e6f, 1e12f}) {
        bool all_finite = true;
        double linear_error = 0.0;
        std::size_t k = 0;
        for (const float e : k_sun_elevations)
            for (const float t : k_turbidities) {
                const sh9_rgb sh = irradiance_sh(intensity, e, t);
                const sh9_rgb& one = unit[k++];
                all_finite = all_finite && finite(sh.c);
                const double scale = std::max(max_abs(one) * double(intensity), 1e-300);
                for (std::size_t i = 0; i < 9; ++i)
                    for (int ch = 0; ch < 3; ++ch)
                        linear_error = std::max(
                            linear_error,
                            std::abs(double(sh.c[i][ch]) - double(one.c[i][ch]) * intensity) /
                                scale);
            }
        // Zero sky must give exactly zero light; otherwise SH(I) = I SH(1) to float rounding.
        const bool ok = all_finite && linear_error < 1e-5;
        out.push_back(row(
            text("sky SH, sky intensity %g", double(intensity)),
            all_finite ? text("finite, rel err %.1e", linear_error) : "NOT finite", linear_error,
            intensity == 0.0f ? "finite, all 0" : "finite, I x SH(1) +- 1e-5", ok,
            text("%zu sun elevations -90..90 x turbidity 1.7, 10", std::size(k_sun_elevations))));
    }
    // The sun's colour times its intensity is what the shader gets (renderer.cpp write_uniforms).
    bool sun_finite = true, dark_below = true;
    float brightest = 0.0f;
    for (const float intensity : {0.0f, 1e-6f, 1e6f, 1e12f})
        for (const float e : k_sun_elevations)
            for (const float t : k_turbidities) {
                const glm::vec3 radiance = sun_radiance_color(glm::radians(e), t) * intensity;
                sun_finite = sun_finite && finite(radiance) &&
                             glm::all(glm::greaterThanEqual(radiance, glm::vec3(0.0f)));
                if (e < -1.0f) dark_below = dark_below && radiance == glm::vec3(0.0f);
                brightest = std::max(brightest, radiance.y);
                sun_finite = sun_finite && finite(sun_direction_from_angles(e, 135.0f));
            }
    out.push_back(row("sun radiance, intensity 0..1e12",
                      text("finite, max %.2g", double(brightest)), double(brightest),
                      "finite, >= 0, 0 below -1 deg", sun_finite && dark_below));
    // Out-of-range inputs through the API (the loader never lets them through): clamped.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    sky_model hazy;
    hazy.turbidity = nan;
    const bool odd_ok = finite(irradiance_sh(1.0f, 45.0f, nan).c) &&
                        finite(hazy.radiance(glm::vec3(0.0f, 1.0f, 0.0f))) &&
                        finite(sun_radiance_color(nan, 3.0f)) &&
                        finite(sun_radiance_color(0.5f, nan));
    out.push_back(row("sky and sun, NaN turbidity / elevation", odd_ok ? "finite" : "NOT finite",
                      odd_ok ? 1.0 : 0.0, "finite", odd_ok));
    return out;
}

rows check_extreme_light_renders(render::gl_context& context, int threads) {
    using expect = light_case::expect;
    const light_case cases[] = {
        {"sun 0, sky 0", 0.0f, 0.0f, 40.0f, 3.0f, expect::black},
        {"sun 1e-6, sky 1e-6", 1e-6f, 1e-6f, 40.0f, 3.0f, expect::black},
        {"sun 1e6, sky 1e6", 1e6f, 1e6f, 40.0f, 3.0f, expect::white},
        {"sun 1e12, sky 1e12 (API)", 1e12f, 1e12f, 40.0f, 3.0f, expect::white},
        {"sun below horizon (-90)", 3.0f, 1.0f, -90.0f, 3.0f, expect::any},
        {"sun on the horizon (0)", 3.0f, 1.0f, 0.0f, 3.0f, expect::lit},
        {"sun at the zenith (90)", 3.0f, 1.0f, 90.0f, 3.0f, expect::lit},
        {"turbidity 1.7", 3.0f, 1.0f, 40.0f, 1.7f, expect::lit},
        {"turbidity 10", 3.0f, 1.0f, 40.0f, 10.0f, expect::lit},
    };
    context.make_current();
    const scenario base = tiny_scenario();
    rows out;
    for (const light_case& c : cases) {
        scenario s = base;
        s.sun.keyframes = {{0.0, c.elevation_deg, 135.0f}};
        s.sun.turbidity = c.turbidity;
        scenario_player player(s, threads, &context);
        // Set directly so 1e12 (beyond the loader's 1e6) reaches update_sun and the projection.
        player.world().resource<sun_track>().intensity = c.sun_intensity;
        player.world().single<environment>().sky_intensity = c.sky_intensity;
        const image_rgba8 image = render_frames(player);
        const sun& light = player.world().single<sun>();
        const environment& env = player.world().single<environment>();
        const bool uniforms_finite = finite(light.direction) &&
                                     finite(light.color * light.intensity) &&
                                     finite(env.irradiance_sh);
        const image_stats st = stats_of(image);
        bool image_ok = image.width == base.width && image.height == base.height;
        std::string limit = "SH, sun finite";
        // NaN reaching the framebuffer is written as 0 by llvmpipe, so a saturated scene with
        // black pixels would show it; a lit scene must have (almost) no black pixels.
        switch (c.image) {
            case expect::black:
                image_ok = image_ok && st.dark == 1.0;
                limit += "; all px <= 2";
                break;
            case expect::white:
                image_ok = image_ok && st.saturated > 0.99;
                limit += "; > 99 % px >= 250";
                break;
            case expect::lit:
                image_ok = image_ok && st.dark < 0.01 && st.mean > 10.0;
                limit += "; lit, < 1 % px black";
                break;
            case expect::any:
                break;
        }
        out.push_back(row("render " + c.name,
                          text("%s, mean %.0f, %.0f %% white", uniforms_finite ? "finite" : "NaN",
                               st.mean, 100.0 * st.saturated),
                          st.mean, limit, uniforms_finite && image_ok,
                          text("%.1f %% of pixels black", 100.0 * st.dark)));
    }
    return out;
}

rows check_time_drift(int threads) {
    rows out;
    // The clock stepped frame by frame as the player does, against a naive accumulator.
    playback_clock clock{0, 24.0};
    double accumulated = 0.0, clock_drift = 0.0, naive_drift = 0.0;
    constexpr std::uint64_t k_frames = 10'000'000;
    for (std::uint64_t f = 0; f <= k_frames; ++f) {
        clock.frame = f;
        const double direct = double(f) / 24.0;
        clock_drift = std::max(clock_drift, std::abs(clock.time_s() - direct));
        if (f == 1'000'000 || f == k_frames)
            naive_drift = std::max(naive_drift, std::abs(accumulated - direct));
        accumulated += 1.0 / 24.0;
    }
    out.push_back(row("clock stepped to frame 1e7 (24 fps)", text("%.1e s", clock_drift),
                      clock_drift, "0 s", clock_drift == 0.0,
                      text("adding 1/24 per frame would drift %.1e s", naive_drift)));

    // A straight 1 m/s path 1e6 m out: collinear, evenly spaced keys make the centripetal spline
    // exactly linear (equal key velocities, Hermite tangents = chords), so x(t) = t.
    const glm::dvec3 offset{1e6, 0.0, 1e6};
    std::vector<camera_keyframe> line;
    for (int k = 0; k <= 5; ++k) {
        const double t = 2e5 * k;
        line.push_back(
            {t, offset + glm::dvec3(t, 10.0, 0.0), offset + glm::dvec3(t + 50.0, 8.0, 0.0), 55.0f});
    }
    double position_error = 0.0, step_error = 0.0;
    for (const std::uint64_t start : {1'000'000ULL, 10'000'000ULL, 23'999'000ULL})
        for (std::uint64_t f = start; f < start + 1000; ++f) {
            const double t = double(f) / 24.0;
            const double x = sample_camera_path(line, t).position.x - offset.x;
            const double next =
                sample_camera_path(line, double(f + 1) / 24.0).position.x - offset.x;
            position_error = std::max(position_error, std::abs(x - t));
            step_error = std::max(step_error, std::abs((next - x) * 24.0 - 1.0));
        }
    out.push_back(
        row("1 m/s path at 1e6 m, frames 1e6..2.4e7",
            text("%.1e m, step %.1e", position_error, step_error), position_error,
            "< 1e-6 m, step +- 1e-6", position_error < 1e-6 && step_error < 1e-6,
            "x(frame / 24) against frame / 24 m; step: (x(f+1) - x(f)) x 24 against 1 m/s"));

    // The sun from -10 to 80 degrees over 1e6 s: linear, monotone frame to frame.
    sun_track track;
    track.keys = {{0.0, -10.0f, 90.0f}, {1e6, 80.0f, 270.0f}};
    double elevation_error = 0.0;
    bool monotone = true;
    float previous = -1e9f;
    for (std::uint64_t f = 10'000'000; f < 10'001'000; ++f) {
        const double t = double(f) / 24.0;
        const float e = sample_sun_track(track, t).elevation_deg;
        elevation_error = std::max(elevation_error, std::abs(double(e) - (-10.0 + 90.0 * t / 1e6)));
        monotone = monotone && e >= previous;
        previous = e;
    }
    out.push_back(row("sun path at frame 1e7", text("%.1e deg", elevation_error), elevation_error,
                      "< 1e-4 deg, monotone", elevation_error < 1e-4 && monotone));

    // Beyond the last key the pose holds; a NaN or infinite time never reaches the spline.
    const scenario s = tiny_scenario();
    std::vector<camera_keyframe> keys;
    for (const auto& k : s.camera.keyframes) keys.push_back(k.key);
    bool holds = true;
    for (const double t : {keys.back().time_s + 1e-9, 1e6 / 24.0, 1e7 / 24.0, k_inf})
        holds = holds && sample_camera_path(keys, t).position == keys.back().position;
    for (const double t : {-1.0, -k_inf, k_nan})
        holds = holds && sample_camera_path(keys, t).position == keys.front().position;
    out.push_back(row("camera path past its last key", holds ? "holds last key" : "moves",
                      holds ? 1.0 : 0.0, "last key; NaN, < 0: first key", holds));

    // The whole frame at frames 1e6 and 1e7: camera and sun equal direct evaluation.
    scenario long_play = s;
    long_play.sun.keyframes = {{0.0, 10.0f, 90.0f}, {1e6, 60.0f, 180.0f}};
    scenario_player player(long_play, threads, nullptr);
    bool exact = true;
    for (const std::uint64_t f : {1'000'000ULL, 10'000'000ULL}) {
        player.set_frame(f);
        player.step();
        const double t = double(f) / long_play.fps;
        const auto& track_keys = player.world().resource<camera_track>().keys;
        exact = exact && player.world().single<camera>().position ==
                             sample_camera_path(track_keys, t).position;
        exact =
            exact && player.world().single<sun>().elevation_deg ==
                         sample_sun_track(player.world().resource<sun_track>(), t).elevation_deg;
    }
    out.push_back(row("player at frames 1e6, 1e7", exact ? "camera, sun exact" : "differ",
                      exact ? 1.0 : 0.0, "== path(frame / fps)", exact));
    return out;
}

rows check_extreme_lod(int threads) {
    rows out;
    species_entry species;
    species.reduced_distance_m = 30.0f;
    species.far_distance_m = 60.0f;
    std::vector<float> distances = {0.0f, 1e-30f};
    for (float d = 1e-3f; d < 1e30f; d *= 3.1f) distances.push_back(d);
    distances.push_back(1e30f);
    distances.push_back(std::numeric_limits<float>::infinity());
    std::size_t finer_farther = 0, sweeps = 0;
    bool nan_far = true, inf_far = true;
    for (const float lod_scale : {0.01f, 1.0f, 100.0f})
        for (const float scale : {0.0f, 1e-30f, 0.8f, 100.0f}) {
            int previous = 0;
            for (const float d : distances) {
                const int r = rank(choose_representation(species, d, scale, lod_scale));
                finer_farther += r < previous ? 1 : 0;
                previous = r;
            }
            ++sweeps;
            nan_far =
                nan_far && choose_representation(species, std::numeric_limits<float>::quiet_NaN(),
                                                 scale, lod_scale) == representation::mesh_far;
            inf_far =
                inf_far && choose_representation(species, std::numeric_limits<float>::infinity(),
                                                 scale, lod_scale) == representation::mesh_far;
        }
    out.push_back(row(text("LOD choice, %zu sweeps 0..inf m", sweeps),
                      text("%zu finer when farther", finer_farther), double(finer_farther), "0",
                      finer_farther == 0,
                      "lod_scale 0.01, 1, 100 x plant scale 0, 1e-30, 0.8, 100"));
    out.push_back(row("LOD choice at NaN and inf distance",
                      nan_far && inf_far ? "far mesh" : "finer than far",
                      nan_far && inf_far ? 1.0 : 0.0, "far mesh", nan_far && inf_far,
                      "a comparison with NaN is false, so NaN falls through to the far mesh"));

    const std::string tiny_json(*embedded_file(k_stress_scenario));
    const std::string low = lod_scale_error(tiny_json, 0.009),
                      high = lod_scale_error(tiny_json, 101.0);
    const std::string expected =
        "/camera/lod_scale: out of range; expected a number from 0.01 to 100";
    const bool rejected =
        low.find(expected) != std::string::npos && high.find(expected) != std::string::npos;
    const bool accepted =
        lod_scale_error(tiny_json, 0.01).empty() && lod_scale_error(tiny_json, 100.0).empty();
    out.push_back(row("loader lod_scale 0.009, 101 / 0.01, 100",
                      rejected && accepted ? "rejected / loaded" : "wrong",
                      rejected && accepted ? 1.0 : 0.0, "usual range error", rejected && accepted,
                      rejected ? "" : low + " | " + high));

    // At 100 every switch distance is beyond the 120 m scene: full meshes only. At 0.01 the draw
    // distance is 4 m (nothing visible) and the plants cast shadows with their far meshes.
    const scenario s = tiny_scenario();
    const auto at_100 = representations_played(s, 100.0f, threads);
    const auto at_001 = representations_played(s, 0.01f, threads);
    const bool sane =
        at_100[0] > 0 && at_100[1] + at_100[2] == 0 && at_001[2] > 0 && at_001[0] + at_001[1] == 0;
    out.push_back(row("play tiny at lod_scale 100 / 0.01",
                      text("%zu full / %zu far", at_100[0], at_001[2]), double(at_100[0]),
                      "all full / all far", sane,
                      text("at 100: %zu reduced, %zu far; at 0.01: %zu full, %zu reduced",
                           at_100[1], at_100[2], at_001[0], at_001[1])));
    return out;
}

rows run_stress_checks(const stress_options& options) {
    const fs::path scratch =
        options.scratch_dir.empty()
            ? fs::temp_directory_path() / ("sylva_stress_" + std::to_string(::getpid()))
            : options.scratch_dir;
    rows all;
    const auto add = [&](const std::string& name, const std::function<rows()>& check) {
        try {
            for (stress_row& r : check()) all.push_back(std::move(r));
        } catch (const std::exception& e) {
            all.push_back(row(name, "threw", 0.0, "no exception", false, e.what()));
        }
    };
    const auto gl = [&](const std::string& name,
                        const std::function<rows(render::gl_context&)>& check) {
        if (options.context)
            add(name, [&] { return check(*options.context); });
        else
            all.push_back(
                row(name, "not run", 0.0, "a GL 4.5 context", false, "no GL context (OSMesa)"));
    };
    gl("world offset renders",
       [&](render::gl_context& c) { return check_world_offset_renders(c, options.threads); });
    add("camera path offsets", [] { return check_camera_path_offsets(); });
    add("degenerate models", [&] { return check_degenerate_models(scratch); });
    add("plant clusters", [&] { return check_plant_clusters(options.threads); });
    add("extreme sky", [] { return check_extreme_sky(); });
    gl("extreme light renders",
       [&](render::gl_context& c) { return check_extreme_light_renders(c, options.threads); });
    add("time drift", [&] { return check_time_drift(options.threads); });
    add("extreme LOD", [&] { return check_extreme_lod(options.threads); });
    if (options.scratch_dir.empty()) {
        std::error_code ec;
        fs::remove_all(scratch, ec);
    }
    return all;
}

std::string format_stress_table(const rows& table) {
    const char* headers[] = {"check", "measured", "limit", "result"};
    std::size_t width[3] = {std::char_traits<char>::length(headers[0]),
                            std::char_traits<char>::length(headers[1]),
                            std::char_traits<char>::length(headers[2])};
    for (const stress_row& r : table) {
        width[0] = std::max(width[0], r.check.size());
        width[1] = std::max(width[1], r.measured.size());
        width[2] = std::max(width[2], r.limit.size());
    }
    const auto line = [&](const std::string& a, const std::string& b, const std::string& c,
                          const std::string& d) {
        std::string s = a + std::string(width[0] - a.size() + 2, ' ') + b +
                        std::string(width[1] - b.size() + 2, ' ') + c +
                        std::string(width[2] - c.size() + 2, ' ') + d;
        return s + "\n";
    };
    std::string out = line(headers[0], headers[1], headers[2], headers[3]);
    out += line(std::string(width[0], '-'), std::string(width[1], '-'), std::string(width[2], '-'),
                "------");
    std::size_t failed = 0;
    for (const stress_row& r : table) {
        out += line(r.check, r.measured, r.limit, r.passed ? "pass" : "FAIL");
        failed += r.passed ? 0 : 1;
    }
    out +=
        text("\n%zu checks, %zu passed, %zu failed\n", table.size(), table.size() - failed, failed);
    for (const stress_row& r : table)
        if (!r.passed && !r.detail.empty()) out += "  FAIL " + r.check + ": " + r.detail + "\n";
    return out;
}

}  // namespace sylva
