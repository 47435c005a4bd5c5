#pragma once
// Generational entity handle. The index names a slot in the world; the generation is bumped each
// time the slot is freed, so a handle kept past destroy() compares unequal to the slot's current
// generation and the world reports it dead instead of silently aliasing a newer entity.
#include <cstdint>
#include <functional>

namespace sylva::ecs {

inline constexpr std::uint32_t k_null_index = 0xFFFF'FFFFu;

struct entity {
    std::uint32_t index = k_null_index;
    std::uint32_t generation = 0;

    constexpr bool is_null() const { return index == k_null_index; }
    friend constexpr bool operator==(entity, entity) = default;
};

inline constexpr entity k_null_entity{};

}  // namespace sylva::ecs

template <>
struct std::hash<sylva::ecs::entity> {
    std::size_t operator()(sylva::ecs::entity e) const noexcept {
        return std::hash<std::uint64_t>{}((std::uint64_t{e.generation} << 32) | e.index);
    }
};
