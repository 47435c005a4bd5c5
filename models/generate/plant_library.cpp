#include "models/generate/plant_library.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "models/generate/fern_generator.h"
#include "models/generate/flower_generator.h"
#include "models/generate/grass_generator.h"
#include "models/generate/plant_textures.h"
#include "models/generate/textures.h"
#include "models/generate/tree_generator.h"

namespace sylva {
namespace {

constexpr std::array<tree_detail, 3> k_details = {tree_detail::full, tree_detail::reduced, tree_detail::far};

[[noreturn]] void throw_unknown(std::string_view preset) {
    std::string valid;
    for (const std::string_view name : k_plant_presets) valid += (valid.empty() ? "" : ", ") + std::string(name);
    throw std::invalid_argument("unknown plant preset \"" + std::string(preset) + "\" (valid: " + valid + ")");
}

bool is_tree_preset(std::string_view preset) {
    return std::find(k_tree_preset_names.begin(), k_tree_preset_names.end(), preset) != k_tree_preset_names.end();
}

// The texture generator a tree preset borrows: the HD broadleaf and the shrub wear the
// broadleaf's leaf sprays and bark.
std::string_view tree_texture_generator(std::string_view preset) {
    return preset == "conifer" ? "conifer" : "broadleaf";
}

}  // namespace

plant_model generate_plant_model(std::string_view preset, std::uint64_t seed, std::uint32_t texture_size) {
    if (std::find(k_plant_presets.begin(), k_plant_presets.end(), preset) == k_plant_presets.end())
        throw_unknown(preset);
    plant_model model;
    model.name = std::string(preset);
    model.has_hierarchy = true;
    model.source_unit_scale = 1.0f;
    if (is_tree_preset(preset)) {
        const tree_params params = tree_preset(preset);
        for (std::size_t i = 0; i < k_details.size(); ++i) model.lods[i] = generate_tree(params, seed, k_details[i]);
        model.leaf_texture = generate_leaf_texture(tree_texture_generator(preset), texture_size);
        model.bark_texture = generate_bark_texture(tree_texture_generator(preset), texture_size);
        return model;
    }
    mesh_data (*generate)(std::uint64_t, tree_detail) = nullptr;
    if (preset == "grass") {
        generate = generate_grass;
        model.leaf_texture = generate_grass_texture(texture_size);
    } else if (preset == "flower") {
        generate = generate_flower;
        model.leaf_texture = generate_flower_atlas(texture_size);
    } else {
        generate = generate_fern;
        model.leaf_texture = generate_fern_texture(texture_size);
    }
    // Herbaceous stems; grass has none, but every plant_model carries a bark texture.
    model.bark_texture = generate_stem_texture(texture_size);
    for (std::size_t i = 0; i < k_details.size(); ++i) model.lods[i] = generate(seed, k_details[i]);
    return model;
}

}  // namespace sylva
