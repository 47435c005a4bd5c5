#pragma once
// Luft 2007 §3.1: "Experience proved that the interactive specification of these parameters is
// necessary ... only user-driven fine tuning offers the best results." The viewer's tuning panel
// (app/view_command.cpp) edits a species' ρ, τ, k_a,min, Eq. 4's d_v and d_min, n and blend;
// this re-bakes the scene's assets with the new values on a background thread (most species come
// from the bake cache; the tuned one is baked again), reports its progress, and hands the assets
// over for the viewer to swap its player. write_implicit_settings writes the chosen values back
// into the scenario file, changing nothing else in it.
#include <atomic>
#include <filesystem>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "app/scenario_player.h"
#include "scenarios/scenario.h"

namespace sylva {

class implicit_rebake {
public:
    // Starts baking `s` with species `species` set to `settings` for a player with `options`,
    // through the bake cache at `cache_root` ("": the default folder; nothing: no cache).
    implicit_rebake(scenario s, std::size_t species, const implicit_lighting_settings& settings,
                    player_options options, std::optional<std::filesystem::path> cache_root = std::filesystem::path{});
    ~implicit_rebake();
    implicit_rebake(const implicit_rebake&) = delete;
    implicit_rebake& operator=(const implicit_rebake&) = delete;

    float progress() const { return m_progress.load(); }  // 0..1
    std::string step() const;
    bool ready() const;
    // Once ready: the tuned scenario and its assets (throws what the bake threw).
    scenario& tuned() { return m_scenario; }
    std::shared_ptr<scene_assets> take();

private:
    scenario m_scenario;
    std::atomic<float> m_progress{0.0f};
    mutable std::mutex m_step_mutex;
    std::string m_step;
    std::future<std::shared_ptr<scene_assets>> m_result;
};

// Sets /species/<index>/implicit in the JSON file `path` to `settings` (every field, so the file
// says exactly what was tuned) and rewrites the file with its other keys in their order. Throws
// with the file named when it cannot be read, parsed or written, or has no such species.
void write_implicit_settings(const std::filesystem::path& path, std::size_t index,
                             const implicit_lighting_settings& settings);

}  // namespace sylva
