// Extreme LOD (app/stress/stress_checks.h): choose_representation over lod_scale 0.01 .. 100,
// distances 0 .. inf and NaN, and plant scale 0 never picks a finer level farther away; the
// loader holds lod_scale to its range, and the tiny scene plays sanely at both ends of it.
#include <array>
#include <limits>
#include <nlohmann/json.hpp>

#include "app/stress/check_support.h"
#include "app/stress/stress_checks.h"
#include "components/lod_state.h"
#include "scenarios/embedded_files.h"
#include "scenarios/scenario_loader.h"
#include "systems/select_representation_system.h"

namespace sylva {
namespace {

using stress::row;
using stress::rows;
using stress::text;

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
    return stress::error_from<scenario_error>([&] { load_scenario_text(doc.dump(), "lod_scale.json"); });
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
    // A comparison with NaN is false, so NaN must fall through to the far mesh, as inf does.
    bool unbounded_far = true;
    for (const float lod_scale : {0.01f, 1.0f, 100.0f})
        for (const float scale : {0.0f, 1e-30f, 0.8f, 100.0f}) {
            int previous = 0;
            for (const float d : distances) {
                const int r = rank(choose_representation(species, d, scale, lod_scale));
                finer_farther += r < previous ? 1 : 0;
                previous = r;
            }
            ++sweeps;
            for (const float d : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()})
                unbounded_far = unbounded_far && choose_representation(species, d, scale, lod_scale) ==
                                                     representation::mesh_far;
        }
    out.push_back(row(text("LOD choice, %zu sweeps 0..inf m", sweeps),
                      text("%zu finer when farther", finer_farther), double(finer_farther), "0",
                      finer_farther == 0,
                      "lod_scale 0.01, 1, 100 x plant scale 0, 1e-30, 0.8, 100"));
    out.push_back(stress::yes_no_row("LOD choice at NaN and inf distance", unbounded_far, "far mesh",
                                     "finer than far", "far mesh",
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
    out.push_back(stress::yes_no_row("loader lod_scale 0.009, 101 / 0.01, 100", rejected && accepted,
                                     "rejected / loaded", "wrong", "usual range error",
                                     rejected ? "" : low + " | " + high));

    // At 100 every switch distance is beyond the 120 m scene: full meshes only. At 0.01 the draw
    // distance is 4 m (nothing visible) and the plants cast shadows with their far meshes.
    const scenario s = stress::tiny_scenario();
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

}  // namespace sylva
