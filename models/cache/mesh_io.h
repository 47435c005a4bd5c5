#pragma once
// Binary form of meshes and images inside bake-cache entries (plant models, billboards). The
// readers validate what they read (index range, texel count) and throw std::runtime_error
// naming the problem, so a damaged entry is baked again instead of drawn.
#include "models/cache/bake_cache.h"
#include "models/image/image.h"
#include "models/mesh.h"

namespace sylva {

void write_mesh(binary_writer& out, const mesh_data& mesh);
mesh_data read_mesh(binary_reader& in);
void write_image(binary_writer& out, const image_rgba8& image);
image_rgba8 read_image(binary_reader& in);

}  // namespace sylva
