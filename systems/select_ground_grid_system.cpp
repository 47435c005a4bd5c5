#include "systems/select_ground_grid_system.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <span>

#include "ecs/parallel.h"

namespace sylva {

void select_ground_grid_system::run(ecs::system_context<select_ground_grid_system>& ctx) {
    auto& tiles = ctx.write<ground_tile>();
    if (tiles.size() == 0) return;
    const camera& cam = ctx.single<camera>();
    const ground_lod* lod = ctx.try_resource<ground_lod>();
    const float tolerance_px = lod ? lod->max_error_px : k_ground_error_px;
    ground_tile* data = tiles.data();
    ctx.parallel_for(tiles.size(), [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t i = begin; i < end; ++i) {
            if (cam.full_geometry) {
                data[i].grid = 0;
                continue;
            }
            const float nearest =
                std::max(float(glm::length(data[i].centre - cam.position)) - data[i].radius, 1e-3f);
            data[i].grid =
                coarsest_ground_grid(std::span(data[i].grid_error_m).first(data[i].grids), nearest,
                                     cam.pixels_per_radian, tolerance_px);
        }
    });
}

}  // namespace sylva
