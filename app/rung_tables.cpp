#include "app/rung_tables.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "app/one_plant_view.h"
#include "app/scenario_player.h"
#include "components/transform.h"
#include "lod/point_line_lod.h"
#include "measure/image_metrics.h"
#include "models/bake/crossed_billboard.h"
#include "models/image/image_ops.h"
#include "resources/playback.h"
#include "scenarios/scenario_loader.h"
#include "systems/update_lodf_system.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_format_version = 6;  // 3: from 2 px, the error between 2x2 block means; 4: shader work;
                                                // 6: the shadow's cascade texel;
                                                // 5: the error judged in a patch of the population,
                                                //    and the SSIM it loses

struct view_sample {
    double error_per_pixel = 0.0;
    double structure_error_per_pixel = 0.0;
    double plant_pixels = 0.0;
    double drawn_pixels = 0.0;
};

// The colour difference is taken between 2x2 block means of the two images, over the blocks
// either plant touches: a plant among many of its kind is seen through its neighbours, and what
// a frame's SSIM and FLIP hold against it is mostly what shifts the local mean (coverage lost,
// colour changed) rather than one-sample aliasing that its neighbours average out.
//
// Measured against the per-pixel difference of the first tables (with the sizes from 2 px), on
// `meadow` at 480x270 auto_1000 covered the plants with IoU 0.680 against 0.551, SSIM 0.804
// against 0.791, FLIP 0.073 against 0.077; on `default` it lost a little (SSIM 0.774 against
// 0.777, FLIP 0.072 against 0.073). Three other errors were tried and left out: docs/
// representations/ladder.md, "Where the tables fell short".
constexpr std::uint32_t k_error_block = 2;

view_sample compare(const image_rgba8& reference, const std::vector<std::uint32_t>& reference_ids,
                    const image_rgba8& image, const std::vector<std::uint32_t>& ids) {
    view_sample v;
    const std::uint32_t width = image.width, bw = width / k_error_block, bh = image.height / k_error_block;
    std::vector<std::uint8_t> touched(std::size_t(bw) * bh, 0);
    for (std::size_t i = 0; i < ids.size() && i < reference_ids.size(); ++i) {
        const bool a = reference_ids[i] != 0, b = ids[i] != 0;
        v.plant_pixels += a;
        v.drawn_pixels += b;
        const std::uint32_t x = std::uint32_t(i % width) / k_error_block, y = std::uint32_t(i / width) / k_error_block;
        if ((a || b) && x < bw && y < bh) touched[std::size_t(y) * bw + x] = 1;
    }
    const image_rgba8 ra = box_downsample(reference, k_error_block), ia = box_downsample(image, k_error_block);
    double error = 0.0;
    for (std::size_t j = 0; j < touched.size(); ++j) {
        if (!touched[j]) continue;
        for (std::size_t c = 0; c < 3; ++c)
            error += std::abs(int(ra.texels[4 * j + c]) - int(ia.texels[4 * j + c])) / (3.0 * 255.0);
    }
    error *= double(k_error_block * k_error_block);  // per pixel of the block
    v.error_per_pixel = error / std::max(1.0, v.plant_pixels);
    // What the frame's mean SSIM loses to the plant: 1 − SSIM summed over the windows centred
    // on a pixel either plant covers (a frame's 1 − MSSIM is that sum over all its windows,
    // over their number).
    const ssim_windows map = ssim_map(reference, image);
    const std::size_t half = (width - map.width) / 2;
    double structure = 0.0;
    for (std::size_t y = 0; y < map.height; ++y)
        for (std::size_t x = 0; x < map.width; ++x) {
            const std::size_t centre = (y + half) * width + x + half;
            if (centre < ids.size() && centre < reference_ids.size() && (ids[centre] != 0 || reference_ids[centre] != 0))
                structure += 1.0 - map.values[y * map.width + x];
        }
    v.structure_error_per_pixel = std::max(0.0, structure) / std::max(1.0, v.plant_pixels);
    return v;
}

struct reference_view {
    image_rgba8 image;
    std::vector<std::uint32_t> ids;
};

// Every view of `s`'s full geometry at 3x3 samples per pixel, in the order measure_views walks.
std::vector<reference_view> reference_views(const scenario& s, render::gl_context& context, bake_cache* cache,
                                            double eye_height_m) {
    scenario big = s;
    big.width = big.height = s.width * k_one_plant_reference_samples;
    player_options full(geometry_mode::full);
    full.id_buffer = true;
    full.scenario_lod = false;
    scenario_player reference(big, 0, &context, cache, full);
    std::vector<reference_view> views;
    for (const float size : k_rung_table_sizes_px)
        for (const float azimuth : k_rung_table_directions) {
            aim_at_plant(reference, size, azimuth, s.height, eye_height_m);  // the same camera: 3x the pixels
            (void)reference.step();
            views.push_back({box_downsample(reference.capture(), k_one_plant_reference_samples),
                             reference.capture_plant_ids(k_one_plant_reference_samples)});
        }
    return views;
}

// What a rung is measured as, beyond the rung itself: as its species' ladder draws it.
struct rung_context {
    float lodf_top_px = 0.0f;  // where the ladder starts LoDF (0: every leaf at every size)
    representation caster = representation::none;  // what it casts its shadow as, another rung (none: itself)
};

// Draws every view of `s` with rung `r` and hands each to `seen(size index, record, sample)`.
// The LoDF rung draws the leaves a ladder whose LoDF rung is whole below `lodf_top_px` gives a
// plant of each size (systems/update_lodf_system.h lodf_leaves_at), so its table holds what a
// frame's LoDF plant of that size draws, not the whole foliage; a rung whose ladder names its
// caster casts as it (ladder::shadow), so its table holds that shadow's cost and error.
void measure_views(const scenario& s, representation r, const point_line_quality& points,
                   render::gl_context& context, bake_cache* cache, double eye_height_m, const rung_context& as,
                   const std::vector<reference_view>& references,
                   const std::function<void(std::size_t, const frame_record&, const view_sample&)>& seen) {
    player_options options;
    options.policy = {lod_policy::kind::single, r, r, 0.0f};
    options.policy.points = points;
    // update_lodf and build_draw_list read both from the species' ladder: one that says only that.
    ladder own;
    if (r == representation::lodf && as.lodf_top_px > 0.0f) {
        own.count = 2;
        own.rungs = {representation::mesh_full, representation::lodf};
        own.below_px[1] = as.lodf_top_px;
    } else if (as.caster != representation::none) {
        own.count = 1;
        own.rungs[0] = r;
        own.shadow[0] = as.caster;
    }
    if (own.count > 0) options.policy.ladders.assign(s.species.size(), own);
    options.scenario_lod = false;
    options.measure_costs = false;
    options.id_buffer = true;
    scenario_player player(s, 0, &context, cache, options);
    std::size_t view = 0;
    for (std::size_t i = 0; i < k_rung_table_size_count; ++i)
        for (const float azimuth : k_rung_table_directions) {
            aim_at_plant(player, k_rung_table_sizes_px[i], azimuth, s.height, eye_height_m);
            const frame_record record = player.step();
            const reference_view& ref = references[view++];
            seen(i, record, compare(ref.image, ref.ids, player.capture(), player.capture_plant_ids()));
        }
}

// A rung's error is judged in `patch` (the species among its own population, species_patch),
// what it costs and covers on `one` plant alone: the solver adds plants' errors and costs one by
// one and weighs each by what the last frame showed of it (resources/seen_pixels.h).
species_rung_measurements measure_species(const scenario& one, const scenario& patch,
                                          const std::vector<representation>& rungs,
                                          const point_line_quality& points, render::gl_context& context,
                                          bake_cache* cache, double eye_height_m,
                                          const std::vector<rung_context>& drawn_as) {
    species_rung_measurements out;
    out.species = one.species[0].name;
    // A lone plant's patch is the plant alone (species_patch): its views are measured once.
    const bool lone = patch == one;
    // Every reference first: one player at a time holds the context's frame.
    const std::vector<reference_view> alone = reference_views(one, context, cache, eye_height_m);
    const std::vector<reference_view> among =
        lone ? std::vector<reference_view>{} : reference_views(patch, context, cache, eye_height_m);
    // The same views without the plant: what the terrain and sky cost there, taken off each
    // rung's shader work so its tables hold only the plant's.
    struct view_work {
        double vertices = 0.0, fragments = 0.0, shadow_vertices = 0.0, shadow_fragments = 0.0;
    };
    const auto work_of = [](const frame_record& r) {
        return view_work{double(r.vertices), double(r.fragments), double(r.shadow_vertices),
                         double(r.shadow_fragments)};
    };
    std::vector<view_work> empty;
    {
        player_options options;
        options.policy = {lod_policy::kind::single, representation::none, representation::none, 0.0f};
        options.scenario_lod = false;
        options.measure_costs = false;
        scenario_player player(one, 0, &context, cache, options);
        for (const float size : k_rung_table_sizes_px)
            for (const float azimuth : k_rung_table_directions) {
                aim_at_plant(player, size, azimuth, one.height, eye_height_m);
                const frame_record record = player.step();
                out.work_counted = record.work_counted;
                empty.push_back(work_of(record));
            }
    }
    const double n = double(k_rung_table_directions.size());
    for (std::size_t k = 0; k < rungs.size(); ++k) {
        const representation r = rungs[k];
        const rung_context& as = drawn_as[k];
        rung_measurement m;
        m.rung = r;
        const auto add_error = [&](std::size_t s, const view_sample& v) {
            m.error_per_pixel[s] += float(v.error_per_pixel / n);
            m.structure_error_per_pixel[s] += float(v.structure_error_per_pixel / n);
        };
        std::size_t view = 0;
        std::array<float, k_rung_table_size_count> casting_views{};  // views whose plant cast, per size
        measure_views(one, r, points, context, cache, eye_height_m, as, alone,
                      [&](std::size_t s, const frame_record& record, const view_sample& v) {
                          if (record.caster_texel_m > 0.0) {
                              m.shadow_texel_m[s] += float(record.caster_texel_m);
                              casting_views[s] += 1.0f;
                          }
                          m.plant_pixels[s] += float(v.plant_pixels / n);
                          m.drawn_pixels[s] += float(v.drawn_pixels / n);
                          m.triangles[s] += float(double(record.triangles) / n);
                          m.shadow_triangles[s] += float(double(record.shadow_triangles) / n);
                          m.points[s] += float(double(record.points) / n);
                          m.lines[s] += float(double(record.lines) / n);
                          const view_work w = work_of(record), e = empty[view++];
                          m.vertices[s] += float(std::max(0.0, w.vertices - e.vertices) / n);
                          m.fragments[s] += float(std::max(0.0, w.fragments - e.fragments) / n);
                          m.shadow_vertices[s] += float(std::max(0.0, w.shadow_vertices - e.shadow_vertices) / n);
                          m.shadow_fragments[s] += float(std::max(0.0, w.shadow_fragments - e.shadow_fragments) / n);
                          if (lone) add_error(s, v);
                      });
        for (std::size_t s = 0; s < k_rung_table_size_count; ++s)
            if (casting_views[s] > 0.0f) m.shadow_texel_m[s] /= casting_views[s];
        if (!lone)
            measure_views(patch, r, points, context, cache, eye_height_m, as, among,
                          [&](std::size_t s, const frame_record&, const view_sample& v) { add_error(s, v); });
        out.rungs.push_back(m);
    }
    return out;
}

std::uint64_t table_key(const scenario& one, const scenario& patch, const std::vector<representation>& rungs,
                        const point_line_quality& points, double eye_height_m,
                        const std::vector<rung_context>& drawn_as) {
    std::ostringstream text;
    text << scenario_to_json_text(one) << "|patch:" << scenario_to_json_text(patch) << "|eye:" << eye_height_m << "|rungs";
    for (const representation r : rungs) text << ':' << int(r);
    // Only the rungs their ladder draws otherwise add to the key (the other tables' keys, and so
    // what the cache holds for them, stay as they were): LoDF by where it starts, a caster.
    for (std::size_t k = 0; k < rungs.size(); ++k) {
        // (",cascade0": since LoDF's foliage casts into the first cascade only, the full
        // mesh's coarser levels into the farther ones.)
        if (rungs[k] == representation::lodf) text << "|lodf_top:" << drawn_as[k].lodf_top_px << ",cascade0";
        if (drawn_as[k].caster != representation::none)
            text << "|shadow:" << int(rungs[k]) << '>' << int(drawn_as[k].caster);
    }
    text << "|points:" << points.sample_distance_px << ',' << points.splat_factor << ','
         << int(points.splats) << ',' << int(points.fog_weighted) << "|version:"
         << k_format_version
         // The bakes the tables measure keep their own keys; the billboards' is not in the
         // scenario's text (a new bake of the facing views must not reuse the old tables).
         << "|billboards:" << k_crossed_billboard_format;
    const std::string key = text.str();
    return fnv1a(key.data(), key.size());
}

// What the solver reads of a rung's error at table size i: the colour error plus the SSIM it
// loses, weighed by k_structure_weight. The bench judges a frame by both SSIM and FLIP. Measured
// with patch tables on `default` at 480x270 (12 frames): the colour error alone bought FLIP and
// lost SSIM (auto_500 SSIM 0.788, FLIP 0.068), 1 − SSIM alone the other way (auto_250 SSIM
// 0.776, FLIP 0.080); the sum with 0.1 (1 − SSIM per plant pixel runs about ten times the
// colour error) gave auto_250 0.784 / 0.073 and auto_500 0.798 / 0.069, and on `forest`
// auto_500 0.764 against 0.755 with colour alone (docs/representations/ladder.md).
constexpr double k_structure_weight = 0.1;

double table_error_per_pixel(const rung_measurement& m, std::size_t i) {
    return double(m.error_per_pixel[i]) + k_structure_weight * double(m.structure_error_per_pixel[i]);
}

}  // namespace

double typical_eye_height_m(const scenario& s, const std::function<double(double, double)>& terrain_height) {
    std::vector<double> heights;
    for (const scenario_camera_key& k : s.camera.keyframes) {
        const glm::dvec3 p = k.key.position;
        heights.push_back(k.above_terrain ? p.y : p.y - terrain_height(p.x, p.z));
    }
    if (heights.empty()) return k_rung_table_level_eye;
    std::sort(heights.begin(), heights.end());
    const std::size_t n = heights.size();
    const double median = n % 2 ? heights[n / 2] : 0.5 * (heights[n / 2 - 1] + heights[n / 2]);
    return std::max(0.5, std::round(2.0 * median) / 2.0);
}

std::vector<std::byte> encode_rung_measurements(const species_rung_measurements& m) {
    binary_writer out;
    out.pod(k_format_version);
    out.pod(std::uint32_t(k_rung_table_size_count));
    out.text(m.species);
    out.pod(std::uint8_t(m.work_counted));
    out.pod(std::uint32_t(m.rungs.size()));
    for (const rung_measurement& r : m.rungs) {
        out.pod(std::uint8_t(r.rung));
        for (const auto* table : {&r.error_per_pixel, &r.structure_error_per_pixel, &r.plant_pixels, &r.drawn_pixels, &r.triangles,
                                  &r.shadow_triangles, &r.points, &r.lines, &r.vertices, &r.fragments,
                                  &r.shadow_vertices, &r.shadow_fragments, &r.shadow_texel_m})
            out.pod(*table);
    }
    return std::move(out.bytes());
}

species_rung_measurements decode_rung_measurements(std::span<const std::byte> bytes) {
    binary_reader in(bytes);
    if (in.pod<std::uint32_t>() != k_format_version) throw std::runtime_error("rung table: another version");
    if (in.pod<std::uint32_t>() != k_rung_table_size_count)
        throw std::runtime_error("rung table: another number of sizes");
    species_rung_measurements m;
    m.species = in.text();
    m.work_counted = in.pod<std::uint8_t>() != 0;
    const auto count = in.pod<std::uint32_t>();
    if (count >= std::uint32_t(representation::count))
        throw std::runtime_error("rung table: " + std::to_string(count) + " rungs");
    for (std::uint32_t i = 0; i < count; ++i) {
        rung_measurement r;
        const auto rung = in.pod<std::uint8_t>();
        if (rung == 0 || rung >= std::uint8_t(representation::count))
            throw std::runtime_error("rung table: rung " + std::to_string(rung) + " is no representation");
        r.rung = representation(rung);
        for (auto* table : {&r.error_per_pixel, &r.structure_error_per_pixel, &r.plant_pixels, &r.drawn_pixels, &r.triangles, &r.shadow_triangles,
                            &r.points, &r.lines, &r.vertices, &r.fragments, &r.shadow_vertices,
                            &r.shadow_fragments, &r.shadow_texel_m}) {
            *table = in.pod<std::array<float, k_rung_table_size_count>>();
            for (const float v : *table)
                if (!std::isfinite(v) || v < 0.0f) throw std::runtime_error("rung table: a value of " + std::to_string(v));
        }
        m.rungs.push_back(r);
    }
    if (!in.at_end()) throw std::runtime_error("rung table: bytes after the last rung");
    return m;
}

species_rung_tables solver_tables(const species_rung_measurements& m, const ladder& ladder,
                                  const std::optional<primitive_cost_model>& model, const point_line_quality& q,
                                  const std::optional<shader_work_costs>& work) {
    const primitive_costs paper;
    const double triangle_us = model ? model->paths[std::size_t(cost_path::triangles)].a_us : 1.0;
    const double pixel_us = model ? model->paths[std::size_t(cost_path::triangles)].b_us_per_px : 0.0;
    const double point_us = model ? model->paths[std::size_t(splat_path(q))].at(splat_pixels(q))
                                  : paper.point / paper.triangle;
    const double line_us =
        model ? model->paths[std::size_t(line_path(q))].at(line_pixels(q)) : paper.line / paper.triangle;
    // Beyond the view the plant's pixels are not all seen: grow the last whole size's coverage.
    const std::size_t last_whole = k_rung_table_size_count - 2;
    const auto beyond = [&](std::size_t i) {
        const double grow = double(k_rung_table_sizes_px[i]) / double(k_rung_table_sizes_px[last_whole]);
        return i > last_whole ? grow * grow : 1.0;
    };
    // The measuring scene's shadows reach only so far: at a size no rung cast (a plant further
    // than its shadow range), a plant that does cast is costed as at the next size that did.
    std::array<std::size_t, k_rung_table_size_count> shadow_size{};
    for (std::size_t i = k_rung_table_size_count; i-- > 0;) {
        const bool cast = std::any_of(m.rungs.begin(), m.rungs.end(),
                                      [&](const rung_measurement& x) { return x.shadow_triangles[i] > 0.0f; });
        shadow_size[i] = cast || i + 1 == k_rung_table_size_count ? i : shadow_size[i + 1];
    }
    species_rung_tables out;
    for (std::size_t r = 0; r < ladder.count; ++r) {
        // The tile's after the solver, and the terrain's shell by its fade: neither is the solver's.
        if (ladder.rungs[r] == representation::eco_tile || ladder.rungs[r] == representation::shell) continue;
        const auto it = std::find_if(m.rungs.begin(), m.rungs.end(),
                                     [&](const rung_measurement& x) { return x.rung == ladder.rungs[r]; });
        if (it == m.rungs.end())
            throw std::invalid_argument("rung tables of " + m.species + " have no " +
                                        std::string(rung_name(ladder.rungs[r])));
        rung_table t;
        t.rung = it->rung;
        for (std::size_t i = 0; i < k_rung_table_size_count; ++i) {
            const std::size_t whole = std::min(i, last_whole), sh = shadow_size[i];
            out.plant_pixels[i] = float(double(it->plant_pixels[whole]) * beyond(i));  // the same for every rung
            t.error[i] = float(table_error_per_pixel(*it, i) * double(out.plant_pixels[i]));
            t.drawn_pixels[i] = float(double(it->drawn_pixels[whole]) * beyond(i));
            if (work && m.work_counted) {  // what the rung makes the device do, at its cost per unit
                t.shadow_cost_us[i] = float(work->cost_us(0.0, 0.0, it->shadow_vertices[sh], it->shadow_fragments[sh]));
                t.shadow_fragment_cost_us[i] = float(work->cost_us(0.0, 0.0, 0.0, it->shadow_fragments[sh]));
                t.shadow_texel_m[i] = it->shadow_texel_m[sh];
                t.cost_us[i] = float(work->cost_us(it->vertices[i], double(it->fragments[whole]) * beyond(i), 0.0, 0.0));
            } else {
                t.shadow_cost_us[i] = float(double(it->shadow_triangles[sh]) * triangle_us);
                t.cost_us[i] = float(double(it->triangles[i]) * triangle_us + double(it->points[i]) * point_us +
                                     double(it->lines[i]) * line_us +
                                     double(it->drawn_pixels[whole]) * beyond(i) * pixel_us);
            }
        }
        out.rungs.push_back(t);
    }
    return out;
}

std::vector<species_rung_measurements> measure_rung_tables(const scenario& s, const std::vector<representation>& rungs,
                                                           const point_line_quality& points,
                                                           render::gl_context& context, bake_cache* cache,
                                                           const std::function<void(const std::string&)>& progress,
                                                           double eye_height_m, std::span<const ladder> ladders,
                                                           float ladder_size_scale) {
    std::vector<species_rung_measurements> out;
    for (std::size_t i = 0; i < s.species.size(); ++i) {
        const ladder own = i < ladders.size() ? ladders[i] : ladder{};
        // Sizes the ladder sees are scaled (the bench's ladder_x…): its LoDF top, in pixels of
        // the tables, moves the other way.
        const float top = lodf_top_px(own) / ladder_size_scale;
        std::vector<rung_context> drawn_as;
        for (const representation r : rungs)
            drawn_as.push_back({r == representation::lodf ? top : 0.0f,
                                own.caster_of(r) != r ? own.caster_of(r) : representation::none});
        const scenario one = species_alone(s, i, k_rung_table_view_px, "rung_tables");
        const scenario patch = species_patch(s, i, k_rung_table_view_px, "rung_tables");
        out.push_back(read_or_bake(
            cache, "rung_tables", table_key(one, patch, rungs, points, eye_height_m, drawn_as),
            [&] {
                if (progress) progress(s.species[i].name);  // measuring, not read from the cache
                return encode_rung_measurements(
                    measure_species(one, patch, rungs, points, context, cache, eye_height_m, drawn_as));
            },
            [](const std::vector<std::byte>& bytes) { return decode_rung_measurements(bytes); }));
    }
    return out;
}

}  // namespace sylva
