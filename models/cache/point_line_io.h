#pragma once
// point_line_model to and from the bake cache's bytes, versioned like plant_model_io: an entry
// of another k_point_line_format is a miss and is re-baked, never misread.
#include <cstddef>
#include <span>
#include <vector>

#include "models/bake/point_line_model.h"

namespace sylva {

// A magic number, k_point_line_format, then the model. Parts and cells are written field by
// field (no struct padding), so equal models give equal bytes.
std::vector<std::byte> serialize_point_line_model(const point_line_model& model);
// Validates every range (triangles, points, points_after, lines of each part; parts of each
// cell), enum and count, and throws std::runtime_error naming the problem on a truncated,
// corrupted or other-version entry.
point_line_model deserialize_point_line_model(std::span<const std::byte> bytes);

}  // namespace sylva
