#pragma once
// The MODEL argument the model commands share (export-cloud, export-lodf, inspect): a species
// preset by name (models/generate/plant_library.h) or a .gltf/.glb file.
#include <cstdint>
#include <string>

#include "models/plant_model.h"

namespace sylva {

bool is_gltf_path(const std::string& model);
// "broadleaf, broadleaf_hd, ...": for messages.
std::string plant_preset_list();
// Throws std::invalid_argument naming `model` when it is neither a preset nor an existing
// .gltf/.glb file; builds nothing.
void check_plant_argument(const std::string& model);
// Generates the preset or imports the file. Throws std::invalid_argument naming the argument
// when it is neither a preset nor an existing file, and passes the importer's complaint on
// (std::runtime_error: the file is bad input too).
plant_model load_plant_argument(const std::string& model, std::uint64_t seed, std::uint32_t texture_size);
// The name a report and an export give the model: the preset, or the file's stem.
std::string plant_argument_name(const std::string& model);

}  // namespace sylva
