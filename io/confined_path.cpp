#include "io/confined_path.h"

#include <algorithm>
#include <cctype>

#include "io/input_file.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// Symbolic links resolved for the part of the path that exists, the rest made lexically normal.
fs::path resolved(const fs::path& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::absolute(path, ec).lexically_normal() : p;
}

}  // namespace

std::string percent_decode(std::string_view uri) {
    std::string out;
    out.reserve(uri.size());
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '%' && i + 2 < uri.size() && hex_value(uri[i + 1]) >= 0 &&
            hex_value(uri[i + 2]) >= 0) {
            out += char(hex_value(uri[i + 1]) * 16 + hex_value(uri[i + 2]));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

bool has_uri_scheme(std::string_view uri) {
    const std::size_t colon = uri.find(':');
    if (colon == std::string_view::npos || colon == 0) return false;
    if (!std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
    return std::all_of(uri.begin(), uri.begin() + std::ptrdiff_t(colon), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
    });
}

bool is_inside(const fs::path& folder, const fs::path& path) {
    const fs::path base = resolved(folder);
    const fs::path target = resolved(path);
    const auto [base_end, target_it] =
        std::mismatch(base.begin(), base.end(), target.begin(), target.end());
    return base_end == base.end() && target_it != target.end();
}

fs::path resolve_inside(const fs::path& folder, std::string_view uri, const std::string& what) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, wrongly) on "'" + std::string(...).
    std::string quoted(1, '\'');
    quoted.append(uri).push_back('\'');
    if (has_uri_scheme(uri))
        throw input_error(what + ": URI " + quoted +
                          " has a scheme; only relative file names inside the model's folder "
                          "(and data: URIs) are read");
    const std::string decoded = percent_decode(uri);
    if (decoded.empty()) throw input_error(what + ": empty URI");
    if (decoded.find('\0') != std::string::npos)
        throw input_error(what + ": URI " + quoted + " holds a NUL character");
    const fs::path relative(decoded);
    if (relative.is_absolute() || relative.has_root_name())
        throw input_error(what + ": URI " + quoted +
                          " is an absolute path; only files inside the model's folder are read");
    const fs::path target = folder / relative;
    if (!is_inside(folder, target))
        throw input_error(what + ": URI " + quoted +
                          " leads outside the model's folder; only files inside it are read");
    return target;
}

}  // namespace sylva
