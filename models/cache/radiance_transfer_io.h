#pragma once
// radiance_transfer to and from the bake cache's bytes, versioned like point_line_io: an entry
// of another k_radiance_transfer_format is a miss and is re-baked, never misread.
#include <cstddef>
#include <span>
#include <vector>

#include "models/cache/bake_cache.h"
#include "models/bake/radiance_transfer.h"

namespace sylva {

// One transfer inside a larger entry: bands, then the front and back arrays.
void write_radiance_transfer(binary_writer& out, const radiance_transfer& transfer);
// Throws std::runtime_error on a truncated entry, bands other than 2 or 3, or arrays whose
// sizes disagree with each other or with bands^2.
radiance_transfer read_radiance_transfer(binary_reader& in);

// A whole entry: a magic number, k_radiance_transfer_format, a count, then the transfers (the
// three mesh levels of a species, or its points and its lines).
std::vector<std::byte> serialize_radiance_transfers(std::span<const radiance_transfer> transfers);
// Throws std::runtime_error naming the problem on a truncated, corrupted or other-version entry.
std::vector<radiance_transfer> deserialize_radiance_transfers(std::span<const std::byte> bytes);

}  // namespace sylva
