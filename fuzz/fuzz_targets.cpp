#include "fuzz/fuzz_targets.h"

#include <spdlog/spdlog.h>

#include <stdexcept>
#include <string>
#include <string_view>

#include "models/gltf/gltf_container.h"
#include "models/gltf/gltf_import.h"
#include "scenarios/scenario_loader.h"

namespace sylva::fuzz {

// Small textures keep each run short; the importer's paths do not depend on the size.
constexpr std::uint32_t k_fuzz_texture_size = 16;

void scenario_loader(const std::uint8_t* data, std::size_t size) {
    try {
        load_scenario_text(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
    } catch (const scenario_error&) {
    }
}

void gltf_import(const std::uint8_t* data, std::size_t size, const std::filesystem::path& folder,
                 bool whole_plant) {
    spdlog::set_level(spdlog::level::off);  // warnings about the input are expected by the thousand
    gltf_source source;
    source.binary = size >= 4 && std::string_view(reinterpret_cast<const char*>(data), 4) == "glTF";
    source.name = source.binary ? "fuzz.glb" : "fuzz.gltf";
    source.folder = folder;
    source.bytes.assign(reinterpret_cast<const char*>(data), size);
    try {
        import_gltf_source(source, k_fuzz_texture_size,
                           whole_plant ? gltf_import_stage::plant : gltf_import_stage::read);
    } catch (const std::runtime_error&) {
    }
}

}  // namespace sylva::fuzz
