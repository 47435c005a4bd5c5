#include "io/json_nesting.h"

namespace sylva {

// Hand-written: a dozen lines that only track strings and brackets. nlohmann's SAX parser could
// count depth too, but it would run the whole parse (and allocate every string) a second time.
std::optional<std::size_t> find_nesting_beyond(std::string_view json, std::size_t max_depth) {
    std::size_t depth = 0;
    bool in_string = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (in_string) {
            if (c == '\\') {
                ++i;  // the escaped character cannot end the string
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > max_depth) return i;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return std::nullopt;
}

}  // namespace sylva
