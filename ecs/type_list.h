#pragma once
// Compile-time helpers over type packs, shared by queries and access declarations. Comparisons
// ignore const: `const camera` and `camera` name the same component.
#include <cstddef>
#include <type_traits>

namespace sylva::ecs::detail {

template <class T, class... Ts>
inline constexpr bool contains_v = (std::is_same_v<std::remove_cv_t<T>, std::remove_cv_t<Ts>> ||
                                    ...);

template <class... Ts>
struct unique;
template <>
struct unique<> : std::true_type {};
template <class T, class... Ts>
struct unique<T, Ts...> : std::bool_constant<!contains_v<T, Ts...> && unique<Ts...>::value> {};
template <class... Ts>
inline constexpr bool unique_v = unique<Ts...>::value;

// Position of T in Ts (first match); sizeof...(Ts) if absent.
template <class T, class... Ts>
constexpr std::size_t index_of() {
    constexpr bool matches[] = {std::is_same_v<std::remove_cv_t<T>, std::remove_cv_t<Ts>>...,
                                false};
    for (std::size_t i = 0; i < sizeof...(Ts); ++i)
        if (matches[i]) return i;
    return sizeof...(Ts);
}

}  // namespace sylva::ecs::detail
