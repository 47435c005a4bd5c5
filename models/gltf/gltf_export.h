#pragma once
// One level of a plant as a self-contained binary glTF 2.0 file (.glb): interleaved positions,
// normals and uvs, one primitive per sub-mesh, a bark material (OPAQUE) and a leaf material
// (MASK at 0.5, double-sided), both textures embedded as PNG. Valid by the Khronos validator.
#include <filesystem>

#include "models/bake/billboard_cloud.h"
#include "models/plant_model.h"

namespace sylva {

// Throws std::runtime_error naming the file if it cannot be written, std::invalid_argument if
// the level has no triangles.
void export_plant_glb(const plant_model& plant, plant_lod lod, const std::filesystem::path& file);

// A billboard cloud (models/bake/billboard_cloud.h) as a self-contained .glb: its quads with
// positions, normals, uvs and tangents in one primitive, one material (MASK at 0.5, single-sided:
// every billboard side is its own quad) with the colour atlas as base colour and the normal page
// as a tangent-space normal texture, both embedded as PNG. glTF wants tangent-space normals and
// a mask on plain coverage, so the export converts the model-space normal page per billboard
// side and takes the base colour's alpha from the normal page (coverage without the gaussian,
// which only Sylva's distance fade uses). Throws like export_plant_glb.
void export_billboard_cloud_glb(const billboard_cloud& cloud, const std::string& name,
                                const std::filesystem::path& file);

}  // namespace sylva
