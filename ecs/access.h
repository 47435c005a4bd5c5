#pragma once
// The vocabulary a system uses to declare itself: which phase it runs in and which component or
// resource types it reads and writes. The scheduler turns these declarations into its dependency
// graph; system_context turns them into compile-time access checks.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <vector>

#include "ecs/type_id.h"
#include "ecs/type_list.h"

namespace sylva::ecs {

// Phases run in this order with a sync point (command buffers applied) between each pair.
enum class phase : std::uint8_t {
    input,
    simulate,
    cull,
    select,
    transition,
    lighting,
    build,
    submit,
    capture
};
inline constexpr std::size_t k_phase_count = static_cast<std::size_t>(phase::capture) + 1;

template <class... Ts>
struct reads {};
template <class... Ts>
struct writes {};

namespace detail {

template <class T, class List>
struct list_contains : std::false_type {};
template <class T, template <class...> class List, class... Ts>
struct list_contains<T, List<Ts...>> : std::bool_constant<contains_v<T, Ts...>> {};

template <class List>
struct list_ids;
template <template <class...> class List, class... Ts>
struct list_ids<List<Ts...>> {
    static std::vector<std::size_t> get() { return {type_id<Ts>()...}; }
};

template <class S>
struct declared_reads {
    using type = reads<>;
};
template <class S>
requires requires {
    typename S::reads;
}
struct declared_reads<S> {
    using type = typename S::reads;
};
template <class S>
struct declared_writes {
    using type = writes<>;
};
template <class S>
requires requires {
    typename S::writes;
}
struct declared_writes<S> {
    using type = typename S::writes;
};

template <class S>
constexpr bool declared_main_thread() {
    if constexpr (requires { S::k_main_thread; })
        return S::k_main_thread;
    else
        return false;
}

}  // namespace detail

// What the scheduler and system_context know about a system S. `reads`, `writes` and
// `k_main_thread` are optional in S; `k_name`, `k_phase` and `static void run(system_context<S>&)`
// are required.
template <class S>
struct system_traits {
    using read_list = typename detail::declared_reads<S>::type;
    using write_list = typename detail::declared_writes<S>::type;
    static constexpr std::string_view k_name = S::k_name;
    static constexpr phase k_phase = S::k_phase;
    static constexpr bool k_main_thread = detail::declared_main_thread<S>();

    template <class T>
    static constexpr bool k_writes = detail::list_contains<T, write_list>::value;
    template <class T>
    static constexpr bool k_reads = k_writes<T> || detail::list_contains<T, read_list>::value;
};

}  // namespace sylva::ecs
