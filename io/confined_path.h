#pragma once
// A model's external files (glTF buffer and image URIs) may only be files inside the model's
// own folder: a model from elsewhere must not make Sylva read /etc/passwd, follow a symbolic
// link out of its folder, or tell what lies outside it.
#include <filesystem>
#include <string>
#include <string_view>

namespace sylva {

// A relative URI reference (RFC 3986) with its %XX escapes decoded; a '%' not followed by two
// hex digits is kept as it is (as tinygltf does).
std::string percent_decode(std::string_view uri);

// Whether `uri` starts with a scheme ("file:", "http:", "data:"): letter, then letters, digits,
// '+', '-' or '.', then ':'.
bool has_uri_scheme(std::string_view uri);

// The file `uri` (relative, not yet decoded) names inside `folder`. Throws input_error naming
// `what` and the URI when it has a scheme, is absolute, leads out of the folder ("../"), or
// resolves (through symbolic links) to a place outside it. The message is the same whether or
// not a file exists there, so it tells nothing about other files.
std::filesystem::path resolve_inside(const std::filesystem::path& folder, std::string_view uri,
                                     const std::string& what);

// Whether `path` resolves (symbolic links followed, as far as they exist) inside `folder`.
bool is_inside(const std::filesystem::path& folder, const std::filesystem::path& path);

}  // namespace sylva
