#include "scenarios/json_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>

#include "io/input_file.h"

namespace sylva {
namespace {

constexpr std::size_t k_max_value_chars = 60;

bool is_integral_and_small(double value) {
    return std::abs(value) < 1e15 && std::trunc(value) == value;
}

std::string range_text(number_range range) {
    return format_number(range.min) + " to " + format_number(range.max);
}

std::string range_text(integer_range range) {
    return std::to_string(range.min) + " to " + std::to_string(range.max);
}

// Cuts at a character boundary: never inside a UTF-8 sequence.
std::string shorten(std::string text) {
    if (text.size() <= k_max_value_chars) return text;
    std::size_t cut = k_max_value_chars - 3;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
    text.resize(cut);
    return text + "...";
}

}  // namespace

std::optional<json_node> json_node::find(std::string_view key) const {
    const auto it = m_value->find(key);
    if (it == m_value->end()) return std::nullopt;
    return json_node(*it, m_path + "/" + pointer_token(key), *m_file);
}

json_node json_node::at(std::size_t index) const {
    return json_node((*m_value)[index], m_path + "/" + std::to_string(index), *m_file);
}

void json_node::fail(std::string problem) const {
    throw scenario_error(*m_file, m_path, describe_value(*m_value), std::move(problem));
}

void json_node::fail_missing(std::string_view key) const {
    throw scenario_error(*m_file, m_path + "/" + pointer_token(key), "nothing",
                         "missing required item \"" + std::string(key) + "\"");
}

std::string pointer_token(std::string_view key) {
    std::string token;
    for (const char c : key) {
        if (c == '~') {
            token += "~0";
        } else if (c == '/') {
            token += "~1";
        } else {
            token += c;
        }
    }
    return token;
}

namespace {

// Appends the compact dump of `value` to `out` until `out` is longer than `limit`: an array of a
// million items or a value nested a million deep costs what the message shows, and never
// recurses deeper than the text it can show (each level adds at least one character).
void describe_into(const nlohmann::json& value, std::string& out, std::size_t limit) {
    if (out.size() > limit) return;
    if (!value.is_structured()) {
        out += value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
        return;
    }
    const bool object = value.is_object();
    out += object ? '{' : '[';
    bool first = true;
    for (auto it = value.begin(); it != value.end() && out.size() <= limit; ++it) {
        if (!first) out += ',';
        first = false;
        if (object) out += nlohmann::json(it.key()).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + ":";
        describe_into(*it, out, limit);
    }
    out += object ? '}' : ']';
}

}  // namespace

std::string describe_value(const nlohmann::json& value) {
    std::string text;
    describe_into(value, text, k_max_value_chars);
    return shorten(std::move(text));
}

std::string join(std::span<const std::string_view> words) {
    std::string text;
    for (const auto word : words) {
        if (!text.empty()) text += ", ";
        text += word;
    }
    return text;
}

std::string format_number(double value) {
    if (is_integral_and_small(value)) return std::to_string(static_cast<std::int64_t>(value));
    return nlohmann::json(value).dump();  // shortest text that reads back the same double
}

std::string format_float(float value) {
    if (is_integral_and_small(value)) return format_number(value);
    for (int digits = 1; digits <= std::numeric_limits<float>::max_digits10; ++digits) {
        std::ostringstream text;
        text.precision(digits);
        text << value;
        if (std::strtof(text.str().c_str(), nullptr) == value) return text.str();
    }
    return format_number(value);
}

std::string line_and_column(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    const std::string_view before = text.substr(0, offset);
    const auto line = 1 + std::count(before.begin(), before.end(), '\n');
    const std::size_t line_start = before.rfind('\n');
    const std::size_t column =
        line_start == std::string_view::npos ? offset + 1 : offset - line_start;
    return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

void expect_object(const json_node& node) {
    if (!node.value().is_object()) node.fail("expected an object");
}

void expect_known_keys(const json_node& node, std::span<const std::string_view> known) {
    for (const auto& [key, value] : node.value().items()) {
        if (std::find(known.begin(), known.end(), key) == known.end())
            node.find(key)->fail("unknown field; expected one of: " + join(known));
    }
}

std::size_t expect_array(const json_node& node, std::size_t min_items, std::size_t max_items) {
    const auto& v = node.value();
    if (!v.is_array()) node.fail("expected an array");
    if (v.size() < min_items)
        node.fail("expected at least " + std::to_string(min_items) +
                  (min_items == 1 ? " item" : " items"));
    if (v.size() > max_items) node.fail("expected at most " + std::to_string(max_items) + " items");
    return v.size();
}

double read_number(const json_node& node, number_range range) {
    const auto& v = node.value();
    if (!v.is_number()) node.fail("expected a number");
    const double value = v.get<double>();
    if (!(value >= range.min && value <= range.max))
        node.fail("out of range; expected a number from " + range_text(range));
    return value;
}

std::uint64_t read_integer(const json_node& node, integer_range range) {
    const auto& v = node.value();
    const std::string expected = "expected an integer from " + range_text(range);
    if (!v.is_number_integer()) node.fail(expected);
    if (v.is_number_unsigned()) {
        const auto value = v.get<std::uint64_t>();
        if (value >= range.min && value <= range.max) return value;
    } else {
        const auto value = v.get<std::int64_t>();
        if (value >= 0 && static_cast<std::uint64_t>(value) >= range.min &&
            static_cast<std::uint64_t>(value) <= range.max)
            return static_cast<std::uint64_t>(value);
    }
    node.fail("out of range; " + expected);
}

bool read_bool(const json_node& node) {
    if (!node.value().is_boolean()) node.fail("expected true or false");
    return node.value().get<bool>();
}

std::string read_string(const json_node& node) {
    if (!node.value().is_string()) node.fail("expected a string");
    auto text = node.value().get<std::string>();
    if (text.empty()) node.fail("expected a non-empty string");
    return text;
}

std::string read_choice(const json_node& node, std::span<const std::string_view> choices) {
    if (!node.value().is_string()) node.fail("expected one of: " + join(choices));
    auto text = node.value().get<std::string>();
    if (std::find(choices.begin(), choices.end(), text) == choices.end())
        node.fail("unknown value; expected one of: " + join(choices));
    return text;
}

glm::dvec3 read_dvec3(const json_node& node, number_range range) {
    const auto& v = node.value();
    if (!v.is_array() || v.size() != 3 ||
        !std::all_of(v.begin(), v.end(), [](const auto& e) { return e.is_number(); }))
        node.fail("expected an array of 3 numbers");
    return {read_number(node.at(0), range), read_number(node.at(1), range),
            read_number(node.at(2), range)};
}

std::string read_file_path(const json_node& node) {
    namespace fs = std::filesystem;
    constexpr std::string_view k_embedded = "embedded:";
    std::string_view source = node.file();
    if (source.starts_with(k_embedded)) source.remove_prefix(k_embedded.size());
    fs::path path(read_string(node));
    if (path.is_relative()) path = fs::path(source).parent_path() / path;
    std::error_code ec;
    path = fs::absolute(path, ec).lexically_normal();
    if (ec || !fs::exists(path, ec)) node.fail("file not found: " + path.string());
    // Readable, a regular file (not a directory, device or FIFO) and of a size Sylva reads: an
    // unreadable file is bad input found now, before a command writes anything.
    try {
        check_input_file(path, k_max_model_bytes);
    } catch (const input_error& e) {
        node.fail(e.what());
    }
    return path.string();
}

}  // namespace sylva
