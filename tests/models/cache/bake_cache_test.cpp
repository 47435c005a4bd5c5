#include "models/cache/bake_cache.h"

#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

namespace sylva {
namespace {

namespace fs = std::filesystem;

struct temp_cache : ::testing::Test {
    fs::path root = fs::temp_directory_path() / ("sylva_cache_test_" + std::to_string(::getpid()));
    void SetUp() override { fs::remove_all(root); }
    void TearDown() override { fs::remove_all(root); }
};

std::vector<std::byte> bytes_of(std::string_view s) {
    const auto b = std::as_bytes(std::span(s.data(), s.size()));
    return {b.begin(), b.end()};
}

TEST_F(temp_cache, stored_entries_load_back_and_absent_ones_do_not) {
    bake_cache cache(root);
    EXPECT_FALSE(cache.load("plants", 42));
    cache.store("plants", 42, bytes_of("oak"));
    const auto loaded = cache.load("plants", 42);
    ASSERT_TRUE(loaded);
    EXPECT_EQ(*loaded, bytes_of("oak"));
    EXPECT_FALSE(cache.load("clouds", 42));  // kinds are separate
    EXPECT_EQ(cache.path_of("plants", 42).filename(), "000000000000002a.bin");
}

TEST_F(temp_cache, get_or_bake_bakes_once_then_hits) {
    bake_cache cache(root);
    int bakes = 0;
    auto bake = [&] {
        ++bakes;
        return bytes_of("baked");
    };
    EXPECT_EQ(cache.get_or_bake("plants", 7, bake), bytes_of("baked"));
    EXPECT_EQ(cache.get_or_bake("plants", 7, bake), bytes_of("baked"));
    bake_cache reopened(root);  // a later run
    EXPECT_EQ(reopened.get_or_bake("plants", 7, bake), bytes_of("baked"));
    EXPECT_EQ(bakes, 1);
    EXPECT_EQ(cache.misses(), 1u);
    EXPECT_EQ(cache.hits(), 1u);
    EXPECT_EQ(reopened.hits(), 1u);
}

// `sylva bake --force`: every entry made again once, then read back within the same run.
TEST_F(temp_cache, rebake_all_misses_each_entry_until_it_is_made_again) {
    bake_cache(root).store("plants", 7, bytes_of("old"));
    bake_cache cache(root);
    cache.rebake_all();
    int bakes = 0;
    auto bake = [&] {
        ++bakes;
        return bytes_of("new");
    };
    EXPECT_EQ(cache.get_or_bake("plants", 7, bake), bytes_of("new"));
    EXPECT_EQ(cache.get_or_bake("plants", 7, bake), bytes_of("new"));
    EXPECT_EQ(bakes, 1);
    EXPECT_EQ(cache.misses(), 1u);
    EXPECT_EQ(cache.hits(), 1u);
    EXPECT_EQ(*bake_cache(root).load("plants", 7),
              bytes_of("new"));  // a later run reads the new one
}

TEST_F(temp_cache, writes_leave_no_temporary_files) {
    bake_cache cache(root);
    cache.store("plants", 1, bytes_of("a"));
    cache.store("plants", 1, bytes_of("b"));  // overwrite
    std::size_t files = 0;
    for (const auto& entry : fs::recursive_directory_iterator(root))
        if (entry.is_regular_file()) {
            ++files;
            EXPECT_EQ(entry.path().extension(), ".bin");
        }
    EXPECT_EQ(files, 1u);
    EXPECT_EQ(*cache.load("plants", 1), bytes_of("b"));
}

// Issue 19: the cache caught truncation only through its decoders; a flipped bit in the middle
// of an entry was trusted (branch spikes across the sky) and stayed in the cache.
TEST_F(temp_cache, a_flipped_bit_anywhere_is_caught_removed_and_rebaked) {
    bake_cache cache(root);
    const std::string payload(4096, 'p');
    cache.store("plants", 3, bytes_of(payload));
    const fs::path path = cache.path_of("plants", 3);
    const auto size = fs::file_size(path);
    for (const std::uintmax_t at : {std::uintmax_t(0), std::uintmax_t(9), std::uintmax_t(17), size / 2, size - 1}) {
        cache.store("plants", 3, bytes_of(payload));
        {
            std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
            f.seekg(std::streamoff(at));
            char c = 0;
            f.get(c);
            f.seekp(std::streamoff(at));
            f.put(char(c ^ 0x10));
        }
        EXPECT_FALSE(cache.load("plants", 3)) << "a bit flipped at byte " << at << " was trusted";
        EXPECT_FALSE(fs::exists(path)) << "the damaged entry must be removed";
        int bakes = 0;
        EXPECT_EQ(cache.get_or_bake("plants", 3, [&] { return ++bakes, bytes_of(payload); }), bytes_of(payload));
        EXPECT_EQ(bakes, 0 + 1);
        EXPECT_TRUE(cache.load("plants", 3)) << "the rebuilt entry is good";
    }
}

TEST_F(temp_cache, truncated_and_headerless_entries_are_rebuilt) {
    bake_cache cache(root);
    cache.store("plants", 4, bytes_of("a payload of some length"));
    const fs::path path = cache.path_of("plants", 4);
    fs::resize_file(path, fs::file_size(path) - 3);
    EXPECT_FALSE(cache.load("plants", 4));
    std::ofstream(path, std::ios::binary) << "raw bytes from an older Sylva";
    EXPECT_FALSE(cache.load("plants", 4));
    EXPECT_EQ(cache.get_or_bake("plants", 4, [] { return bytes_of("new"); }), bytes_of("new"));
    EXPECT_EQ(*cache.load("plants", 4), bytes_of("new"));
}

// Issue 19: a directory in an entry's place failed every run with std::bad_alloc.
TEST_F(temp_cache, a_directory_in_an_entrys_place_is_replaced) {
    bake_cache cache(root);
    fs::create_directories(cache.path_of("plants", 5) / "inside");
    EXPECT_FALSE(cache.load("plants", 5));
    EXPECT_EQ(cache.get_or_bake("plants", 5, [] { return bytes_of("baked"); }), bytes_of("baked"));
    EXPECT_TRUE(fs::is_regular_file(cache.path_of("plants", 5)));
    fs::remove_all(cache.path_of("plants", 6));
    fs::create_directories(cache.path_of("plants", 6));
    EXPECT_NO_THROW(cache.store("plants", 6, bytes_of("x"))) << "store replaces it too";
    EXPECT_EQ(*cache.load("plants", 6), bytes_of("x"));
}

// An entry that passes its checksum but that its decoder refuses (an older layout under the
// same key) is discarded and baked again by read_or_bake, not an error for every later run.
TEST_F(temp_cache, read_or_bake_rebuilds_what_the_decoder_refuses) {
    bake_cache cache(root);
    cache.store("primitive_costs", 8, bytes_of("short"));
    int bakes = 0;
    const auto read = [](std::span<const std::byte> b) {
        if (b.size() != 8) throw std::runtime_error("entry has " + std::to_string(b.size()) + " bytes");
        return std::string(reinterpret_cast<const char*>(b.data()), b.size());
    };
    EXPECT_EQ(read_or_bake(&cache, "primitive_costs", 8, [&] { return ++bakes, bytes_of("8 bytes!"); }, read),
              "8 bytes!");
    EXPECT_EQ(bakes, 1);
    EXPECT_EQ(read_or_bake(&cache, "primitive_costs", 8, [&] { return ++bakes, bytes_of("8 bytes!"); }, read),
              "8 bytes!");
    EXPECT_EQ(bakes, 1) << "the rebuilt entry is read from then on";
}

TEST_F(temp_cache, a_store_the_disk_refuses_is_a_warning_not_a_failure) {
    fs::create_directories(root);
    std::ofstream(root / "plants") << "a file where the kind's folder should be";
    bake_cache cache(root);
    EXPECT_THROW(cache.store("plants", 1, bytes_of("x")), std::runtime_error);
    EXPECT_EQ(cache.get_or_bake("plants", 1, [] { return bytes_of("x"); }), bytes_of("x"));
}

TEST_F(temp_cache, file_hash_depends_on_contents_not_name) {
    fs::create_directories(root);
    std::ofstream(root / "a.gltf") << "same";
    std::ofstream(root / "b.gltf") << "same";
    std::ofstream(root / "c.gltf") << "other";
    EXPECT_EQ(hash_file(root / "a.gltf"), hash_file(root / "b.gltf"));
    EXPECT_NE(hash_file(root / "a.gltf"), hash_file(root / "c.gltf"));
    EXPECT_EQ(hash_file(root / "a.gltf"), hash_string("same"));
    EXPECT_THROW(hash_file(root / "missing.gltf"), std::runtime_error);
    EXPECT_THROW(hash_file("/dev/zero"), std::runtime_error) << "must not hash forever";
}

TEST(hash, fnv1a_matches_the_reference_values) {
    // FNV-1a 64 test vectors (Fowler, Noll, Vo): "" and "a".
    EXPECT_EQ(hash_string(""), 0xcbf29ce484222325ULL);
    EXPECT_EQ(hash_string("a"), 0xaf63dc4c8601ec8cULL);
}

TEST(binary_stream, round_trips_and_rejects_truncation) {
    binary_writer out;
    out.pod(std::uint32_t(7));
    out.array(std::vector<float>{1.0f, 2.5f});
    out.text("oak");
    const std::vector<std::byte> bytes = out.bytes();
    binary_reader in(bytes);
    EXPECT_EQ(in.pod<std::uint32_t>(), 7u);
    EXPECT_EQ(in.array<float>(), (std::vector<float>{1.0f, 2.5f}));
    EXPECT_EQ(in.text(), "oak");
    EXPECT_TRUE(in.at_end());
    binary_reader cut(std::span<const std::byte>(bytes).first(bytes.size() - 1));
    cut.pod<std::uint32_t>();
    cut.array<float>();
    EXPECT_THROW(cut.text(), std::runtime_error);
}

}  // namespace
}  // namespace sylva
