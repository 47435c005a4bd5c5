#pragma once
// The shell textures of a tile set (models/bake/shell_bake.h shell_stack, one per Wang tile) to
// and from the bake cache's bytes, versioned: an entry of another k_shell_format is a miss and is
// baked again, never misread.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "models/bake/shell_bake.h"

namespace sylva {

// 2: slices may carry SH transfer pages (shell_stack::transfer). 3: with k_a in page 4's blue.
constexpr std::uint32_t k_shell_format = 3;

std::vector<std::byte> serialize_shell_stacks(const std::vector<shell_stack>& stacks);
// Throws std::runtime_error naming the problem on a truncated, corrupted or other-version entry,
// or stacks whose slices differ in count or size.
std::vector<shell_stack> deserialize_shell_stacks(std::span<const std::byte> bytes);

}  // namespace sylva
