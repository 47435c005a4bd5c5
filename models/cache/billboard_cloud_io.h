#pragma once
// billboard_cloud to and from the bake cache's bytes (kind "billboard_clouds"), versioned like
// billboard_io: an entry of another k_billboard_cloud_format is a miss and is re-baked, never
// misread. Every field is written on its own (no struct bytes, so no padding): equal clouds give
// equal bytes.
#include <cstddef>
#include <span>
#include <vector>

#include "models/bake/billboard_cloud.h"

namespace sylva {

std::vector<std::byte> serialize_billboard_cloud(const billboard_cloud& cloud);
// Throws std::runtime_error on a malformed entry or another format version.
billboard_cloud deserialize_billboard_cloud(std::span<const std::byte> bytes);

}  // namespace sylva
