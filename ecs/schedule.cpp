#include "ecs/schedule.h"

#include <oneapi/tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>

#include "ecs/tsan_handoff.h"

namespace sylva::ecs {

namespace {

bool intersects(const std::vector<std::size_t>& a, const std::vector<std::size_t>& b) {
    return std::any_of(a.begin(), a.end(), [&](std::size_t id) {
        return std::find(b.begin(), b.end(), id) != b.end();
    });
}

}  // namespace

schedule::schedule() = default;
schedule::~schedule() = default;

void schedule::add_entry(system_entry entry) {
    for (const system_entry& s : m_systems)
        if (s.name == entry.name)
            throw std::invalid_argument("ecs::schedule::add: duplicate system name " +
                                        std::string(entry.name));
    m_systems.push_back(std::move(entry));
    m_built = false;
}

bool schedule::conflict(const system_entry& a, const system_entry& b) const {
    return intersects(a.writes, b.writes) || intersects(a.writes, b.reads) ||
           intersects(a.reads, b.writes);
}

void schedule::build() {
    const std::size_t n = m_systems.size();
    m_phases.clear();
    m_successors.assign(n, {});
    m_predecessors.assign(n, {});
    for (std::size_t p = 0; p < k_phase_count; ++p) {
        phase_group group{static_cast<phase>(p), false, {}};
        for (std::uint32_t i = 0; i < n; ++i) {
            if (m_systems[i].stage != group.stage) continue;
            group.main_thread = group.main_thread || m_systems[i].main_thread;
            for (const std::uint32_t earlier : group.systems) {
                if (!conflict(m_systems[earlier], m_systems[i])) continue;
                m_successors[earlier].push_back(i);
                m_predecessors[i].push_back(earlier);
            }
            group.systems.push_back(i);
        }
        if (!group.systems.empty()) m_phases.push_back(std::move(group));
    }
    m_pending = std::make_unique<std::atomic<std::uint32_t>[]>(n);
    m_timings.clear();
    for (const system_entry& s : m_systems) m_timings.emplace_back(s.name, 0.0);
    m_built = true;
}

std::uint32_t schedule::index_of(std::string_view name) const {
    for (std::uint32_t i = 0; i < m_systems.size(); ++i)
        if (m_systems[i].name == name) return i;
    throw std::invalid_argument("ecs::schedule: unknown system " + std::string(name));
}

bool schedule::depends_on(std::string_view later, std::string_view earlier) const {
    if (!m_built) throw std::logic_error("ecs::schedule::depends_on: call build() first");
    const auto& preds = m_predecessors[index_of(later)];
    return std::find(preds.begin(), preds.end(), index_of(earlier)) != preds.end();
}

const std::vector<loop_record>& schedule::last_loops(std::string_view system) const {
    return m_systems[index_of(system)].loops;
}

std::vector<std::string_view> schedule::system_names() const {
    std::vector<std::string_view> names;
    names.reserve(m_systems.size());
    for (const system_entry& s : m_systems) names.push_back(s.name);
    return names;
}

void schedule::run(world& w, executor& exec) {
    if (!m_built) build();
    for (const system_entry& s : m_systems) s.prepare(w);
    for (const phase_group& group : m_phases) {
        run_phase(group, w, exec);
        // The sync point: structural changes land here, in registration order.
        for (const std::uint32_t i : group.systems) m_systems[i].commands.apply(w);
    }
}

void schedule::run_phase(const phase_group& group, world& w, executor& exec) {
    if (group.main_thread) {
        for (const std::uint32_t i : group.systems) run_one(i, w);
    } else if (group.systems.size() == 1) {
        exec.run([&] { run_one(group.systems.front(), w); });
    } else {
        exec.run([&] { run_concurrent(group, w); });
    }
}

// Launches each system as soon as its last predecessor in the phase finishes. The task group
// lives and is waited on inside the executor's arena, so nested parallel_for calls share it.
void schedule::run_concurrent(const phase_group& group, world& w) {
    for (const std::uint32_t i : group.systems)
        m_pending[i].store(static_cast<std::uint32_t>(m_predecessors[i].size()),
                           std::memory_order_relaxed);
    tbb::task_group tasks;
    // Each system's task acquires what its spawner released on that system's counter: the edge
    // TBB's spawn makes, told to TSan (ecs/tsan_handoff.h); the tasks' ends are joined below.
    const task_handoff ends;
    struct launcher {
        schedule& self;
        world& w;
        tbb::task_group& tasks;
        const task_handoff& ends;
        void spawn(std::uint32_t i) const {
            // The token travels in the task itself: the task must acquire before it reads
            // anything the spawner wrote, this launcher included.
            const void* token = &self.m_pending[i];
            tsan_release(token);
            tasks.run([this, i, token] {
                tsan_acquire(token);
                const auto in_task = ends.task();
                (*this)(i);
            });
        }
        void operator()(std::uint32_t i) const {
            self.run_one(i, w);
            for (const std::uint32_t next : self.m_successors[i])
                if (self.m_pending[next].fetch_sub(1, std::memory_order_acq_rel) == 1) spawn(next);
        }
    };
    const launcher launch{*this, w, tasks, ends};
    for (const std::uint32_t i : group.systems)
        if (m_predecessors[i].empty()) launch.spawn(i);
    tasks.wait();
    ends.joined();
}

void schedule::run_one(std::uint32_t system, world& w) {
    system_entry& s = m_systems[system];
    const auto start = std::chrono::steady_clock::now();
    s.loops.clear();
    s.run(w, s.commands, s.loops);
    const std::chrono::duration<double, std::milli> elapsed =
        std::chrono::steady_clock::now() - start;
    m_timings[system].second = elapsed.count();
}

}  // namespace sylva::ecs
