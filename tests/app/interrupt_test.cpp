// Interrupts (issue 19): SIGINT or SIGTERM during `play` or `bench` finishes the current frame,
// writes metrics.json (or the bench files) for what was done, marked partial, and exits 130 or
// 143. On main the run ended with no message and no metrics.json.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

#include "run_sylva.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
    std::ifstream in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// Starts the binary under test with `arguments` (split on spaces), its output in `log`.
pid_t start(const std::string& arguments, const fs::path& log) {
    std::vector<std::string> words{test::sylva_binary()};
    std::istringstream split(arguments);
    for (std::string w; split >> w;) words.push_back(w);
    const pid_t child = ::fork();
    if (child == 0) {
        const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(fd, STDOUT_FILENO);
        ::dup2(fd, STDERR_FILENO);
        std::vector<char*> argv;
        for (std::string& w : words) argv.push_back(w.data());
        argv.push_back(nullptr);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    return child;
}

// Waits until `log` contains `text` (or the child ended, or 300 s passed).
bool wait_for(pid_t child, const fs::path& log, const std::string& text) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
    while (std::chrono::steady_clock::now() < deadline) {
        if (read_all(log).find(text) != std::string::npos) return true;
        if (::waitpid(child, nullptr, WNOHANG) == child) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

int exit_code_of(pid_t child) {
    int status = 0;
    ::waitpid(child, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

void expect_partial_play(int signal, int expected_code, const std::string& signal_name) {
    const fs::path dir = test::fresh_temp_dir("interrupt_play_" + signal_name);
    const fs::path log = dir / "log.txt";
    const pid_t child = start(
        "play tiny --representation mesh_levels --headless --frames 100000 --width 32 --height 18 "
        "--out " +
            (dir / "out").string(),
        log);
    ASSERT_TRUE(wait_for(child, log, "frame 3/100000")) << read_all(log);
    ::kill(child, signal);
    EXPECT_EQ(exit_code_of(child), expected_code) << read_all(log);
    const std::string output = read_all(log);
    EXPECT_NE(output.find("interrupted by " + signal_name), std::string::npos) << output;
    ASSERT_TRUE(fs::exists(dir / "out" / "metrics.json")) << output;
    const auto metrics = nlohmann::json::parse(std::ifstream(dir / "out" / "metrics.json"));
    EXPECT_TRUE(metrics["summary"]["partial"].get<bool>());
    EXPECT_EQ(metrics["summary"]["interrupted_by"], signal_name);
    EXPECT_EQ(metrics["summary"]["frames_planned"], 100000);
    std::size_t pngs = 0, temporaries = 0;
    for (const auto& entry : fs::directory_iterator(dir / "out")) {
        if (entry.path().extension() == ".png") ++pngs;
        if (entry.path().filename().string().find(".tmp") != std::string::npos) ++temporaries;
    }
    // Every frame in metrics.json is on disk, complete; the frame in progress was finished.
    EXPECT_GE(metrics["frames"].size(), 3u);
    EXPECT_EQ(pngs, metrics["frames"].size());
    EXPECT_EQ(temporaries, 0u);
    fs::remove_all(dir);
}

TEST(interrupt, sigint_during_play_keeps_the_frames_and_a_partial_metrics_file) {
    expect_partial_play(SIGINT, 130, "SIGINT");
}

TEST(interrupt, sigterm_during_play_exits_143_with_a_partial_metrics_file) {
    expect_partial_play(SIGTERM, 143, "SIGTERM");
}

TEST(interrupt, sigterm_during_bench_writes_the_bench_files_marked_partial) {
    const fs::path dir = test::fresh_temp_dir("interrupt_bench");
    const fs::path log = dir / "log.txt";
    const pid_t child = start("bench tiny --only baseline --frames 100000 --width 32 --height 18 --out " +
                                  (dir / "out").string(),
                              log);
    ASSERT_TRUE(wait_for(child, log, "frame 3/100000")) << read_all(log);
    ::kill(child, SIGTERM);
    EXPECT_EQ(exit_code_of(child), 143) << read_all(log);
    ASSERT_TRUE(fs::exists(dir / "out" / "bench.json")) << read_all(log);
    const auto bench = nlohmann::json::parse(std::ifstream(dir / "out" / "bench.json"));
    EXPECT_TRUE(bench["partial"].get<bool>());
    for (const char* file : {"bench.csv", "bench.svg", "summary.md"}) EXPECT_TRUE(fs::exists(dir / "out" / file)) << file;
    EXPECT_NE(read_all(dir / "out" / "summary.md").find("Partial"), std::string::npos);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
