#pragma once
// crossed_billboard to and from the bake cache's bytes, versioned like plant_model_io: an entry
// of another k_crossed_billboard_format is a miss and is re-baked, never misread.
#include <cstddef>
#include <span>
#include <vector>

#include "models/bake/crossed_billboard.h"

namespace sylva {

std::vector<std::byte> serialize_crossed_billboard(const crossed_billboard& billboard);
// Throws std::runtime_error on a malformed entry or another format version.
crossed_billboard deserialize_crossed_billboard(std::span<const std::byte> bytes);

}  // namespace sylva
