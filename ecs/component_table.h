#pragma once
// One table per component type: a sparse set. Components live densely in a contiguous
// std::vector<T> with a parallel vector of owning entities, so systems stream over data() with no
// indirection; the sparse vector (indexed by entity index) answers "where is e's component" in
// O(1). Removal swaps the last element into the hole, which keeps the arrays dense but changes
// order — see world::align() for restoring a shared order across tables.
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "ecs/entity.h"

namespace sylva::ecs {

inline constexpr std::size_t k_npos = static_cast<std::size_t>(-1);

// The type-erased face the world needs to strip a destroyed entity from every table.
class table_base {
public:
    virtual ~table_base() = default;
    virtual bool remove(entity e) = 0;
    virtual bool contains(entity e) const = 0;
    virtual std::size_t size() const = 0;
    virtual std::span<const entity> entities() const = 0;
    // Bumped on every change of membership or order (not on value writes); lets the world cache
    // "these two tables are aligned" without rescanning them every query.
    std::uint64_t layout_version() const { return m_layout_version; }

protected:
    table_base() = default;
    table_base(const table_base&) = default;
    table_base& operator=(const table_base&) = default;
    void touch_layout() { ++m_layout_version; }

private:
    std::uint64_t m_layout_version = 0;
};

template <class T>
class component_table final : public table_base {
    static_assert(std::is_trivially_copyable_v<T>,
                  "ecs components are plain data: use handles instead of pointers or containers");
    static_assert(!std::is_const_v<T> && !std::is_reference_v<T>,
                  "component_table<T> takes a bare type");

public:
    using value_type = T;

    std::size_t size() const override { return m_data.size(); }
    bool empty() const { return m_data.empty(); }
    T* data() { return m_data.data(); }
    const T* data() const { return m_data.data(); }
    std::span<T> values() { return m_data; }
    std::span<const T> values() const { return m_data; }
    std::span<const entity> entities() const override { return m_entities; }

    std::size_t index_of(entity e) const {
        if (e.index >= m_sparse.size()) return k_npos;
        const std::uint32_t dense = m_sparse[e.index];
        if (dense == k_absent || m_entities[dense] != e) return k_npos;
        return dense;
    }
    bool contains(entity e) const override { return index_of(e) != k_npos; }

    T* try_get(entity e) {
        const std::size_t i = index_of(e);
        return i == k_npos ? nullptr : &m_data[i];
    }
    const T* try_get(entity e) const { return const_cast<component_table*>(this)->try_get(e); }
    T& get(entity e) {
        T* value = try_get(e);
        if (!value)
            throw std::out_of_range("ecs::component_table::get: entity has no such component");
        return *value;
    }
    const T& get(entity e) const { return const_cast<component_table*>(this)->get(e); }

    // Inserts or overwrites; the caller (world) has checked that e is alive.
    T& emplace(entity e, const T& value) {
        if (T* existing = try_get(e)) return *existing = value;
        if (e.index >= m_sparse.size()) m_sparse.resize(std::size_t{e.index} + 1, k_absent);
        m_sparse[e.index] = static_cast<std::uint32_t>(m_data.size());
        m_entities.push_back(e);
        m_data.push_back(value);
        touch_layout();
        return m_data.back();
    }

    bool remove(entity e) override {
        const std::size_t i = index_of(e);
        if (i == k_npos) return false;
        const std::size_t last = m_data.size() - 1;
        if (i != last) move_dense(last, i);
        m_sparse[e.index] = k_absent;
        m_entities.pop_back();
        m_data.pop_back();
        touch_layout();
        return true;
    }

    // Exchanges two dense slots; used by world::align() to reorder without reallocating.
    void swap_dense(std::size_t a, std::size_t b) {
        if (a == b) return;
        std::swap(m_entities[a], m_entities[b]);
        std::swap(m_data[a], m_data[b]);
        m_sparse[m_entities[a].index] = static_cast<std::uint32_t>(a);
        m_sparse[m_entities[b].index] = static_cast<std::uint32_t>(b);
        touch_layout();
    }

    void reserve(std::size_t n) {
        m_entities.reserve(n);
        m_data.reserve(n);
    }
    void clear() {
        for (const entity e : m_entities) m_sparse[e.index] = k_absent;
        m_entities.clear();
        m_data.clear();
        touch_layout();
    }

private:
    static constexpr std::uint32_t k_absent = 0xFFFF'FFFFu;

    void move_dense(std::size_t from, std::size_t to) {
        m_entities[to] = m_entities[from];
        m_data[to] = m_data[from];
        m_sparse[m_entities[to].index] = static_cast<std::uint32_t>(to);
    }

    std::vector<std::uint32_t> m_sparse;  // entity index -> dense index, k_absent if none
    std::vector<entity> m_entities;       // dense: owner of m_data[i]
    std::vector<T> m_data;                // dense component values
};

}  // namespace sylva::ecs
