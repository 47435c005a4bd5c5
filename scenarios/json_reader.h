#pragma once
// Strict, located reading of JSON values. A json_node is a value plus where it sits (file and
// JSON Pointer), so every check can name the exact place that failed; a field_table binds a
// struct's fields to object keys once, and that one table rejects unknown keys, reads, and
// writes the struct back. Failures throw scenario_error (the first problem found wins).
#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scenarios/scenario_loader.h"

namespace sylva {

class json_node {
public:
    json_node(const nlohmann::json& value, std::string path, const std::string& file)
        : m_value(&value), m_path(std::move(path)), m_file(&file) {}

    const nlohmann::json& value() const { return *m_value; }
    const std::string& path() const { return m_path; }
    const std::string& file() const { return *m_file; }  // the document's name (source)

    // The member `key` of this object, if present (this must be an object).
    std::optional<json_node> find(std::string_view key) const;
    json_node at(std::size_t index) const;  // element of this array

    [[noreturn]] void fail(std::string problem) const;
    // Reports that the member `key` of this object is missing.
    [[noreturn]] void fail_missing(std::string_view key) const;

private:
    const nlohmann::json* m_value;
    std::string m_path;
    const std::string* m_file;
};

struct number_range {
    double min;
    double max;
};

struct integer_range {
    std::uint64_t min;
    std::uint64_t max;
};

// Escapes a key for a JSON Pointer (RFC 6901: "~" -> "~0", "/" -> "~1").
std::string pointer_token(std::string_view key);
// The value dumped compactly, cut to about 60 characters.
std::string describe_value(const nlohmann::json& value);
// "a, b, c"
std::string join(std::span<const std::string_view> words);
// A limit as people write it: 16384, 0.001, 1e+06.
std::string format_number(double value);
// The shortest text that reads back as the same float: 1.2f gives "1.2", not 1.2000000476837158.
std::string format_float(float value);
// "line 3, column 14" for the byte at `offset` (0-based) of `text`.
std::string line_and_column(std::string_view text, std::size_t offset);

void expect_object(const json_node& node);
// Every key of the object must be one of `known`.
void expect_known_keys(const json_node& node, std::span<const std::string_view> known);
// An array of min_items .. max_items elements; returns its size.
std::size_t expect_array(const json_node& node, std::size_t min_items, std::size_t max_items);

double read_number(const json_node& node, number_range range);
std::uint64_t read_integer(const json_node& node, integer_range range);
bool read_bool(const json_node& node);
std::string read_string(const json_node& node);  // non-empty
std::string read_choice(const json_node& node, std::span<const std::string_view> choices);
glm::dvec3 read_dvec3(const json_node& node, number_range range);  // [x, y, z]
// A non-empty string naming an existing regular file, relative to the folder of the document's
// file (node.file(); an "embedded:" prefix is dropped) unless absolute; returned absolute and
// lexically normal. A missing file fails with "file not found: <absolute path>"; one that is not
// a readable regular file of at most k_max_model_bytes (io/input_file.h) fails naming why.
std::string read_file_path(const json_node& node);

// Binds the fields of S to object keys. Fields are read in table order after the unknown-key
// check, so the first problem reported is always the same for the same document.
template <class S>
class field_table {
public:
    using reader = std::function<void(const json_node&, S&)>;
    using writer = std::function<void(const S&, nlohmann::json&)>;

    field_table& add(std::string_view key, reader read, writer write) {
        m_fields.push_back({key, false, std::move(read), std::move(write)});
        m_keys.push_back(key);
        return *this;
    }
    // Marks the field added last as required.
    field_table& required() {
        m_fields.back().required = true;
        return *this;
    }
    // A check across fields, run once all of them are read (e.g. scale_min <= scale_max).
    field_table& check(std::function<void(const json_node&, const S&)> check_fields) {
        m_checks.push_back(std::move(check_fields));
        return *this;
    }

    template <class Access>
    field_table& number(std::string_view key, Access access, number_range range) {
        return add(
            key,
            [=](const json_node& n, S& s) {
                auto& target = std::invoke(access, s);
                target = static_cast<std::remove_cvref_t<decltype(target)>>(read_number(n, range));
            },
            [=](const S& s, nlohmann::json& j) { j[std::string(key)] = std::invoke(access, s); });
    }
    template <class Access>
    field_table& integer(std::string_view key, Access access, integer_range range) {
        return add(
            key,
            [=](const json_node& n, S& s) {
                auto& target = std::invoke(access, s);
                target = static_cast<std::remove_cvref_t<decltype(target)>>(read_integer(n, range));
            },
            [=](const S& s, nlohmann::json& j) { j[std::string(key)] = std::invoke(access, s); });
    }
    template <class Access>
    field_table& boolean(std::string_view key, Access access) {
        return add(
            key, [=](const json_node& n, S& s) { std::invoke(access, s) = read_bool(n); },
            [=](const S& s, nlohmann::json& j) { j[std::string(key)] = std::invoke(access, s); });
    }
    template <class Access>
    field_table& text(std::string_view key, Access access) {
        return add(
            key, [=](const json_node& n, S& s) { std::invoke(access, s) = read_string(n); },
            [=](const S& s, nlohmann::json& j) { j[std::string(key)] = std::invoke(access, s); });
    }
    template <class Access>
    field_table& choice(std::string_view key, Access access,
                        std::span<const std::string_view> choices) {
        return add(
            key,
            [=](const json_node& n, S& s) { std::invoke(access, s) = read_choice(n, choices); },
            [=](const S& s, nlohmann::json& j) { j[std::string(key)] = std::invoke(access, s); });
    }
    // An optional file path (read_file_path), stored absolute; "" (absent) is not written.
    template <class Access>
    field_table& file_path(std::string_view key, Access access) {
        return add(
            key, [=](const json_node& n, S& s) { std::invoke(access, s) = read_file_path(n); },
            [=](const S& s, nlohmann::json& j) {
                const std::string& path = std::invoke(access, s);
                if (!path.empty()) j[std::string(key)] = path;
            });
    }
    // glm::vec3 or glm::dvec3 written as [x, y, z].
    template <class Access>
    field_table& vec3(std::string_view key, Access access, number_range range) {
        return add(
            key,
            [=](const json_node& n, S& s) {
                auto& target = std::invoke(access, s);
                target = std::remove_cvref_t<decltype(target)>(read_dvec3(n, range));
            },
            [=](const S& s, nlohmann::json& j) {
                const auto& v = std::invoke(access, s);
                j[std::string(key)] = {v.x, v.y, v.z};
            });
    }
    // A nested object read with its own table.
    template <class T, class Access>
    field_table& object(std::string_view key, Access access, const field_table<T>& table) {
        return add(
            key, [=, &table](const json_node& n, S& s) { table.read(n, std::invoke(access, s)); },
            [=, &table](const S& s, nlohmann::json& j) {
                j[std::string(key)] = table.write(std::invoke(access, s));
            });
    }
    // An array of at least min_items objects read with `table`. Each item starts as make(s)
    // (its defaults may depend on fields read earlier); check_items then sees the whole array.
    template <class T>
    struct array_options {
        std::size_t min_items = 1;
        std::function<T(const S&)> make = [](const S&) { return T{}; };
        std::function<void(const json_node&, const S&)> check_items = {};
    };
    template <class T, class Access>
    field_table& array(std::string_view key, Access access, const field_table<T>& table,
                       array_options<T> options = {}) {
        return add(
            key,
            [=, &table](const json_node& n, S& s) {
                const std::size_t size = expect_array(n, options.min_items, SIZE_MAX);
                auto& items = std::invoke(access, s);
                items.clear();
                for (std::size_t i = 0; i < size; ++i) {
                    T item = options.make(s);
                    table.read(n.at(i), item);
                    items.push_back(std::move(item));
                }
                if (options.check_items) options.check_items(n, s);
            },
            [=, &table](const S& s, nlohmann::json& j) {
                nlohmann::json items = nlohmann::json::array();
                for (const T& item : std::invoke(access, s)) items.push_back(table.write(item));
                j[std::string(key)] = std::move(items);
            });
    }

    void read(const json_node& node, S& out) const {
        expect_object(node);
        expect_known_keys(node, m_keys);
        for (const auto& f : m_fields) {
            if (const auto child = node.find(f.key)) {
                f.read(*child, out);
            } else if (f.required) {
                node.fail_missing(f.key);
            }
        }
        for (const auto& check_fields : m_checks) check_fields(node, out);
    }

    nlohmann::json write(const S& in) const {
        nlohmann::json j = nlohmann::json::object();
        for (const auto& f : m_fields) f.write(in, j);
        return j;
    }

private:
    struct field {
        std::string_view key;
        bool required;
        reader read;
        writer write;
    };
    std::vector<field> m_fields;
    std::vector<std::string_view> m_keys;
    std::vector<std::function<void(const json_node&, const S&)>> m_checks;
};

}  // namespace sylva
