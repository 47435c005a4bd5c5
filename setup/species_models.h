#pragma once
// A scenario species as a plant_model: generated from its preset or imported from its glTF
// file, through the bake cache (keyed by everything that determines the result).
#include <array>
#include <cstdint>

#include "models/cache/bake_cache.h"
#include "models/bake/billboard_cloud.h"
#include "models/bake/crossed_billboard.h"
#include "models/bake/implicit_illumination.h"
#include "models/bake/lodf_bake.h"
#include "models/plant_model.h"
#include "models/bake/point_line_model.h"
#include "models/bake/radiance_transfer.h"
#include "resources/scene_assets.h"
#include "scenarios/scenario.h"

namespace sylva {

constexpr std::uint32_t k_species_texture_size = 256;
// Each crossed-billboard quad's image is this many texels square (the atlas twice as wide).
constexpr std::uint32_t k_species_billboard_resolution = 256;

// The seed species `index` of a scenario is generated with (spawning and baking agree).
std::uint64_t species_seed_of(std::uint64_t scenario_seed, std::size_t index);

// The cache key of a species' model: preset name and seed, or the glTF file's contents, plus
// the texture size and the plant-model format version.
std::uint64_t species_model_key(const species_settings& species, std::uint64_t seed);

// Bumped when the implicit illumination bake (models/bake/implicit_illumination.h) changes.
constexpr std::uint32_t k_implicit_format =
    3;  // 3: Eq. 4 of the depth below the surface by default

// `species` with its lighting resolved: "scenario" becomes the scenario's lod.lighting. Every
// load_species_* below reads `lighting` ("implicit" bakes Luft 2007 into the model), so callers
// pass resolved settings.
species_settings resolved_species(const scenario& s, const species_settings& species);

// The lighting variant a resolved species is drawn with (its `lighting` name).
lighting_variant lighting_variant_of(const species_settings& species);

// True when the species' lighting bakes Luft 2007 into its model: "implicit", and "sh_implicit"
// (SH transfer baked from the realigned normals). Unresolved ("scenario"): no.
inline bool bakes_implicit(const species_settings& species) {
    return species.lighting != "scenario" && uses_implicit_normals(lighting_variant_of(species));
}

// The bake's settings for a species with lighting "implicit" (its seed derived from `seed`).
implicit_settings implicit_settings_of(const species_settings& species, std::uint64_t seed);

// `cache` may be null (no caching). Throws with the file and part on a broken glTF. With
// lighting "implicit" the model's normals carry Luft 2007's illumination.
plant_model load_species_model(const species_settings& species, std::uint64_t seed, bake_cache* cache);

// The cache key of a species' crossed billboard: its model's key, the billboard format version,
// the resolution and the supersampling.
std::uint64_t species_billboard_key(const species_settings& species, std::uint64_t seed);

// The crossed billboard of `model` (the species' model as load_species_model returns it,
// unscaled), through the cache ("billboards") when `cache` is not null.
// With `transfer` (lods[0]'s, Behrendt 2005 §4) its transfer pages are baked too, and the cache
// entry is keyed on `transfer_key` (species_transfer_key) as well.
crossed_billboard load_species_billboard(const species_settings& species, std::uint64_t seed,
                                         const plant_model& model, bake_cache* cache,
                                         const radiance_transfer* transfer = nullptr,
                                         std::uint64_t transfer_key = 0);

// The cache key of a species' billboard cloud: its model's key and the cloud's format version
// (the settings are default_billboard_cloud_settings of that model, fixed by the two).
std::uint64_t species_billboard_cloud_key(const species_settings& species, std::uint64_t seed);

// The billboard cloud (Behrendt 2005 §2) of `model` (unscaled), baked with
// default_billboard_cloud_settings, through the cache ("billboard_clouds") when `cache` is not
// null. With `transfer` (lods[0]'s, Behrendt 2005 §4) its transfer pages are baked too, and the
// cache entry is keyed on `transfer_key` (species_transfer_key) as well.
billboard_cloud load_species_billboard_cloud(const species_settings& species, std::uint64_t seed,
                                             const plant_model& model, bake_cache* cache,
                                             const radiance_transfer* transfer = nullptr,
                                             std::uint64_t transfer_key = 0);

// The cache key of a species' point/line representation: its model's key and the bake's format.
std::uint64_t species_point_line_key(const species_settings& species, std::uint64_t seed);

// The species' LoDF foliage (Rebollo 2006, models/bake/lodf_bake.h) over its full mesh, through
// `cache` (kind "lodf", keyed by the model and k_lodf_format).
lodf_model load_species_lodf(const species_settings& species, std::uint64_t seed, const plant_model& model,
                             bake_cache* cache);

// The point/line representation (Deussen 2002 §4) of `model` (unscaled), through the cache
// ("point_lines") when `cache` is not null.
point_line_model load_species_point_lines(const species_settings& species, std::uint64_t seed,
                                          const plant_model& model, bake_cache* cache);

// The cache key of a species' radiance transfer for its three mesh levels: its model's key, the
// transfer format and every transfer setting.
std::uint64_t species_transfer_key(const species_settings& species, std::uint64_t seed,
                                   const transfer_settings& settings);

// The radiance transfer (Behrendt 2005 §4) of `model`'s full, reduced and far meshes: the full
// mesh's vertices ray-cast against the full mesh, the coarser levels' resampled from it
// (models/bake/transfer_resampling.h), through the cache ("radiance_transfer") when `cache` is not
// null.
std::array<radiance_transfer, 3> load_species_transfer(const species_settings& species,
                                                       std::uint64_t seed, const plant_model& model,
                                                       const transfer_settings& settings,
                                                       bake_cache* cache);

// The transfer of a point/line representation: one vector per point_line_model::points vertex
// and one per point_line_model::lines vertex.
struct point_line_transfer {
    radiance_transfer points;
    radiance_transfer lines;
};

// The cache key of a species' point/line transfer: species_transfer_key and the point/line
// representation's key (its receivers).
std::uint64_t species_point_line_transfer_key(const species_settings& species, std::uint64_t seed,
                                              const transfer_settings& settings);

// The radiance transfer of `point_lines` (load_species_point_lines of `model`), shadowed by
// `model`'s full mesh, through the cache ("radiance_transfer") when `cache` is not null.
point_line_transfer load_species_point_line_transfer(const species_settings& species,
                                                     std::uint64_t seed, const plant_model& model,
                                                     const point_line_model& point_lines,
                                                     const transfer_settings& settings,
                                                     bake_cache* cache);

}  // namespace sylva
