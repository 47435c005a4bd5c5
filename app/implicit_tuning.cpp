#include "app/implicit_tuning.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace sylva {

implicit_rebake::implicit_rebake(scenario s, std::size_t species, const implicit_lighting_settings& settings,
                                 player_options options, std::optional<std::filesystem::path> cache_root)
    : m_scenario(std::move(s)) {
    if (species >= m_scenario.species.size())
        throw std::invalid_argument("implicit tuning: species " + std::to_string(species) + " of " +
                                    std::to_string(m_scenario.species.size()));
    m_scenario.species[species].implicit = settings;
    // Its own cache handle: the bake cache is a folder, safe for two handles (entries are written
    // whole and renamed into place).
    m_result = std::async(std::launch::async, [this, options, cache_root] {
        std::optional<bake_cache> cache;
        if (cache_root) cache.emplace(*cache_root);
        auto assets = std::make_shared<scene_assets>(build_player_assets(
            m_scenario, options, cache ? &*cache : nullptr, [this](float done, const std::string& what) {
                m_progress.store(done);
                const std::lock_guard lock(m_step_mutex);
                m_step = what;
            }));
        m_progress.store(1.0f);
        return assets;
    });
}

implicit_rebake::~implicit_rebake() {
    if (m_result.valid()) m_result.wait();  // the bake reads m_scenario
}

std::string implicit_rebake::step() const {
    const std::lock_guard lock(m_step_mutex);
    return m_step;
}

bool implicit_rebake::ready() const {
    return m_result.valid() && m_result.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

std::shared_ptr<scene_assets> implicit_rebake::take() { return m_result.get(); }

void write_implicit_settings(const std::filesystem::path& path, std::size_t index,
                             const implicit_lighting_settings& settings) {
    // ordered_json keeps the file's keys in their order, so only the tuned object changes.
    nlohmann::ordered_json root;
    {
        std::ifstream in(path);
        if (!in) throw std::runtime_error(path.string() + ": cannot read the scenario to write the tuning back");
        try {
            root = nlohmann::ordered_json::parse(in);
        } catch (const nlohmann::json::exception& e) {
            throw std::runtime_error(path.string() + ": not JSON (" + e.what() + ")");
        }
    }
    if (!root.contains("species") || !root["species"].is_array() || index >= root["species"].size())
        throw std::runtime_error(path.string() + ": /species/" + std::to_string(index) + " does not exist");
    auto& implicit = root["species"][index]["implicit"];
    implicit["generator_fraction"] = settings.generator_fraction;
    implicit["rho_m"] = settings.rho_m;
    implicit["tau"] = settings.tau;
    implicit["ka_min"] = settings.ka_min;
    implicit["ambient_from"] = settings.ambient_from;
    implicit["d_min"] = settings.d_min;
    implicit["depth_min_m"] = settings.depth_min_m;
    implicit["exponent"] = settings.exponent;
    implicit["blend"] = settings.blend;
    implicit["population"] = settings.population;
    // Written beside the file and renamed over it: an interrupted write loses nothing.
    const std::filesystem::path temporary = path.string() + ".tmp";
    {
        std::ofstream out(temporary);
        out << root.dump(2) << '\n';
        if (!out) throw std::runtime_error(temporary.string() + ": cannot write");
    }
    std::filesystem::rename(temporary, path);
}

}  // namespace sylva
