// Shards of a run (issue 25): how a player reaches a shard's first frame as a whole run would
// (scenario_player::replay_to), when it cannot, and what its selection reads from the device.
#include <chrono>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "app/scenario_player.h"
#include "components/camera.h"
#include "resources/seen_pixels.h"
#include "systems/render/submit_system.h"

namespace sylva {
namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::string scenario_player::unreproducible_reason() const {
    const rung_budget& ladder = m_world.resource<rung_budget>();
    if (ladder.active() && ladder.target_frame_ms > 0.0 && !(ladder.max_error > 0.0))
        return fmt::format("the auto ladder holds a frame-time target (lod.target_frame_ms {:g}), adapting to the "
                           "device's measured time",
                           ladder.target_frame_ms);
    const sample_distance_budget& budget = m_world.resource<sample_distance_budget>();
    if (m_world.resource<lod_policy>().mode == lod_policy::kind::points_lines && !(budget.primitives > 0.0) &&
        budget.frame_ms > 0.0)
        return fmt::format("the points' sample distance holds a frame-time target (lod.target_frame_ms {:g}), "
                           "adapting to the device's measured time",
                           budget.frame_ms);
    return {};
}

std::uint64_t scenario_player::selection_inputs_hash() const {
    const primitive_costs& costs = m_world.resource<primitive_costs>();
    std::uint64_t h = fnv1a(&costs.triangle, sizeof(double));
    h = fnv1a(&costs.point, sizeof(double), h);
    h = fnv1a(&costs.line, sizeof(double), h);
    for (const species_rung_tables& species : m_world.resource<rung_budget>().tables) {  // field by field: padding
        for (const rung_table& t : species.rungs) {
            const auto rung = static_cast<std::uint32_t>(t.rung);
            h = fnv1a(&rung, sizeof(rung), h);
            for (const auto* a : {&t.error, &t.cost_us, &t.shadow_cost_us, &t.shadow_fragment_cost_us,
                                  &t.shadow_texel_m, &t.drawn_pixels})
                h = fnv1a(a->data(), a->size() * sizeof(float), h);
        }
        h = fnv1a(species.plant_pixels.data(), species.plant_pixels.size() * sizeof(float), h);
    }
    return h;
}

bool scenario_player::replay_renders_every_frame() const { return m_world.resource<seen_pixels>().wanted; }

replay_cost scenario_player::replay_to(std::uint64_t frame, const std::function<bool(std::uint64_t)>& render_frame,
                                       const std::function<void(const frame_record&, bool)>& after,
                                       const std::function<bool()>& stop) {
    if (frame < m_frame)
        throw std::logic_error("replay_to: frame " + std::to_string(frame) + " is behind the player's " +
                               std::to_string(m_frame));
    if (const std::string why = unreproducible_reason(); !why.empty() && frame > 0)
        throw std::invalid_argument("a shard cannot start at frame " + std::to_string(frame) + ": " + why +
                                    ", so no two runs of it are equal; play it whole");
    const auto start = std::chrono::steady_clock::now();
    replay_cost cost;
    render_device& device = m_world.resource<render_device>();
    render::renderer* const renderer = device.renderer;
    // Restored however the loop ends: a player left without its renderer would draw nothing.
    struct restore {
        render_device& device;
        render::renderer* renderer;
        ~restore() { device.renderer = renderer; }
    } const restore_renderer{device, renderer};
    const bool every = replay_renders_every_frame();
    // Full geometry carries nothing over frames but the frame before's: every plant is its full
    // mesh at any distance (lod_scale 1e6), so no level, fade, prefix or budget changes. The frame
    // before is still played, rendered: each plant's previous level and the renderer's buffers
    // (their first frame uploads more) are in the frame's record (without it the images are the
    // same, the state hash and upload bytes of a shard's first frame are not).
    // tests/app/shard_command_test.cpp compares reference shards with a whole reference.
    if (m_world.single<camera>().full_geometry && !every && frame > m_frame + 1) m_frame = frame - 1;
    frame_record record;
    while (m_frame < frame && !(stop && stop())) {
        const std::uint64_t f = m_frame;
        const bool rendered = renderer && (every || f + 1 == frame || (render_frame && render_frame(f)));
        device.renderer = rendered ? renderer : nullptr;
        step(record);
        ++(rendered ? cost.rendered_frames : cost.cpu_frames);
        if (after) after(record, rendered);
    }
    cost.ms = ms_since(start);
    return cost;
}

}  // namespace sylva
