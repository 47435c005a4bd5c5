#include "models/bake_cache.h"

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

TEST_F(temp_cache, file_hash_depends_on_contents_not_name) {
    fs::create_directories(root);
    std::ofstream(root / "a.gltf") << "same";
    std::ofstream(root / "b.gltf") << "same";
    std::ofstream(root / "c.gltf") << "other";
    EXPECT_EQ(hash_file(root / "a.gltf"), hash_file(root / "b.gltf"));
    EXPECT_NE(hash_file(root / "a.gltf"), hash_file(root / "c.gltf"));
    EXPECT_EQ(hash_file(root / "a.gltf"), hash_string("same"));
    EXPECT_THROW(hash_file(root / "missing.gltf"), std::runtime_error);
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
