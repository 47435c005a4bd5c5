#pragma once
// plant_model to and from the bake cache's bytes. The format is versioned: an entry written by
// another version is treated as a miss and re-baked, never misread.
#include <cstddef>
#include <span>
#include <vector>

#include "models/plant_model.h"

namespace sylva {

// Bump whenever plant_model, mesh_data or a generator changes what it produces.
constexpr std::uint32_t k_plant_model_format = 2;  // 2: foliage parent_branch is its stem's parent

std::vector<std::byte> serialize_plant_model(const plant_model& model);
// Throws std::runtime_error on a malformed entry or another format version.
plant_model deserialize_plant_model(std::span<const std::byte> bytes);

}  // namespace sylva
