#include "setup/shell_assets.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "models/cache/shell_stack_io.h"
#include "scenarios/species_lookup.h"
#include "setup/wang_populations.h"

namespace sylva {
namespace {

static_assert(sizeof(shell_bake_settings) == 28, "hashed as bytes: seven 32-bit fields, no padding");

std::uint64_t hash_mesh(const mesh_data& mesh, std::uint64_t seed) {
    seed = hash_bytes(std::as_bytes(std::span(mesh.vertices)), seed);
    seed = hash_bytes(std::as_bytes(std::span(mesh.indices)), seed);
    seed = hash_bytes(std::as_bytes(std::span(mesh.transfer)), seed);
    return hash_bytes(std::as_bytes(std::span(mesh.submeshes)), seed);
}

std::uint64_t hash_image(const image_rgba8& image, std::uint64_t seed) {
    const std::uint32_t size[2] = {image.width, image.height};
    return hash_bytes(std::as_bytes(std::span(image.texels)), hash_bytes(std::as_bytes(std::span(size)), seed));
}

}  // namespace

shell_bake_settings shell_bake_settings_of(const scenario& s) {
    shell_bake_settings settings;
    settings.texels = std::clamp(std::uint32_t(std::ceil(s.wang_tiles.tile_size_m / 0.25)), 16u, 256u);
    return settings;
}

shell_textures build_shell_assets(const scenario& s, const scene_assets& assets, bake_cache* cache) {
    std::vector<std::size_t> tiled;
    for (std::size_t p = 0; p < s.populations.size(); ++p)
        if (s.populations[p].placement == "wang_tiles") tiled.push_back(p);
    shell_textures out;
    if (tiled.empty()) return out;
    out.tile_size_m = s.wang_tiles.tile_size_m;
    out.colours = s.wang_tiles.colours;
    out.tiling_seed = wang_tiling_seed(s);
    out.origin = wang_lattice_origin(s);
    out.area = s.populations[tiled.front()].area;
    out.standard_blending = s.shells.blending == "standard";
    shell_bake_settings settings = shell_bake_settings_of(s);
    // Behrendt 2005 §4 on the shells: lit like their plants. When every tiled species is lit by SH
    // transfer, the slices carry the transfer of what covers them (a quarter of the colour's
    // texels a side: the transfer varies with depth in the crown, not leaf by leaf); a mix of
    // SH-lit and normal-lit species keeps the normals, which every species has.
    bool by_transfer = s.shells.lighting == "plants";
    // Luft 2007 on the shells: the slices' normals are the mean of their plants' baked normals,
    // whose length is k_a when the species is implicit-lit. Decoded only when every tiled species'
    // is: a plain leaf's mean normal is short by its leaves' spread, not by an ambient coefficient.
    bool implicit = s.shells.lighting == "plants";
    for (std::size_t p : tiled) {
        const species_entry& entry =
            assets.library.species.at(species_index_of(s, s.populations[p].species));
        by_transfer = by_transfer && uses_transfer(entry.lighting) &&
                      !assets.meshes.at(entry.mesh_reduced).transfer.empty();
        implicit = implicit && uses_implicit_normals(entry.lighting);
    }
    out.implicit = implicit && !by_transfer;
    if (by_transfer) settings.transfer_texels = std::max(1u, settings.texels / 4);
    // One slice height for every tile (the slices are offset surfaces of the whole terrain):
    // the stack is as tall as the tallest plant any tiled population can have.
    for (std::size_t p : tiled) {
        const population_settings& pop = s.populations[p];
        for (std::size_t sp = 0; sp < s.species.size(); ++sp)
            if (s.species[sp].name == pop.species)
                settings.height_m = std::max(
                    settings.height_m, assets.meshes.at(assets.library.species.at(sp).mesh_full).bounds_max.y * pop.scale_max);
    }
    // Each tiled population's species (by species index) and tile set.
    std::vector<shell_species> species;
    std::vector<std::size_t> species_of;  // shell species index -> scenario species index
    std::vector<std::pair<std::uint32_t, wang_tile_set>> sets;
    std::uint64_t key = hash_string("shells " + std::to_string(k_shell_format));
    key = hash_bytes(std::as_bytes(std::span(&settings, 1)), key);
    for (std::size_t p : tiled) {
        const population_settings& pop = s.populations[p];
        const std::size_t sp = species_index_of(s, pop.species);
        const auto known = std::find(species_of.begin(), species_of.end(), sp);
        const auto index = std::uint32_t(known - species_of.begin());
        if (known == species_of.end()) {
            const species_entry& entry = assets.library.species.at(sp);
            species_of.push_back(sp);
            species.push_back({&assets.meshes.at(entry.mesh_reduced), &assets.leaf_textures.at(sp), &assets.bark_textures.at(sp)});
            key = hash_mesh(*species.back().mesh, key);
            key = hash_image(*species.back().leaf_texture, key);
            key = hash_image(*species.back().bark_texture, key);
        }
        sets.emplace_back(index, wang_tile_set_of(s, p, wang_reach_m(s, p, assets)));
        for (const auto& tile : sets.back().second.tiles)
            for (const placement& where : tile) {  // field by field: placement has padding
                const double xz[2] = {where.xz.x, where.xz.y};
                const float pose[2] = {where.scale, where.yaw};
                key = hash_bytes(std::as_bytes(std::span(xz)), key);
                key = hash_bytes(std::as_bytes(std::span(pose)), key);
            }
    }
    const std::uint32_t tile_count = out.colours * out.colours * out.colours * out.colours;
    key = hash_bytes(std::as_bytes(std::span(&out.tile_size_m, 1)), key);
    out.tiles = read_or_bake(
        cache, "shells", key,
        [&] {
            std::vector<shell_stack> stacks;
            for (std::uint32_t t = 0; t < tile_count; ++t) {
                std::vector<shell_plant> plants;
                for (const auto& [index, set] : sets) {
                    for (const placement& where : set.tiles[t]) plants.push_back({index, where});
                    for (const placement& where : set.reaching[t]) plants.push_back({index, where});
                }
                stacks.push_back(bake_shell_stack(species, plants, out.tile_size_m, settings));
            }
            return serialize_shell_stacks(stacks);
        },
        [](std::span<const std::byte> bytes) { return deserialize_shell_stacks(bytes); });
    return out;
}

}  // namespace sylva
