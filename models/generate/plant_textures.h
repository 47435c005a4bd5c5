#pragma once
// Foliage textures of the small plants (grass, flower, fern) and their green stems. Same
// conventions as models/generate/textures.h: linear albedo, alpha 255 inside a shape and 0 outside,
// the base of a card at the bottom row (v = 1), deterministic.
#include <cstdint>

#include "models/image/image.h"
#include "models/generate/plant_mesh_builder.h"

namespace sylva {

// Regions of the flower atlas (generate_flower_atlas): the leaf on the left half, a petal top
// right, the blossom's centre disc bottom right.
inline constexpr uv_rect k_flower_leaf_region{{0.0f, 0.0f}, {0.5f, 1.0f}};
inline constexpr uv_rect k_flower_petal_region{{0.5f, 0.0f}, {1.0f, 0.5f}};
inline constexpr uv_rect k_flower_centre_region{{0.5f, 0.5f}, {1.0f, 1.0f}};

// One grass blade filling the card's width, narrowing to a pointed tip, with lengthwise veins.
image_rgba8 generate_grass_texture(std::uint32_t size);
// Leaf, petal and centre disc of the meadow flower in one texture (regions above).
image_rgba8 generate_flower_atlas(std::uint32_t size);
// One fern pinna: a narrow lanceolate leaflet with lobed (pinnatifid) edges.
image_rgba8 generate_fern_texture(std::uint32_t size);
// Opaque green stem (herbaceous: grass, flower and fern stalks), tiling.
image_rgba8 generate_stem_texture(std::uint32_t size);

}  // namespace sylva
