#include "setup/tile_point_sets.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <limits>
#include <glm/geometric.hpp>
#include <map>
#include <tuple>

#include "components/bounds.h"
#include "components/plant_instance.h"
#include "components/tile.h"
#include "components/transform.h"
#include "models/random.h"
#include "lighting/transfer_rotation.h"
#include "setup/point_line_assets.h"

namespace sylva {
namespace {

// What one set gathers: one species' samples of one material and primitive.
using set_key = std::tuple<std::uint32_t, material_kind, lod_primitive>;  // species, material, primitive

// A set while it is being built: samples relative to its tile's origin.
struct sample_set {
    std::vector<vertex> vertices;  // one per point, two per line
    std::vector<vertex_transfer> transfer;  // one per vertex when the species is lit by transfer
    double area = 0.0;
    double full_length = 0.0;  // of every line the set stands for
    float line_error = 0.0f;
    std::uint32_t samples = 0;
    double stands_for = 0.0;  // samples of every plant of the tile
};

std::uint32_t vertices_per(lod_primitive p) { return p == lod_primitive::lines ? 2u : 1u; }

// Takes `share` (rounded) of `from`'s samples (a prefix: a random subset), moved by `offset`.
// Transfer records (when `from_transfer` has them) turn with the plant's yaw into the tile's
// frame, as its normals do.
void take(sample_set& into, const std::vector<vertex>& from,
          const std::vector<vertex_transfer>& from_transfer, std::uint32_t per, double share,
          glm::vec3 offset, float yaw, float scale) {
    const auto available = std::uint32_t(from.size() / per);
    const auto n = std::min(available, std::uint32_t(std::lround(share)));
    const float c = std::cos(yaw), s = std::sin(yaw);
    auto rotate = [&](glm::vec3 p) { return glm::vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z); };
    for (std::uint32_t i = 0; i < n * per; ++i) {
        vertex v = from[i];
        v.position = rotate(v.position * scale) + offset;
        v.normal = rotate(v.normal);
        into.vertices.push_back(v);
        if (!from_transfer.empty())
            into.transfer.push_back(yaw == 0.0f ? from_transfer[i]
                                                : rotate_about_y(from_transfer[i], yaw));
    }
}

glm::dvec3 origin_of(const tile& t) {
    return {t.min.x + 0.5 * t.size, 0.5 * (double(t.min_height) + double(t.max_height)), t.min.y + 0.5 * t.size};
}

}  // namespace

tile_point_sets build_tile_point_sets(const ecs::world& world, scene_assets& assets, std::uint64_t seed) {
    tile_point_sets out;
    const auto& tiles = world.table<tile>();
    if (tiles.size() == 0 || assets.library.lod_parts.empty()) return out;
    const auto& transforms = world.table<world_transform>();
    const auto& instances = world.table<plant_instance>();
    const auto& bounds_of = world.table<bounds>();
    const species_library& library = assets.library;

    const std::size_t n = tiles.size();
    std::vector<std::map<set_key, sample_set>> sets(n);
    out.origin.resize(n);
    out.radius.resize(n);
    // Children follow their parent in the tile table (eco tile preorder): a reverse walk
    // builds every child's sets before its parent merges them.
    for (std::size_t i = n; i-- > 0;) {
        const tile& t = tiles.data()[i];
        // The sphere around the tile's plants (their bounding spheres), not around its square: a
        // few plants in a large, mostly empty tile are as far from the eye as they stand, and the
        // tile's distance rules (aggregate_eco_tiles) measure what the set draws.
        if (t.plant_count > 0 && bounds_of.size() >= t.first_plant + t.plant_count) {
            glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
            for (std::uint32_t k = t.first_plant; k < t.first_plant + t.plant_count; ++k) {
                const glm::dvec3 c = transforms.data()[k].position +
                                     glm::dvec3(0.0, double(bounds_of.data()[k].center_height), 0.0);
                lo = glm::min(lo, c);
                hi = glm::max(hi, c);
            }
            out.origin[i] = 0.5 * (lo + hi);
            double r = 0.0;
            for (std::uint32_t k = t.first_plant; k < t.first_plant + t.plant_count; ++k) {
                const glm::dvec3 c = transforms.data()[k].position +
                                     glm::dvec3(0.0, double(bounds_of.data()[k].center_height), 0.0);
                r = std::max(r, glm::length(c - out.origin[i]) + double(bounds_of.data()[k].radius));
            }
            out.radius[i] = float(r);
        } else {
            out.origin[i] = origin_of(t);
            out.radius[i] = float(std::sqrt(0.5 * t.size * t.size + 0.25 * double(t.max_height - t.min_height) *
                                                                          double(t.max_height - t.min_height)) +
                                  double(t.reach_m));
        }
        std::map<set_key, sample_set>& own = sets[i];
        if (t.is_leaf()) {
            // Every plant's parts: their areas first, then prefixes in proportion to them.
            std::map<set_key, double> area;
            auto each_part = [&](std::size_t plant, auto&& f) {
                const species_entry& sp = library.species[static_cast<std::size_t>(instances.data()[plant].species)];
                const lod_cell_entry whole{sp.first_lod_part, sp.lod_part_count};
                for (std::uint32_t c = 0; c < std::max(sp.cell_count, 1u); ++c) {
                    const lod_cell_entry cell = sp.cell_count > 1 ? library.cells[sp.first_cell + c] : whole;
                    for (std::uint32_t p = 0; p < cell.lod_part_count; ++p) {
                        const lod_part_entry& part = library.lod_parts[cell.first_lod_part + p];
                        const mesh_data& mesh = assets.meshes[part.mesh_primitives];
                        f(static_cast<std::uint32_t>(instances.data()[plant].species), part, mesh);
                    }
                }
            };
            for (std::uint32_t k = t.first_plant; k < t.first_plant + t.plant_count; ++k)
                each_part(k, [&](std::uint32_t species, const lod_part_entry& part, const mesh_data& mesh) {
                    const float s = transforms.data()[k].scale;
                    area[{species, mesh.submeshes[0].material, part.primitive}] +=
                        double(part.area_m2) * s * s;
                });
            // Samples per m², the same for every plant of a set (so samples follow area), as
            // high as the budget and the sparsest plant's own list allow.
            std::map<set_key, double> density;
            for (std::uint32_t k = t.first_plant; k < t.first_plant + t.plant_count; ++k)
                each_part(k, [&](std::uint32_t species, const lod_part_entry& part, const mesh_data& mesh) {
                    const set_key key{species, mesh.submeshes[0].material, part.primitive};
                    const float s = transforms.data()[k].scale;
                    const double a = double(part.area_m2) * s * s;
                    const double plant_density = a > 0.0 ? double(part.primitive_count) / a : 0.0;
                    const auto it = density.find(key);
                    density[key] = it == density.end() ? std::min(plant_density, k_tile_samples / area[key])
                                                       : std::min(it->second, plant_density);
                });
            for (std::uint32_t k = t.first_plant; k < t.first_plant + t.plant_count; ++k) {
                const world_transform& w = transforms.data()[k];
                const glm::vec3 offset(w.position - out.origin[i]);
                each_part(k, [&](std::uint32_t species, const lod_part_entry& part, const mesh_data& mesh) {
                    const set_key key{species, mesh.submeshes[0].material, part.primitive};
                    const double a = double(part.area_m2) * w.scale * w.scale;
                    sample_set& set = own[key];
                    set.area += a;
                    set.line_error = std::max(set.line_error, part.line_error_m * w.scale);
                    set.full_length += double(part.line_length_m) * w.scale;
                    set.stands_for += part.primitive_count;
                    take(set, mesh.vertices, mesh.transfer, vertices_per(part.primitive),
                         density[key] * a, offset, w.yaw, w.scale);
                });
            }
        } else {
            // Merge the children's sets: prefixes in proportion to their areas, at one density.
            std::map<set_key, double> area, density;
            for (const ecs::entity child : t.children)
                for (const auto& [key, set] : sets[tiles.index_of(child)]) area[key] += set.area;
            for (const ecs::entity child : t.children)
                for (const auto& [key, set] : sets[tiles.index_of(child)]) {
                    const double child_density = set.area > 0.0 ? double(set.samples) / set.area : 0.0;
                    const auto it = density.find(key);
                    density[key] = it == density.end() ? std::min(child_density, k_tile_samples / area[key])
                                                       : std::min(it->second, child_density);
                }
            for (const ecs::entity child : t.children) {
                const std::size_t c = tiles.index_of(child);
                const glm::vec3 offset(out.origin[c] - out.origin[i]);
                for (const auto& [key, set] : sets[c]) {
                    sample_set& merged = own[key];
                    merged.area += set.area;
                    merged.line_error = std::max(merged.line_error, set.line_error);
                    merged.full_length += set.full_length;
                    merged.stands_for += set.stands_for;
                    take(merged, set.vertices, set.transfer, vertices_per(std::get<2>(key)),
                         density[key] * set.area, offset, 0.0f, 1.0f);
                }
            }
        }
        std::uint32_t stream = 0;
        for (auto& [key, set] : own) {
            const std::uint32_t per = vertices_per(std::get<2>(key));
            rng random(hash_combine(seed, std::uint64_t(i), std::uint64_t(stream++)), 0x711eULL);
            rng same_order = random;  // the transfer records take the vertices' permutation
            shuffle_groups(set.vertices, per, random);
            shuffle_groups(set.transfer, per, same_order);
            set.samples = std::uint32_t(set.vertices.size() / per);
        }
    }

    // Meshes and part records, tile by tile.
    out.first_part.assign(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        out.first_part[i] = std::uint32_t(out.parts.size());
        for (auto& [key, set] : sets[i]) {
            if (set.samples == 0) continue;
            const auto [species, material, primitive] = key;
            tile_point_part part;
            part.tile = std::uint32_t(i);
            part.primitive = primitive;
            part.texture_layer = library.species[species].texture_layer;
            part.area_m2 = float(set.area);
            // Eq. 2's l is the length of all the lines the set stands for: its own lines'
            // length scaled by how many of the tile's lines they are.
            part.line_length_m = float(set.full_length);
            part.line_error_m = set.line_error;
            part.count = set.samples;
            part.stands_for = std::uint32_t(std::min(set.stands_for, 4e9));
            const primitive_kind kind =
                primitive == lod_primitive::points ? primitive_kind::points : primitive_kind::lines;
            if (primitive == lod_primitive::lines)
                part.mesh_splats = add_sample_mesh(
                    assets,
                    primitive_mesh(set.vertices, primitive_kind::points, material, set.transfer),
                    2 * set.samples);
            part.mesh = add_sample_mesh(
                assets,
                primitive_mesh(std::move(set.vertices), kind, material, std::move(set.transfer)),
                set.samples);
            for (const std::uint16_t m : {part.mesh, part.mesh_splats})
                if (m) assets.library.meshes[m].lighting = library.species[species].lighting;
            out.parts.push_back(part);
        }
        sets[i].clear();
    }
    out.first_part[n] = std::uint32_t(out.parts.size());
    return out;
}

}  // namespace sylva
