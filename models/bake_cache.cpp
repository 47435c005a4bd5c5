#include "models/bake_cache.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

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
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error(path.string() + ": cannot open for hashing");
    std::vector<char> buffer(1 << 16);
    std::uint64_t h = seed;
    while (in) {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        h = hash_bytes(std::as_bytes(std::span(buffer.data(), std::size_t(in.gcount()))), h);
    }
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

std::optional<std::vector<std::byte>> bake_cache::load(std::string_view kind, std::uint64_t key) {
    std::ifstream in(path_of(kind, key), std::ios::binary | std::ios::ate);
    if (!in) return std::nullopt;
    const auto size = std::size_t(in.tellg());
    std::vector<std::byte> bytes(size);
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size))) return std::nullopt;
    return bytes;
}

void bake_cache::store(std::string_view kind, std::uint64_t key, std::span<const std::byte> bytes) {
    const std::filesystem::path path = path_of(kind, key);
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
    if (ec) throw std::runtime_error("bake cache: cannot create " + path.parent_path().string() + ": " + ec.message());
    const std::filesystem::path temporary = path.string() + ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(temporary, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        if (!out) throw std::runtime_error("bake cache: cannot write " + temporary.string());
    }
    std::filesystem::rename(temporary, path, ec);
    if (ec) throw std::runtime_error("bake cache: cannot move " + temporary.string() + " to " + path.string());
}

std::vector<std::byte> bake_cache::get_or_bake(std::string_view kind, std::uint64_t key,
                                               const std::function<std::vector<std::byte>()>& bake) {
    if (auto cached = load(kind, key)) {
        ++m_hits;
        return std::move(*cached);
    }
    ++m_misses;
    std::vector<std::byte> bytes = bake();
    store(kind, key, bytes);
    return bytes;
}

void binary_reader::take(void* out, std::size_t n) {
    if (n > m_bytes.size() - m_offset) throw_truncated();
    std::memcpy(out, m_bytes.data() + m_offset, n);
    m_offset += n;
}

void binary_reader::throw_truncated() { throw std::runtime_error("bake cache entry is truncated or malformed"); }

}  // namespace sylva
