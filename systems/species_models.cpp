#include "systems/species_models.h"

#include "models/gltf_import.h"
#include "models/plant_library.h"
#include "models/plant_model_io.h"
#include "models/random.h"

namespace sylva {

std::uint64_t species_seed_of(std::uint64_t scenario_seed, std::size_t index) {
    return hash_combine(scenario_seed, std::uint64_t(index), 0x5eed5eedULL);
}

std::uint64_t species_model_key(const species_settings& species, std::uint64_t seed) {
    std::uint64_t key = hash_string("plant_model");
    key = hash_string(std::to_string(k_plant_model_format) + "/" + std::to_string(k_species_texture_size), key);
    if (!species.model.empty()) return hash_file(species.model, hash_string("gltf", key));
    return hash_string(species.generator + "/" + std::to_string(seed), key);
}

plant_model load_species_model(const species_settings& species, std::uint64_t seed, bake_cache* cache) {
    auto bake = [&] {
        plant_model model = species.model.empty()
                                ? generate_plant_model(species.generator, seed, k_species_texture_size)
                                : import_plant_model(species.model, k_species_texture_size);
        return serialize_plant_model(model);
    };
    if (!cache) return deserialize_plant_model(bake());
    const std::uint64_t key = species_model_key(species, seed);
    try {
        return deserialize_plant_model(cache->get_or_bake("plants", key, bake));
    } catch (const std::runtime_error&) {
        // A damaged or outdated entry: bake again and replace it.
        std::vector<std::byte> bytes = bake();
        cache->store("plants", key, bytes);
        return deserialize_plant_model(bytes);
    }
}

}  // namespace sylva
