#include "setup/species_models.h"

#include <array>
#include <span>
#include <spdlog/spdlog.h>
#include <stdexcept>
#include <string>

#include "io/input_file.h"
#include "models/cache/billboard_cloud_io.h"
#include "models/cache/billboard_io.h"
#include "models/cache/lodf_io.h"
#include "models/gltf/gltf_import.h"
#include "models/generate/plant_library.h"
#include "models/cache/plant_model_io.h"
#include "models/bake/implicit_illumination.h"
#include "models/bake/point_line_bake.h"
#include "models/cache/point_line_io.h"
#include "models/cache/radiance_transfer_io.h"
#include "models/random.h"
#include "models/bake/transfer_resampling.h"

namespace sylva {
namespace {

constexpr crossed_billboard_settings k_billboard_settings{k_species_billboard_resolution, 4};

// A billboard bake with transfer pages depends on the transfer too (species_transfer_key).
std::uint64_t keyed_on_transfer(std::uint64_t key, const radiance_transfer* transfer, std::uint64_t transfer_key) {
    return transfer ? hash_string("transfer/" + std::to_string(transfer_key), key) : key;
}

// Loads through the cache; a damaged or outdated entry is reported, baked again and replaced
// (models/cache/bake_cache.h: read_or_bake). A failing bake is not retried.
template <class T, class Bake, class Read>
T load_cached(bake_cache* cache, std::string_view kind, std::uint64_t key, const Bake& bake, const Read& read) {
    return read_or_bake(cache, kind, key, bake, read);
}

std::string transfer_settings_text(const transfer_settings& s) {
    return std::to_string(k_radiance_transfer_format) + "/" + std::to_string(s.bands) + "/" +
           std::to_string(s.rays_per_receiver) + "/" + std::to_string(s.interreflection ? 1 : 0) +
           "/" + std::to_string(s.seed);
}

// An entry must hold one transfer per expected receiver set, each of the right size and bands;
// anything else (a hash collision, a hand-edited file) is a damaged entry and is re-baked.
std::vector<radiance_transfer> read_transfers(std::span<const std::byte> bytes,
                                              std::span<const std::size_t> receivers,
                                              std::uint32_t bands) {
    std::vector<radiance_transfer> transfers = deserialize_radiance_transfers(bytes);
    if (transfers.size() != receivers.size())
        throw std::runtime_error("bake cache entry: radiance transfer count does not match");
    for (std::size_t i = 0; i < transfers.size(); ++i)
        if (transfers[i].bands != bands || transfers[i].receiver_count() != receivers[i])
            throw std::runtime_error(
                "bake cache entry: radiance transfer does not match its receivers");
    return transfers;
}

}  // namespace

lighting_variant lighting_variant_of(const species_settings& species) {
    const std::string& name = species.lighting;
    if (name == "pre_lit") return lighting_variant::pre_lit;
    if (name == "sh") return lighting_variant::sh;
    if (name == "normal_mapped") return lighting_variant::normal_mapped;
    if (name == "implicit") return lighting_variant::implicit;
    if (name == "sh_implicit") return lighting_variant::sh_implicit;
    throw std::invalid_argument("species '" + species.name + "': unknown lighting '" + name +
                                "' (resolve \"scenario\" with resolved_species first)");
}

species_settings resolved_species(const scenario& s, const species_settings& species) {
    species_settings out = species;
    if (out.lighting == "scenario") out.lighting = s.lod.lighting;
    return out;
}

std::uint64_t species_seed_of(std::uint64_t scenario_seed, std::size_t index) {
    return hash_combine(scenario_seed, std::uint64_t(index), 0x5eed5eedULL);
}

std::uint64_t species_model_key(const species_settings& species, std::uint64_t seed) {
    std::uint64_t key = hash_string("plant_model");
    key = hash_string(std::to_string(k_plant_model_format) + "/" + std::to_string(k_species_texture_size), key);
    key = !species.model.empty() ? hash_file(species.model, hash_string("gltf", key))
                                 : hash_string(species.generator + "/" + std::to_string(seed), key);
    if (!bakes_implicit(species)) return key;
    // Luft 2007's normals are the model's own: every bake made from the model keys on them.
    const implicit_lighting_settings& i = species.implicit;
    const std::array<float, 10> fields{float(k_implicit_format),
                                       i.generator_fraction,
                                       i.rho_m,
                                       i.tau,
                                       i.ka_min,
                                       i.d_min,
                                       i.exponent,
                                       i.blend,
                                       float(ambient_source_named(i.ambient_from)),
                                       i.depth_min_m};
    return hash_bytes(std::as_bytes(std::span(fields)), hash_string("implicit", key));
}

implicit_settings implicit_settings_of(const species_settings& species, std::uint64_t seed) {
    const implicit_lighting_settings& i = species.implicit;
    implicit_settings out;
    out.generator_fraction = i.generator_fraction;
    out.seed = hash_combine(seed, 0x4c554654u);  // "LUFT"
    out.rho_m = i.rho_m;
    out.tau = i.tau;
    out.ka_min = i.ka_min;
    out.d_min = i.d_min;
    out.source = ambient_source_named(i.ambient_from);
    out.depth_min_m = i.depth_min_m;
    out.exponent = i.exponent;
    out.blend = i.blend;
    return out;
}

// A model file the importer cannot use is bad input (io/input_file.h: input_error), whatever
// its complaint, so a scenario naming it is refused like any other bad field.
plant_model import_species_model(const std::string& file) {
    try {
        return import_plant_model(file, k_species_texture_size);
    } catch (const input_error&) {
        throw;
    } catch (const std::runtime_error& e) {
        throw input_error(e.what());
    }
}

plant_model load_species_model(const species_settings& species, std::uint64_t seed, bake_cache* cache) {
    auto bake = [&] {
        plant_model model = species.model.empty()
                                ? generate_plant_model(species.generator, seed, k_species_texture_size)
                                : import_species_model(species.model);
        if (bakes_implicit(species)) {
            const implicit_report r = bake_implicit_illumination(model, implicit_settings_of(species, seed));
            spdlog::info(
                "{}: implicit illumination from {} generators, ρ {:.3g} m, τ {:.3g}, d_min {:.3g}, "
                "depth d_min {:.3g} m: {} surface vertices, mean k_a {:.2f}",
                species.name, r.generators, r.used.rho_m, r.used.tau, r.used.d_min,
                r.used.depth_min_m, r.surface_vertices, r.mean_ka);
        }
        return serialize_plant_model(model);
    };
    return load_cached<plant_model>(cache, "plants", species_model_key(species, seed), bake,
                                    [](std::span<const std::byte> bytes) { return deserialize_plant_model(bytes); });
}

std::uint64_t species_billboard_key(const species_settings& species, std::uint64_t seed) {
    std::uint64_t key = hash_string("crossed_billboard", species_model_key(species, seed));
    return hash_string(std::to_string(k_crossed_billboard_format) + "/" +
                           std::to_string(k_billboard_settings.resolution) + "/" +
                           std::to_string(k_billboard_settings.supersampling),
                       key);
}

crossed_billboard load_species_billboard(const species_settings& species, std::uint64_t seed,
                                         const plant_model& model, bake_cache* cache,
                                         const radiance_transfer* transfer,
                                         std::uint64_t transfer_key) {
    auto bake = [&] {
        return serialize_crossed_billboard(
            bake_crossed_billboard(model, k_billboard_settings, transfer));
    };
    const std::uint64_t key = keyed_on_transfer(species_billboard_key(species, seed), transfer, transfer_key);
    return load_cached<crossed_billboard>(
        cache, "billboards", key, bake,
        [](std::span<const std::byte> bytes) { return deserialize_crossed_billboard(bytes); });
}

std::uint64_t species_billboard_cloud_key(const species_settings& species, std::uint64_t seed) {
    const std::uint64_t key = hash_string("billboard_cloud", species_model_key(species, seed));
    return hash_string(std::to_string(k_billboard_cloud_format) + "/default", key);
}

billboard_cloud load_species_billboard_cloud(const species_settings& species, std::uint64_t seed,
                                             const plant_model& model, bake_cache* cache,
                                             const radiance_transfer* transfer,
                                             std::uint64_t transfer_key) {
    auto bake = [&] {
        return serialize_billboard_cloud(
            bake_billboard_cloud(model, default_billboard_cloud_settings(model), transfer));
    };
    const std::uint64_t key =
        keyed_on_transfer(species_billboard_cloud_key(species, seed), transfer, transfer_key);
    return load_cached<billboard_cloud>(
        cache, "billboard_clouds", key, bake,
        [](std::span<const std::byte> bytes) { return deserialize_billboard_cloud(bytes); });
}

lodf_model load_species_lodf(const species_settings& species, std::uint64_t seed, const plant_model& model,
                             bake_cache* cache) {
    const std::uint64_t key = hash_string("lodf " + std::to_string(k_lodf_format), species_model_key(species, seed));
    return load_cached<lodf_model>(
        cache, "lodf", key, [&] { return serialize_lodf_model(bake_lodf(model.lods[0], model.has_hierarchy)); },
        [](std::span<const std::byte> bytes) { return deserialize_lodf_model(bytes); });
}

std::uint64_t species_point_line_key(const species_settings& species, std::uint64_t seed) {
    const std::uint64_t key = hash_string("point_lines", species_model_key(species, seed));
    return hash_string(std::to_string(k_point_line_format) + "/" + std::to_string(seed) + "/" +
                           std::to_string(species.octree_depth),
                       key);
}

point_line_model load_species_point_lines(const species_settings& species, std::uint64_t seed,
                                          const plant_model& model, bake_cache* cache) {
    auto bake = [&] {
        point_line_settings settings;
        settings.seed = seed;
        settings.octree_depth = int(species.octree_depth);
        return serialize_point_line_model(bake_point_lines(model, settings));
    };
    return load_cached<point_line_model>(
        cache, "point_lines", species_point_line_key(species, seed), bake,
        [](std::span<const std::byte> bytes) { return deserialize_point_line_model(bytes); });
}

std::uint64_t species_transfer_key(const species_settings& species, std::uint64_t seed,
                                   const transfer_settings& settings) {
    const std::uint64_t key = hash_string("radiance_transfer", species_model_key(species, seed));
    return hash_string(transfer_settings_text(settings), key);
}

std::array<radiance_transfer, 3> load_species_transfer(const species_settings& species,
                                                       std::uint64_t seed, const plant_model& model,
                                                       const transfer_settings& settings,
                                                       bake_cache* cache) {
    auto bake = [&] {
        const transfer_occluders occluders(model.lods[0], model.leaf_texture, model.bark_texture);
        std::array<radiance_transfer, 3> levels;
        levels[0] = occluders.bake(model.lods[0].vertices, settings);
        // The coarser levels show the full plant's light (models/bake/transfer_resampling.h).
        for (std::size_t i = 1; i < 3; ++i)
            levels[i] = resample_transfer(model.lods[0], levels[0], model.lods[i].vertices);
        return serialize_radiance_transfers(levels);
    };
    const std::array<std::size_t, 3> receivers = {model.lods[0].vertices.size(),
                                                  model.lods[1].vertices.size(),
                                                  model.lods[2].vertices.size()};
    auto read = [&](std::span<const std::byte> bytes) {
        std::vector<radiance_transfer> t = read_transfers(bytes, receivers, settings.bands);
        return std::array<radiance_transfer, 3>{std::move(t[0]), std::move(t[1]), std::move(t[2])};
    };
    return load_cached<std::array<radiance_transfer, 3>>(
        cache, "radiance_transfer", species_transfer_key(species, seed, settings), bake, read);
}

std::uint64_t species_point_line_transfer_key(const species_settings& species, std::uint64_t seed,
                                              const transfer_settings& settings) {
    const std::uint64_t key =
        hash_string("point_line_transfer", species_point_line_key(species, seed));
    return hash_string(transfer_settings_text(settings), key);
}

point_line_transfer load_species_point_line_transfer(const species_settings& species,
                                                     std::uint64_t seed, const plant_model& model,
                                                     const point_line_model& point_lines,
                                                     const transfer_settings& settings,
                                                     bake_cache* cache) {
    auto bake = [&] {
        const transfer_occluders occluders(model.lods[0], model.leaf_texture, model.bark_texture);
        const std::array<radiance_transfer, 2> parts = {
            occluders.bake(point_lines.points, settings),
            occluders.bake(point_lines.lines, settings)};
        return serialize_radiance_transfers(parts);
    };
    const std::array<std::size_t, 2> receivers = {point_lines.points.size(),
                                                  point_lines.lines.size()};
    auto read = [&](std::span<const std::byte> bytes) {
        std::vector<radiance_transfer> t = read_transfers(bytes, receivers, settings.bands);
        return point_line_transfer{std::move(t[0]), std::move(t[1])};
    };
    return load_cached<point_line_transfer>(
        cache, "radiance_transfer", species_point_line_transfer_key(species, seed, settings), bake,
        read);
}

}  // namespace sylva
