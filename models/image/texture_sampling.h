#pragma once
// CPU texture lookups that match what GL does with the same texture: bilinear filtering with
// GL_REPEAT wrapping, texel row 0 at v = 0 (rows uploaded top first). The billboard bake and
// the point/line bake both read leaf and bark textures through it, so what they bake is what
// the renderer would show.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "models/image/image.h"

namespace sylva {

// Texel index i wrapped into [0, size) (GL_REPEAT).
std::uint32_t wrap_texel(std::int32_t i, std::uint32_t size);

// The four texels and weights of a bilinear fetch at `uv`.
struct bilinear_footprint {
    const std::uint8_t* texel[4];  // (x0, y0), (x1, y0), (x0, y1), (x1, y1)
    float weight[4];
};
bilinear_footprint footprint(const image_rgba8& texture, glm::vec2 uv);

// Alpha at `uv`, 0..255: what GL's alpha test compares with 0.5 (times 255).
float bilinear_alpha(const image_rgba8& texture, glm::vec2 uv);
// Colour at `uv`, rgb 0..255. `alpha_weighted`: weights multiplied by alpha, so the transparent
// texels of a leaf card do not pull their (meaningless) colour into the leaf's edge.
glm::vec3 bilinear_colour(const image_rgba8& texture, glm::vec2 uv, bool alpha_weighted);

}  // namespace sylva
