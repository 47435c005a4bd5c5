#pragma once
// lodf_model (models/bake/lodf_bake.h) to and from the bake cache's bytes, versioned like
// point_line_io: an entry of another k_lodf_format is a miss and is re-baked, never misread.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "models/bake/lodf_bake.h"

namespace sylva {

constexpr std::uint32_t k_lodf_format = 1;

// A magic number, k_lodf_format, then the model, array by array (no struct padding: every
// stored struct is made of 32-bit fields).
std::vector<std::byte> serialize_lodf_model(const lodf_model& model);
// Validates the whole structure (validate_lodf) and throws std::runtime_error naming the problem
// on a truncated, corrupted or other-version entry.
lodf_model deserialize_lodf_model(std::span<const std::byte> bytes);
// Throws std::runtime_error unless every cluster, leaf, collapse and index range of `model` is
// consistent: what the runtime walks without further checks.
void validate_lodf(const lodf_model& model);

}  // namespace sylva
