#pragma once
// Dense per-type ids for component tables, resources and access declarations. Ids are handed out
// on first use, so they are not stable across runs; nothing may persist or sort by them.
#include <atomic>
#include <cstddef>
#include <type_traits>

namespace sylva::ecs {

namespace detail {
inline std::size_t next_type_id() {
    static std::atomic<std::size_t> counter{0};
    return counter.fetch_add(1, std::memory_order_relaxed);
}
}  // namespace detail

// `const T` and `T` share an id: access declarations may spell either.
template <class T>
std::size_t type_id() {
    using bare = std::remove_cvref_t<T>;
    if constexpr (!std::is_same_v<bare, T>) {
        return type_id<bare>();
    } else {
        static const std::size_t id = detail::next_type_id();
        return id;
    }
}

}  // namespace sylva::ecs
