// ECS iteration cost on the plant-frame shape: 1M entities with six components (52 B in total),
// walked by a cull-like query in fixed chunks. Compares the aligned fast path with the sparse
// lookup fallback, and measures query construction (alignment cache hit) on its own.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "ecs/executor.h"
#include "ecs/parallel.h"
#include "ecs/world.h"

namespace {

using namespace sylva;

struct transform32 {
    double x, y, z;
    float yaw, scale;
};
struct bounds8 {
    float radius, center;
};
struct instance8 {
    std::uint16_t species, tint;
    std::uint32_t seed;
};
struct lod4 {
    std::uint32_t bits;
};
struct prefix8 {
    std::uint32_t points, lines;
};
struct fade4 {
    float alpha;
};
static_assert(sizeof(transform32) == 32);

constexpr std::size_t k_plants = 1'000'000;

ecs::world& plants() {
    static ecs::world w = [] {
        ecs::world built;
        for (std::size_t i = 0; i < k_plants; ++i) {
            const ecs::entity e = built.create();
            built.emplace<transform32>(e, {double(i % 1000), 0.0, double(i / 1000), 0.0f, 1.0f});
            built.emplace<bounds8>(e, {4.0f, 3.0f});
            built.emplace<instance8>(e, {std::uint16_t(i % 7), 0, std::uint32_t(i)});
            built.emplace<lod4>(e);
            built.emplace<prefix8>(e);
            built.emplace<fade4>(e);
        }
        return built;
    }();
    return w;
}

void cull_like(ecs::query<const transform32, const bounds8, const instance8, lod4>& q) {
    ecs::parallel_for(
        q.size(), ecs::k_default_chunk, [&](std::size_t begin, std::size_t end, std::size_t) {
            q.each_chunk(begin, end,
                         [](ecs::entity, const transform32& t, const bounds8& b, const instance8& p,
                            lod4& lod) {
                             const double d2 = t.x * t.x + t.z * t.z;
                             const double r = double(b.radius) * t.scale + 200.0;
                             lod.bits = (d2 < r * r ? 1u : 0u) | (std::uint32_t(p.species) << 1);
                         });
        });
}

void bm_aligned_query(benchmark::State& state) {
    ecs::world& w = plants();
    ecs::executor exec(int(state.range(0)));
    for (auto _ : state) {
        auto q = w.query<const transform32, const bounds8, const instance8, lod4>();
        if (!q.aligned()) state.SkipWithError("tables not aligned");
        exec.run([&] { cull_like(q); });
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(k_plants));
}
BENCHMARK(bm_aligned_query)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void bm_lookup_fallback(benchmark::State& state) {
    ecs::world& w = plants();
    ecs::executor exec(int(state.range(0)));
    for (auto _ : state) {
        ecs::query<const transform32, const bounds8, const instance8, lod4> q(
            {&std::as_const(w).table<transform32>(), &std::as_const(w).table<bounds8>(),
             &std::as_const(w).table<instance8>(), &w.table<lod4>()},
            false);
        exec.run([&] { cull_like(q); });
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(k_plants));
}
BENCHMARK(bm_lookup_fallback)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void bm_query_construction(benchmark::State& state) {
    ecs::world& w = plants();
    for (auto _ : state) {
        auto q = w.query<const transform32, const bounds8, const instance8, lod4, prefix8, fade4>();
        benchmark::DoNotOptimize(q);
    }
}
BENCHMARK(bm_query_construction);

}  // namespace

BENCHMARK_MAIN();
