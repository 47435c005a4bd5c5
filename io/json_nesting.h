#pragma once
// A bound on how deeply a JSON text nests, checked on the raw text before any parser sees it.
// Parsers and printers that recurse (tinygltf's value parser, a JSON dump) overflow the stack on
// a million '[': the check turns that into an error with a position.
#include <cstddef>
#include <optional>
#include <string_view>

namespace sylva {

// The offset of the first '[' or '{' that opens a level deeper than max_depth (the document's
// own object or array is level 1), outside strings; nothing when the text stays within it.
// Linear, no allocation; malformed text is left to the parser.
std::optional<std::size_t> find_nesting_beyond(std::string_view json, std::size_t max_depth);

}  // namespace sylva
