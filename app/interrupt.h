#pragma once
// Ctrl-C (SIGINT) and SIGTERM during a long play or bench: the first one asks the loop to stop
// after the current frame, so what was done is kept (complete frames, metrics.json or the bench
// files marked partial) and the process exits 130 or 143 as shells expect (128 + signal). A
// second one ends the process at once, for a run that does not reach a frame boundary.
#include <optional>
#include <string>

namespace sylva {

// Installs the handlers for its lifetime and restores the previous ones after. One at a time.
class interrupt_guard {
public:
    interrupt_guard();
    ~interrupt_guard();
    interrupt_guard(const interrupt_guard&) = delete;
    interrupt_guard& operator=(const interrupt_guard&) = delete;
};

// Whether SIGINT or SIGTERM arrived since the guard was installed (lock-free, any thread).
bool interrupt_requested();
// The signal that asked to stop, if any: its name ("SIGINT") and the exit code (130, 143).
std::optional<int> interrupt_signal();
std::string interrupt_signal_name();
int interrupt_exit_code();

}  // namespace sylva
