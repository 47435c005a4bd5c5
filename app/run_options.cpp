#include "app/run_options.h"

#include <array>
#include <string_view>

namespace sylva {
namespace {

std::vector<std::string>& remembered() {
    static std::vector<std::string> options;
    return options;
}

constexpr std::array<std::string_view, 4> k_shard_own = {"--frame-range", "--shard", "--out", "--threads"};

}  // namespace

void remember_run_options(int argc, const char* const* argv) {
    std::vector<std::string>& out = remembered();
    out.clear();
    for (int i = 1; i < argc; ++i) {
        const std::string_view word = argv[i];
        bool own = false;
        for (const std::string_view o : k_shard_own) {
            if (word == o) {
                own = true;
                ++i;  // and its value
                break;
            }
            if (word.size() > o.size() && word.substr(0, o.size()) == o && word[o.size()] == '=') {
                own = true;
                break;
            }
        }
        if (!own) out.emplace_back(word);
    }
}

const std::vector<std::string>& run_options() { return remembered(); }

std::string run_options_text(const std::vector<std::string>& options) {
    std::string text;
    for (const std::string& o : options) {
        if (!text.empty()) text += ' ';
        text += o;
    }
    return text.empty() ? std::string("(none)") : text;
}

}  // namespace sylva
