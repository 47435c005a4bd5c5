#pragma once
// Pieces of the small hand-built scenes GL tests render: horizontal quads, solid textures, a
// camera looking straight down, a sun with one shadow cascade, one rendered frame, and the
// luminance the camera sees at a world point.
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <vector>

#include "components/camera.h"
#include "models/image/image.h"
#include "models/mesh.h"
#include "lighting/shadow_cascades.h"
#include "lighting/sky_model.h"
#include "systems/render/renderer.h"
#include "systems/update_camera_system.h"

namespace sylva::testing {

// A square of side 2·half at height y, normal up, wound counter-clockwise seen from above.
inline mesh_data horizontal_quad(float half, float y, material_kind material) {
    mesh_data m;
    m.vertices = {{{-half, y, -half}, {0, 1, 0}, {0, 0}},
                  {{half, y, -half}, {0, 1, 0}, {1, 0}},
                  {{half, y, half}, {0, 1, 0}, {1, 1}},
                  {{-half, y, half}, {0, 1, 0}, {0, 1}}};
    m.indices = {0, 2, 1, 0, 3, 2};
    m.submeshes = {{0, 6, material}};
    m.bounds_min = {-half, y, -half};
    m.bounds_max = {half, y, half};
    return m;
}

// A 16 x 16 opaque texture of grey level v.
inline image_rgba8 solid(std::uint8_t v) {
    image_rgba8 image{16, 16, std::vector<std::uint8_t>(16 * 16 * 4, v)};
    for (std::size_t i = 3; i < image.texels.size(); i += 4) image.texels[i] = 255;
    return image;
}

// A square view of `pixels` from `position`, looking straight down, fov_y degrees wide.
inline camera looking_down(glm::dvec3 position, float fov_y_deg, float pixels) {
    camera cam;
    cam.position = position;
    cam.forward = {0.0f, -1.0f, 0.0f};
    cam.aspect = 1.0f;
    cam.fov_y = glm::radians(fov_y_deg);
    cam.viewport_height_px = pixels;
    derive_camera_matrices(cam);
    return cam;
}

// Sunlight for a shadow test: a white sun `elevation_deg` up in the east (+x), intensity 3, under
// a uniform sky (irradiance 1.5), and one 2048² cascade fitted to `cam` out to 60 m.
struct sunlit {
    sun light;
    environment sky;
    cascade_set cascades;
};
inline sunlit sun_from_the_east(const camera& cam, float elevation_deg) {
    sunlit s;
    s.light.direction = sun_direction_from_angles(elevation_deg, 90.0f);
    s.light.color = glm::vec3(1.0f);
    s.light.intensity = 3.0f;
    s.sky.irradiance_sh[0] = glm::vec3(1.5f);
    s.cascades = fit_cascades(cam.view, cam.fov_y, cam.aspect, cam.near_plane, 60.0f,
                              s.light.direction, 1, 0.5f, 2048, 50.0f, cam.position);
    return s;
}

// Rec. 709 luminance (0..255) of the pixel where `cam` sees `world`.
inline float luminance_at(const image_rgba8& image, const camera& cam, glm::dvec3 world) {
    const glm::vec4 clip =
        cam.projection * cam.view * glm::vec4(glm::vec3(world - cam.position), 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const auto px = std::uint32_t((ndc.x * 0.5f + 0.5f) * float(image.width));
    const auto py = std::uint32_t((0.5f - ndc.y * 0.5f) * float(image.height));
    const std::uint8_t* p = image.at(px, py);
    return 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2];
}

// The frame of `draws` seen by `cam`, the terrain instance at the world origin.
inline render::frame_view make_view(const camera& cam, const sun& light, const environment& sky,
                                    const cascade_set& cascades, const draw_list& draws) {
    render::frame_view view;
    view.view_camera = &cam;
    view.sun_light = &light;
    view.sky = &sky;
    view.cascades = &cascades;
    view.draws = &draws;
    view.terrain_position = glm::vec3(-cam.position);
    return view;
}

// Renders one frame of `draws` (the terrain instance at the world origin) and reads it back.
inline image_rgba8 render_frame(render::renderer& renderer, const camera& cam, const sun& light,
                                const environment& sky, const cascade_set& cascades,
                                const draw_list& draws) {
    renderer.render(make_view(cam, light, sky, cascades, draws));
    renderer.finish();
    return renderer.read_color();
}

}  // namespace sylva::testing
