#include "models/cache/bake_cache.h"

#include <spdlog/spdlog.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "io/atomic_file.h"
#include "io/input_file.h"
#include "io/once_per_process.h"

namespace sylva {

std::uint64_t hash_bytes(std::span<const std::byte> bytes, std::uint64_t seed) {
    std::uint64_t h = seed;
    for (std::byte b : bytes) {
        h ^= std::uint64_t(b);
        h *= 0x100000001b3ULL;
    }
    return h;
}

std::uint64_t hash_string(std::string_view text, std::uint64_t seed) {
    return hash_bytes(std::as_bytes(std::span(text.data(), text.size())), seed);
}

std::uint64_t hash_file(const std::filesystem::path& path, std::uint64_t seed) {
    check_input_file(path, k_max_model_bytes);  // never hash /dev/zero until memory runs out
    std::ifstream in(path, std::ios::binary);
    if (!in) throw input_error(path.string() + ": cannot open for hashing");
    std::vector<char> buffer(1 << 16);
    std::uint64_t h = seed;
    while (in) {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        h = hash_bytes(std::as_bytes(std::span(buffer.data(), std::size_t(in.gcount()))), h);
    }
    if (in.bad()) throw input_error(path.string() + ": cannot be read for hashing");
    return h;
}

namespace {

std::filesystem::path default_root() {
    if (const char* dir = std::getenv("SYLVA_CACHE_DIR"); dir && *dir) return dir;
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return std::filesystem::path(xdg) / "sylva";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "sylva";
    return std::filesystem::temp_directory_path() / "sylva-cache";
}

}  // namespace

bake_cache::bake_cache(std::filesystem::path root) : m_root(root.empty() ? default_root() : std::move(root)) {}

std::filesystem::path bake_cache::path_of(std::string_view kind, std::uint64_t key) const {
    char name[32];
    std::snprintf(name, sizeof(name), "%016llx.bin", static_cast<unsigned long long>(key));
    return m_root / std::string(kind) / name;
}

namespace {

constexpr std::array<char, 8> k_entry_magic = {'S', 'Y', 'L', 'V', 'A', 'C', 'E', '1'};
constexpr std::size_t k_entry_header_bytes = 24;
constexpr std::string_view k_older_format = "not a Sylva cache entry of this version (no header)";
// No bake comes near this; a larger "entry" is something else in the cache's place.
constexpr std::uint64_t k_max_entry_bytes = 4ull << 30;

std::uint64_t read_u64(const std::string& bytes, std::size_t at) {
    std::uint64_t v;
    std::memcpy(&v, bytes.data() + at, sizeof(v));
    return v;
}

// The payload of a stored entry, or why it cannot be trusted. FNV-1a (hash_bytes, already the
// cache's key hash) changes with any single changed byte: each step is a bijection of the state.
std::optional<std::vector<std::byte>> payload_of(const std::string& bytes, std::string& problem) {
    if (bytes.size() < k_entry_header_bytes ||
        std::memcmp(bytes.data(), k_entry_magic.data(), k_entry_magic.size()) != 0) {
        problem = k_older_format;
        return std::nullopt;
    }
    const std::uint64_t size = read_u64(bytes, 8);
    if (size != bytes.size() - k_entry_header_bytes) {
        problem = "truncated (" + std::to_string(bytes.size() - k_entry_header_bytes) + " of " +
                  std::to_string(size) + " bytes)";
        return std::nullopt;
    }
    const auto* begin = reinterpret_cast<const std::byte*>(bytes.data()) + k_entry_header_bytes;
    const std::span<const std::byte> payload(begin, std::size_t(size));
    if (hash_bytes(payload) != read_u64(bytes, 16)) {
        problem = "damaged (checksum mismatch)";
        return std::nullopt;
    }
    return std::vector<std::byte>(payload.begin(), payload.end());
}

// Each damaged entry is reported once per process, however many players read it.
bool first_report(const std::filesystem::path& path) {
    return first_time_in_process("damaged cache entry", path.string());
}

}  // namespace

void bake_cache::remove_damaged(const std::filesystem::path& path, const std::string& reason) {
    // An entry from an older Sylva is expected after an upgrade; a damaged one is not.
    const bool older_format = reason.starts_with(k_older_format);
    if (first_report(path))
        spdlog::log(older_format ? spdlog::level::info : spdlog::level::warn,
                    "bake cache: {}: {}; rebuilding it", path.string(), reason);
    std::error_code ec;
    std::filesystem::remove_all(path, ec);  // a directory in an entry's place goes too
}

std::optional<std::vector<std::byte>> bake_cache::load(std::string_view kind, std::uint64_t key) {
    const std::filesystem::path path = path_of(kind, key);
    std::error_code ec;
    if ((m_rebake && !m_stored.contains({std::string(kind), key})) ||
        !std::filesystem::exists(std::filesystem::symlink_status(path, ec))) {
        ++m_misses;
        return std::nullopt;
    }
    std::string problem;
    std::optional<std::vector<std::byte>> payload;
    try {
        payload = payload_of(read_input_file(path, k_max_entry_bytes), problem);
    } catch (const std::exception& e) {
        problem = e.what();  // a directory, a device, unreadable: named by read_input_file
    }
    if (!payload) {
        remove_damaged(path, problem);
        ++m_misses;
        return std::nullopt;
    }
    ++m_hits;
    return payload;
}

void bake_cache::discard(std::string_view kind, std::uint64_t key, const std::string& reason) {
    remove_damaged(path_of(kind, key), reason);
    if (m_hits > 0) --m_hits;
    ++m_misses;
}

void bake_cache::store(std::string_view kind, std::uint64_t key, std::span<const std::byte> bytes) {
    const std::filesystem::path path = path_of(kind, key);
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec) throw std::runtime_error("bake cache: cannot create " + path.parent_path().string() + ": " + ec.message());
    const std::uint64_t size = bytes.size();
    const std::uint64_t checksum = hash_bytes(bytes);
    std::vector<std::byte> entry(k_entry_header_bytes + bytes.size());
    std::memcpy(entry.data(), k_entry_magic.data(), k_entry_magic.size());
    std::memcpy(entry.data() + 8, &size, sizeof(size));
    std::memcpy(entry.data() + 16, &checksum, sizeof(checksum));
    if (!bytes.empty()) std::memcpy(entry.data() + k_entry_header_bytes, bytes.data(), bytes.size());
    // Whatever sits in the entry's place (a directory) would make every rename fail.
    if (const auto status = std::filesystem::symlink_status(path, ec);
        std::filesystem::exists(status) && !std::filesystem::is_regular_file(status))
        std::filesystem::remove_all(path, ec);
    try {
        write_atomically(path, entry);
    } catch (const output_error& e) {
        throw std::runtime_error(std::string("bake cache: ") + e.what());
    }
    if (m_rebake) m_stored.emplace(std::string(kind), key);
}

void bake_cache::store_or_warn(std::string_view kind, std::uint64_t key, std::span<const std::byte> bytes) {
    try {
        store(kind, key, bytes);
    } catch (const std::runtime_error& e) {
        if (first_report(m_root / "store failure"))
            spdlog::warn("{}; going on without caching", e.what());
    }
}

std::vector<std::byte> bake_cache::get_or_bake(std::string_view kind, std::uint64_t key,
                                               const std::function<std::vector<std::byte>()>& bake) {
    if (auto cached = load(kind, key)) return std::move(*cached);
    std::vector<std::byte> bytes = bake();
    store_or_warn(kind, key, bytes);
    return bytes;
}

void binary_reader::take(void* out, std::size_t n) {
    if (n > m_bytes.size() - m_offset) throw_truncated();
    if (n == 0) return;  // an empty array's data() may be null: memcpy(nullptr, ..., 0) is UB
    std::memcpy(out, m_bytes.data() + m_offset, n);
    m_offset += n;
}

void binary_reader::throw_truncated() { throw std::runtime_error("bake cache entry is truncated or malformed"); }

}  // namespace sylva
