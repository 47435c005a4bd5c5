#include "app/model_argument.h"

#include <filesystem>
#include <stdexcept>

#include "models/generate/plant_library.h"
#include "models/gltf/gltf_import.h"

namespace sylva {

bool is_gltf_path(const std::string& model) {
    const std::string ext = std::filesystem::path(model).extension().string();
    return ext == ".gltf" || ext == ".glb";
}

std::string plant_preset_list() {
    std::string names;
    for (const std::string_view name : k_plant_presets) names += (names.empty() ? "" : ", ") + std::string(name);
    return names;
}

void check_plant_argument(const std::string& model) {
    if (is_gltf_path(model)) {
        if (!std::filesystem::exists(model)) throw std::invalid_argument(model + ": file not found");
        return;
    }
    for (const std::string_view name : k_plant_presets)
        if (name == model) return;
    throw std::invalid_argument("'" + model + "' is neither a preset (" + plant_preset_list() + ") nor a .gltf/.glb file");
}

plant_model load_plant_argument(const std::string& model, std::uint64_t seed, std::uint32_t texture_size) {
    check_plant_argument(model);
    return is_gltf_path(model) ? import_plant_model(model, texture_size) : generate_plant_model(model, seed, texture_size);
}

std::string plant_argument_name(const std::string& model) {
    return is_gltf_path(model) ? std::filesystem::path(model).stem().string() : model;
}

}  // namespace sylva
