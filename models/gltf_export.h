#pragma once
// One level of a plant as a self-contained binary glTF 2.0 file (.glb): interleaved positions,
// normals and uvs, one primitive per sub-mesh, a bark material (OPAQUE) and a leaf material
// (MASK at 0.5, double-sided), both textures embedded as PNG. Valid by the Khronos validator.
#include <filesystem>

#include "models/plant_model.h"

namespace sylva {

// Throws std::runtime_error naming the file if it cannot be written, std::invalid_argument if
// the level has no triangles.
void export_plant_glb(const plant_model& plant, plant_lod lod, const std::filesystem::path& file);

}  // namespace sylva
