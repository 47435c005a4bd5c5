// io/atomic_file.h: whole files or none, every failure an error naming the path.
#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace sylva {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("sylva_io_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string read_all(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

std::size_t entries_in(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

TEST(atomic_file, writes_the_whole_content_and_replaces_an_older_file) {
    const fs::path dir = fresh_dir("whole");
    write_atomically(dir / "a.txt", std::string_view("first"));
    write_atomically(dir / "a.txt", std::string_view("second, longer"));
    EXPECT_EQ(read_all(dir / "a.txt"), "second, longer");
    EXPECT_EQ(entries_in(dir), 1u) << "no temporary file is left behind";
    fs::remove_all(dir);
}

TEST(atomic_file, refuses_a_directory_in_the_target_place_naming_it) {
    const fs::path dir = fresh_dir("directory");
    fs::create_directories(dir / "out.glb");
    try {
        write_atomically(dir / "out.glb", std::string_view("x"));
        FAIL() << "a directory was accepted as a file";
    } catch (const output_error& e) {
        EXPECT_NE(std::string(e.what()).find((dir / "out.glb").string()), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("a directory"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_directory(dir / "out.glb"));
    EXPECT_EQ(entries_in(dir), 1u);
    fs::remove_all(dir);
}

TEST(atomic_file, refuses_a_device_rather_than_replacing_it) {
    if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
    EXPECT_THROW(write_atomically("/dev/full", std::string_view("x")), output_error);
    EXPECT_TRUE(fs::is_character_file("/dev/full")) << "the device must still be there";
}

TEST(atomic_file, a_missing_folder_is_an_error_naming_the_path) {
    const fs::path dir = fresh_dir("missing");
    try {
        write_atomically(dir / "no" / "such" / "file.json", std::string_view("{}"));
        FAIL();
    } catch (const output_error& e) {
        EXPECT_NE(std::string(e.what()).find("file.json"), std::string::npos) << e.what();
    }
    fs::remove_all(dir);
}

// A full disk, simulated without privileges: RLIMIT_FSIZE makes write() fail with EFBIG once a
// file would pass the limit (SIGXFSZ ignored, as the contract tests of the commands do too).
TEST(atomic_file, a_write_that_fails_midway_leaves_no_file_and_reports_the_path) {
    const fs::path dir = fresh_dir("full");
    write_atomically(dir / "big.bin", std::string_view("old content"));
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::signal(SIGXFSZ, SIG_IGN);
        const rlimit limit{4096, 4096};
        ::setrlimit(RLIMIT_FSIZE, &limit);
        try {
            write_atomically(dir / "big.bin", std::string(1 << 20, 'x'));
        } catch (const output_error& e) {
            const std::string what = e.what();
            ::_exit(what.find("big.bin") != std::string::npos ? 42 : 43);
        }
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 42) << "0: the failed write went unnoticed";
    EXPECT_EQ(read_all(dir / "big.bin"), "old content") << "the old file must be untouched";
    EXPECT_EQ(entries_in(dir), 1u) << "the temporary file must be removed";
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
