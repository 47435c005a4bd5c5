#pragma once
// A query walks the dense order of its first component table (the driver) and hands the visitor
// every entity that also has the other components. When the world has verified that all tables
// line up index for index (see world::align), the walk is a plain indexed loop over contiguous
// arrays — no sparse lookups, no hashing — which is what makes a million-plant frame affordable.
// Otherwise each non-driver component is found through its table's sparse index (still correct).
//
// A query is a view: it holds table pointers, is cheap to copy, and is valid until the next
// structural change (create/destroy/emplace/remove/align), i.e. until the next phase boundary.
// each_chunk() may be called concurrently on disjoint ranges.
#include <cstddef>
#include <span>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>

#include "ecs/component_table.h"
#include "ecs/type_list.h"

namespace sylva::ecs {

template <class... Ts>
class query {
    static_assert(sizeof...(Ts) > 0, "ecs::query needs at least one component type");
    static_assert(detail::unique_v<Ts...>, "ecs::query lists a component type twice");
    static_assert((!std::is_reference_v<Ts> && ...),
                  "ecs::query takes component types, not references");

    template <class T>
    using table_ptr =
        std::conditional_t<std::is_const_v<T>, const component_table<std::remove_const_t<T>>*,
                           component_table<std::remove_const_t<T>>*>;

public:
    using tables_type = std::tuple<table_ptr<Ts>...>;

    query(tables_type tables, bool aligned) : m_tables(tables), m_aligned(aligned) {}

    // Candidates: the driver's size. With aligned tables every candidate matches.
    std::size_t size() const { return std::get<0>(m_tables)->size(); }
    bool aligned() const { return m_aligned; }
    std::span<const entity> entities() const { return std::get<0>(m_tables)->entities(); }

    // f(entity, Ts&...) for every matching entity, in driver dense order.
    template <class F>
    void each(F&& f) const {
        each_chunk(0, size(), f);
    }

    // Same over driver dense indices [begin, end): the unit parallel_for hands out.
    template <class F>
    void each_chunk(std::size_t begin, std::size_t end, F&& f) const {
        if (m_aligned)
            each_aligned(begin, end, f, std::index_sequence_for<Ts...>{});
        else
            each_lookup(begin, end, f, std::index_sequence_for<Ts...>{});
    }

    // The dense column of T, indexed like the driver. Only meaningful when aligned (or for the
    // driver itself); asking for another column of an unaligned query is a logic error.
    template <class T>
    auto column() const {
        constexpr std::size_t i = detail::index_of<T, Ts...>();
        static_assert(i < sizeof...(Ts), "ecs::query::column<T>: T is not part of this query");
        using declared = std::tuple_element_t<i, std::tuple<Ts...>>;
        static_assert(
            std::is_const_v<T> || !std::is_const_v<declared>,
            "ecs::query::column<T>: T is read-only in this query; ask for column<const T>");
        using element =
            std::conditional_t<std::is_const_v<T>, const std::remove_const_t<T>, declared>;
        if (i != 0 && !m_aligned)
            throw std::logic_error(
                "ecs::query::column: tables are not aligned; call world::align first");
        return std::span<element>(std::get<i>(m_tables)->data(), size());
    }

private:
    template <class F, std::size_t... Is>
    void each_aligned(std::size_t begin, std::size_t end, F& f, std::index_sequence<Is...>) const {
        const entity* owners = std::get<0>(m_tables)->entities().data();
        const std::tuple<Ts*...> columns{std::get<Is>(m_tables)->data()...};
        for (std::size_t i = begin; i < end; ++i) f(owners[i], std::get<Is>(columns)[i]...);
    }

    template <class F, std::size_t... Is>
    void each_lookup(std::size_t begin, std::size_t end, F& f, std::index_sequence<Is...>) const {
        const entity* owners = std::get<0>(m_tables)->entities().data();
        for (std::size_t i = begin; i < end; ++i) {
            const entity e = owners[i];
            const std::tuple<Ts*...> found{find<Is>(i, e)...};
            if (((std::get<Is>(found) != nullptr) && ...)) f(e, *std::get<Is>(found)...);
        }
    }

    template <std::size_t I>
    auto* find(std::size_t dense, entity e) const {
        if constexpr (I == 0)
            return std::get<0>(m_tables)->data() + dense;
        else
            return std::get<I>(m_tables)->try_get(e);
    }

    tables_type m_tables;
    bool m_aligned = false;
};

}  // namespace sylva::ecs
