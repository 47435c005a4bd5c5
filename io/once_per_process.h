#pragma once
// "Say it once": the bench and the tests build many players from one scenario, cache and device
// in one process, and each would repeat the same warning word for word.
#include <mutex>
#include <set>
#include <string>
#include <string_view>

namespace sylva {

// True the first time this (topic, key) pair is asked about in this process, from any thread;
// false after. The topic keeps unrelated callers' keys apart.
inline bool first_time_in_process(std::string_view topic, std::string_view key) {
    static std::mutex mutex;
    static std::set<std::string, std::less<>> seen;
    std::string entry;
    entry.reserve(topic.size() + 1 + key.size());
    entry.append(topic).push_back('\0');
    entry.append(key);
    const std::lock_guard lock(mutex);
    return seen.insert(std::move(entry)).second;
}

}  // namespace sylva
