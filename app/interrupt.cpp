#include "app/interrupt.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>

namespace sylva {
namespace {

// Written by the handler, read by the frame loop: a lock-free atomic is async-signal-safe.
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction g_previous_int {};
struct sigaction g_previous_term {};

void on_interrupt(int signal) {
    int expected = 0;
    if (!g_signal.compare_exchange_strong(expected, signal)) {
        // The second one: the default action now (end the process with this signal).
        ::signal(signal, SIG_DFL);
        ::raise(signal);
        return;
    }
    // write(2) is async-signal-safe; spdlog and printf are not.
    static const char message[] =
        "\n[sylva] interrupted: finishing the current frame and writing what was done "
        "(interrupt again to stop at once)\n";
    [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, message, sizeof(message) - 1);
}

}  // namespace

interrupt_guard::interrupt_guard() {
    g_signal = 0;
    struct sigaction action {};
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;  // file and GL calls resume; the loop checks between frames
    ::sigaction(SIGINT, &action, &g_previous_int);
    ::sigaction(SIGTERM, &action, &g_previous_term);
}

interrupt_guard::~interrupt_guard() {
    ::sigaction(SIGINT, &g_previous_int, nullptr);
    ::sigaction(SIGTERM, &g_previous_term, nullptr);
}

bool interrupt_requested() { return g_signal.load(std::memory_order_relaxed) != 0; }

std::optional<int> interrupt_signal() {
    const int s = g_signal.load();
    return s ? std::optional<int>(s) : std::nullopt;
}

std::string interrupt_signal_name() {
    const int s = g_signal.load();
    if (s == SIGINT) return "SIGINT";
    if (s == SIGTERM) return "SIGTERM";
    return s ? "signal " + std::to_string(s) : "";
}

int interrupt_exit_code() { return 128 + g_signal.load(); }

}  // namespace sylva
