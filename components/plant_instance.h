#pragma once
// One plant of a population: which species model it draws and the seed its variation derives
// from. Writer: population spawning; read by select_representation and build_draw_list.
#include <cstdint>

namespace sylva {

// Index into the species library resource (typed so it cannot be mixed up with other ids).
enum class species_id : std::uint16_t {};

struct plant_instance {
    species_id species{};
    std::uint16_t tint = 0;  // per-instance colour variation, 0..65535
    std::uint32_t seed = 0;
};
static_assert(sizeof(plant_instance) == 8);

}  // namespace sylva
