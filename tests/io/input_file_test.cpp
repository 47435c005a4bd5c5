// io/input_file.h, io/json_nesting.h and io/confined_path.h: bounded, confined reading.
#include "io/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/confined_path.h"
#include "io/json_nesting.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("sylva_in_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const input_error& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(input_file, reads_a_regular_file_whole) {
    const fs::path dir = fresh_dir("read");
    std::ofstream(dir / "a.json") << "{\"a\": 1}";
    EXPECT_EQ(read_input_file(dir / "a.json", 100), "{\"a\": 1}");
    EXPECT_EQ(check_input_file(dir / "a.json", 100), 8u);
    fs::remove_all(dir);
}

TEST(input_file, refuses_devices_directories_and_fifos_without_reading_them) {
    const fs::path dir = fresh_dir("kinds");
    EXPECT_NE(message_of([&] { read_input_file("/dev/zero", 1 << 20); }).find("a character device"),
              std::string::npos);
    EXPECT_NE(message_of([&] { read_input_file(dir, 1 << 20); }).find("a directory"), std::string::npos);
    ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
    // Opening a FIFO with no writer would block forever without O_NONBLOCK.
    EXPECT_NE(message_of([&] { read_input_file(dir / "pipe", 1 << 20); }).find("FIFO"), std::string::npos);
    fs::remove_all(dir);
}

TEST(input_file, refuses_a_file_above_the_limit_naming_both_sizes) {
    const fs::path dir = fresh_dir("limit");
    std::ofstream(dir / "big.json") << std::string(3 << 20, ' ');
    const std::string message = message_of([&] { read_input_file(dir / "big.json", 2 << 20); });
    EXPECT_NE(message.find("big.json"), std::string::npos) << message;
    EXPECT_NE(message.find("3 MB"), std::string::npos) << message;
    EXPECT_NE(message.find("2 MB limit"), std::string::npos) << message;
    fs::remove_all(dir);
}

TEST(input_file, image_dimensions_are_bounded_before_decoding) {
    EXPECT_NO_THROW(check_image_dimensions("tex", 8192, 8192));
    EXPECT_NO_THROW(check_image_dimensions("tex", 16384, 4096));
    EXPECT_NE(message_of([] { check_image_dimensions("tex", 30000, 30000); }).find("30000x30000"),
              std::string::npos);
    EXPECT_THROW(check_image_dimensions("tex", 16385, 1), input_error);
    EXPECT_THROW(check_image_dimensions("tex", 16384, 8192), input_error);  // 128 M pixels
    EXPECT_THROW(check_image_dimensions("tex", 0, 10), input_error);
    EXPECT_THROW(check_image_dimensions("tex", -5, 10), input_error);
}

TEST(json_nesting, finds_the_first_bracket_beyond_the_limit_outside_strings) {
    EXPECT_FALSE(find_nesting_beyond(R"({"a": [1, [2]]})", 3));
    EXPECT_EQ(find_nesting_beyond(R"({"a": [1, [2]]})", 2), 10u);
    EXPECT_FALSE(find_nesting_beyond(R"({"a": "[[[[[[\"[[[["})", 1)) << "brackets in strings";
    EXPECT_EQ(find_nesting_beyond(std::string(1000000, '['), 64), 64u);
    EXPECT_FALSE(find_nesting_beyond("[]]]]]]][", 1)) << "stray closers do not underflow";
}

TEST(confined_path, percent_decoding_and_schemes) {
    EXPECT_EQ(percent_decode("a%20b%2e%2E%2Fc"), "a b../c");
    EXPECT_EQ(percent_decode("100%"), "100%");
    EXPECT_EQ(percent_decode("%zz%4"), "%zz%4");
    EXPECT_TRUE(has_uri_scheme("file:///etc/passwd"));
    EXPECT_TRUE(has_uri_scheme("http://x"));
    EXPECT_TRUE(has_uri_scheme("data:application/octet-stream;base64,AA=="));
    EXPECT_FALSE(has_uri_scheme("textures/leaf.png"));
    EXPECT_FALSE(has_uri_scheme(":x"));
    EXPECT_FALSE(has_uri_scheme("1http:x"));
}

TEST(confined_path, files_inside_the_folder_resolve_and_everything_else_is_refused_alike) {
    const fs::path dir = fresh_dir("confined");
    fs::create_directories(dir / "model" / "textures");
    std::ofstream(dir / "model" / "textures" / "leaf.png") << "png";
    std::ofstream(dir / "secret.txt") << "a secret of 33 bytes, not to leak";
    fs::create_symlink(dir / "secret.txt", dir / "model" / "link.bin");
    const fs::path model = dir / "model";
    EXPECT_EQ(resolve_inside(model, "textures/leaf.png", "m"), model / "textures/leaf.png");
    EXPECT_EQ(resolve_inside(model, "textures/../textures/leaf%2Epng", "m"),
              model / "textures/../textures/leaf.png");
    for (const char* uri : {"../secret.txt", "%2e%2e/secret.txt", "textures/../../secret.txt",
                            "/etc/passwd", "file:///etc/passwd", "link.bin", "../nonexistent.bin"}) {
        const std::string message = message_of([&] { resolve_inside(model, uri, "m.gltf: buffer 0"); });
        EXPECT_NE(message.find(std::string("'") + uri + "'"), std::string::npos) << message;
        EXPECT_EQ(message.find("33"), std::string::npos) << "reveals the secret's size: " << message;
        EXPECT_EQ(message.find("secret of"), std::string::npos) << message;
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
