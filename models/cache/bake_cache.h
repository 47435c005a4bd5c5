#pragma once
// The bake cache: derived data (plant models now; billboard clouds, PRT coefficients and the
// other bakes later) stored on disk under a key that hashes every input and setting that
// produced it, so a bake is reused exactly when nothing it depends on changed. Entries are
// written atomically (temporary file, then rename): an interrupted bake never leaves a
// half-written entry that a later run would trust. Each entry carries its payload's size and
// checksum, verified on every read: a truncated or bit-flipped entry, or anything else in its
// place (a directory, a device), is reported once, removed and baked again, never used.
//
//   entry = | magic "SYLVACE1" (8 bytes) | payload size (u64) | FNV-1a 64 of payload (u64) | payload |
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sylva {

// FNV-1a 64 over bytes; chain calls through `seed` to hash several inputs.
std::uint64_t hash_bytes(std::span<const std::byte> bytes, std::uint64_t seed = 0xcbf29ce484222325ULL);
std::uint64_t hash_string(std::string_view text, std::uint64_t seed = 0xcbf29ce484222325ULL);
// The file's contents (not its name or time): moving or touching a model keeps its bakes.
std::uint64_t hash_file(const std::filesystem::path& path, std::uint64_t seed = 0xcbf29ce484222325ULL);

class bake_cache {
public:
    // `root` empty: $SYLVA_CACHE_DIR, else $XDG_CACHE_HOME/sylva, else ~/.cache/sylva.
    explicit bake_cache(std::filesystem::path root = {});

    // The stored payload of (kind, key), or nothing when absent; a damaged or unreadable entry
    // is discarded (reported once, removed) and also gives nothing. Counts a hit or a miss.
    std::optional<std::vector<std::byte>> load(std::string_view kind, std::uint64_t key);
    // Stores atomically with its checksum; throws std::runtime_error naming the path when the
    // disk refuses.
    void store(std::string_view kind, std::uint64_t key, std::span<const std::byte> bytes);
    // store, but a disk that refuses (full, read-only) is reported once and the bake used
    // anyway: the cache only saves time, the run does not depend on it.
    void store_or_warn(std::string_view kind, std::uint64_t key, std::span<const std::byte> bytes);
    // load, or produce + store_or_warn on a miss.
    std::vector<std::byte> get_or_bake(std::string_view kind, std::uint64_t key,
                                       const std::function<std::vector<std::byte>()>& bake);
    // An entry that loaded but cannot be used (`reason`: its decoder's complaint): reported once
    // per process, removed, and the last load counted as a miss.
    void discard(std::string_view kind, std::uint64_t key, const std::string& reason);

    // From now on every entry is made again: a load misses (counted as one) unless this cache
    // stored the entry itself since, so each is baked once and later reads in the same run hit
    // (`sylva bake --force`).
    void rebake_all() { m_rebake = true; }

    std::filesystem::path path_of(std::string_view kind, std::uint64_t key) const;
    const std::filesystem::path& root() const { return m_root; }
    std::size_t hits() const { return m_hits; }
    std::size_t misses() const { return m_misses; }

private:
    void remove_damaged(const std::filesystem::path& path, const std::string& reason);

    std::filesystem::path m_root;
    std::size_t m_hits = 0;
    std::size_t m_misses = 0;
    bool m_rebake = false;
    std::set<std::pair<std::string, std::uint64_t>> m_stored;  // with m_rebake: made in this run
};

// Decodes (kind, key) from the cache with `read`; an entry that is absent, damaged, or that
// `read` rejects (throws std::runtime_error) is discarded, baked again, stored and read. Without
// a cache, bakes and reads.
template <class Bake, class Read>
auto read_or_bake(bake_cache* cache, std::string_view kind, std::uint64_t key, const Bake& bake,
                  const Read& read) -> decltype(read(std::vector<std::byte>{})) {
    if (!cache) return read(bake());
    if (auto bytes = cache->load(kind, key)) {
        try {
            return read(*bytes);
        } catch (const std::runtime_error& e) {
            cache->discard(kind, key, e.what());
        }
    }
    const std::vector<std::byte> bytes = bake();
    cache->store_or_warn(kind, key, bytes);
    return read(bytes);
}

// Little-endian binary streams of plain data for cache entries. Readers check bounds and
// throw std::runtime_error on a truncated or malformed entry (the caller re-bakes).
class binary_writer {
public:
    template <class T>
    void pod(const T& value) {
        append(&value, sizeof(T));
    }
    template <class T>
    void array(const std::vector<T>& values) {
        pod(std::uint64_t(values.size()));
        append(values.data(), values.size() * sizeof(T));
    }
    void text(std::string_view s) {
        pod(std::uint64_t(s.size()));
        append(s.data(), s.size());
    }
    // Bytes as they are, with no count (the caller wrote one).
    void raw(std::span<const std::byte> bytes) { append(bytes.data(), bytes.size()); }
    std::vector<std::byte>& bytes() { return m_bytes; }

private:
    // resize + memcpy rather than vector::insert, whose inlined form GCC 12 misreads as an
    // overflow (-Wstringop-overflow) when the writer starts empty.
    void append(const void* data, std::size_t size) {
        if (size == 0) return;
        const std::size_t at = m_bytes.size();
        m_bytes.resize(at + size);
        std::memcpy(m_bytes.data() + at, data, size);
    }

    std::vector<std::byte> m_bytes;
};

class binary_reader {
public:
    explicit binary_reader(std::span<const std::byte> bytes) : m_bytes(bytes) {}
    template <class T>
    T pod() {
        T value;
        take(&value, sizeof(T));
        return value;
    }
    template <class T>
    std::vector<T> array() {
        const auto count = pod<std::uint64_t>();
        if (count > (m_bytes.size() - m_offset) / sizeof(T)) throw_truncated();
        std::vector<T> values(count);
        take(values.data(), count * sizeof(T));
        return values;
    }
    std::string text() {
        const auto count = pod<std::uint64_t>();
        if (count > m_bytes.size() - m_offset) throw_truncated();
        std::string s(count, '\0');
        take(s.data(), count);
        return s;
    }
    bool at_end() const { return m_offset == m_bytes.size(); }

private:
    void take(void* out, std::size_t n);
    [[noreturn]] static void throw_truncated();
    std::span<const std::byte> m_bytes;
    std::size_t m_offset = 0;
};

}  // namespace sylva
