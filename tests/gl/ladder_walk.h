#pragma once
// A camera backing away from the plants of a scenario along +z at a fixed eye height, looking
// level at their centroid, one frame per distance: what the ladder tests walk across a band.
// Each sample holds the frame's record and how many pixels the plants cover in the ID buffer.
#include <algorithm>
#include <cmath>

#include "app/scenario_player.h"
#include "components/transform.h"
#include "gl_test_support.h"
#include "lod/point_line_lod.h"
#include "resources/playback.h"

namespace sylva::testing {

struct walk_sample {
    double distance_m = 0.0;
    std::size_t pixels = 0;
    frame_record record;
    // What a fixed shape keeps as it recedes: coverage times distance².
    double normalised() const { return double(pixels) * distance_m * distance_m; }
};

inline std::uint32_t drawn(const walk_sample& s, representation r) { return s.record.instances[std::size_t(r)]; }

class ladder_walk {
public:
    static constexpr float k_fov_deg = 50.0f;
    static constexpr double k_eye_height_m = 7.0;

    explicit ladder_walk(scenario s) : m_height(s.height), m_player(std::move(s), 2, shared_gl_context(), nullptr, id_buffer()) {}

    // The ground distance from the centroid at which the first plant's bounding sphere projects
    // to `size_px` (select_representation measures from the eye to the plant's base).
    double distance_for(float size_px) {
        const species_entry& species = m_player.world().resource<species_library>().species[0];
        const float scale = m_player.world().table<world_transform>().data()[0].scale;
        const double pixel = image_plane_units(1.0, double(k_fov_deg) * M_PI / 180.0, double(m_height));
        const double eye_to_base = 2.0 * double(species.bounding_radius * scale) / (double(size_px) * pixel);
        return std::sqrt(eye_to_base * eye_to_base - k_eye_height_m * k_eye_height_m);
    }

    walk_sample at(double distance_m) {
        ecs::world& world = m_player.world();
        const auto& transforms = world.table<world_transform>();
        glm::dvec3 centre(0.0);
        for (std::size_t i = 0; i < transforms.size(); ++i) centre += transforms.data()[i].position;
        centre /= double(std::max<std::size_t>(transforms.size(), 1));
        camera_keyframe key;
        key.position = centre + glm::dvec3(0.0, k_eye_height_m, distance_m);
        key.target = centre + glm::dvec3(0.0, k_eye_height_m, 0.0);
        key.fov_deg = k_fov_deg;
        world.resource<camera_track>().keys = {key};
        m_player.set_frame(0);
        walk_sample s;
        s.distance_m = distance_m;
        s.record = m_player.step();
        const std::vector<std::uint32_t> ids = m_player.capture_plant_ids();
        s.pixels = std::size_t(std::count_if(ids.begin(), ids.end(), [](std::uint32_t id) { return id != 0; }));
        return s;
    }

    ecs::world& world() { return m_player.world(); }

private:
    static player_options id_buffer() {
        player_options options;
        options.id_buffer = true;
        return options;
    }

    std::uint32_t m_height;
    scenario_player m_player;
};

}  // namespace sylva::testing
