// Leaf or bark per primitive, one leaf atlas and one bark texture, and the reduced and far
// levels (bark through meshoptimizer, leaves by keeping a subset of whole leaves).
#include "models/gltf/gltf_plant_builder.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "models/gltf/gltf_image_codec.h"
#include "models/random.h"

namespace sylva {
namespace {

// Triangle share of the reduced and far levels (plant_model.h).
constexpr std::array<float, 3> k_lod_fraction = {1.0f, 0.10f, 0.04f};
// A leaf texture: this share of its texels cut away by alpha (cards, leaf sprays).
constexpr float k_leaf_alpha_ratio = 0.15f;
// Foliage: many pieces, none holding more than this share of the triangles.
constexpr std::uint32_t k_leaf_min_components = 8;
constexpr float k_leaf_max_component_share = 0.2f;
// A trunk: one piece holding at least this share.
constexpr float k_trunk_component_share = 0.5f;

struct texture_evidence {
    float alpha_ratio = 0;
    bool green = false;
    bool brown = false;
};

// Alpha cut-out share and mean colour of the visible texels (alpha >= 0.5) of the material's
// texture (the factor is already baked in), or the factor alone when it has no texture.
texture_evidence look_at(const gltf_source_material* material) {
    texture_evidence e;
    glm::vec3 mean = material ? glm::vec3(material->factor) : glm::vec3(1.0f);
    if (material && !material->texture.texels.empty()) {
        const auto& t = material->texture.texels;
        std::size_t cut = 0, visible = 0;
        glm::dvec3 sum(0.0);
        for (std::size_t i = 0; i < t.size(); i += 4) {
            if (t[i + 3] < 128) {
                ++cut;
                continue;
            }
            ++visible;
            sum += glm::dvec3(t[i], t[i + 1], t[i + 2]) / 255.0;
        }
        e.alpha_ratio = float(double(cut) / double(t.size() / 4));
        mean = visible ? glm::vec3(sum / double(visible)) : glm::vec3(0.0f);
    }
    const float chroma = std::max({mean.r, mean.g, mean.b}) - std::min({mean.r, mean.g, mean.b});
    e.green = mean.g >= mean.r && mean.g > mean.b && chroma > 0.06f;
    e.brown = mean.r > mean.g && mean.g >= mean.b * 0.8f && !e.green;
    return e;
}

// Votes: alpha cut-outs count double because they are the surest sign of a leaf card; an
// alpha-tested or blended material, a green colour and many small pieces count once each;
// brown and one dominant piece count against.
bool classify(const gltf_source_material* material, const texture_evidence& e,
              const gltf_primitive_report& r) {
    int votes = 0;
    if (e.alpha_ratio > k_leaf_alpha_ratio) votes += 2;
    if (material && material->alpha_mode != gltf_alpha_mode::opaque) votes += 1;
    if (e.green) votes += 1;
    if (e.brown) votes -= 1;
    if (r.components >= k_leaf_min_components &&
        r.largest_component_share <= k_leaf_max_component_share)
        votes += 1;
    if (r.largest_component_share >= k_trunk_component_share) votes -= 1;
    return votes >= 2;
}

image_rgba8 solid(glm::vec4 colour, std::uint32_t size) {
    image_rgba8 out{size, size, std::vector<std::uint8_t>(std::size_t(size) * size * 4)};
    for (std::size_t i = 0; i < out.texels.size(); ++i)
        out.texels[i] =
            std::uint8_t(std::lround(std::clamp(colour[int(i % 4)], 0.0f, 1.0f) * 255.0f));
    return out;
}

image_rgba8 material_texture(const gltf_source_material* m, std::uint32_t size) {
    if (!m) return solid(glm::vec4(1.0f), size);
    if (m->texture.texels.empty()) return solid(m->factor, size);
    return resize_image(m->texture, size, size);
}

// The leaf atlas: a grid of equal cells, one per leaf material (a shelf packer whose shelves
// are all one cell high, enough since every source texture is resampled to the cell). A texel
// of padding keeps filtering from reaching the next cell.
struct atlas_cell {
    glm::vec2 origin{0.0f};
    glm::vec2 extent{1.0f};
};

std::unordered_map<int, atlas_cell> pack_leaf_atlas(
    const std::vector<gltf_source_material>& materials, const std::vector<int>& used,
    std::uint32_t size, image_rgba8& atlas) {
    atlas = image_rgba8{size, size, std::vector<std::uint8_t>(std::size_t(size) * size * 4, 0)};
    std::unordered_map<int, atlas_cell> cells;
    if (used.empty()) return cells;
    const auto columns = std::uint32_t(std::ceil(std::sqrt(double(used.size()))));
    const std::uint32_t cell = size / columns;
    const std::uint32_t pad = columns > 1 ? 1 : 0;
    for (std::size_t i = 0; i < used.size(); ++i) {
        const auto cx = std::uint32_t(i) % columns * cell, cy = std::uint32_t(i) / columns * cell;
        const int m = used[i];
        const image_rgba8 tile =
            material_texture(m >= 0 ? &materials[std::size_t(m)] : nullptr, cell - 2 * pad);
        for (std::uint32_t y = 0; y < tile.height; ++y)
            std::copy_n(tile.at(0, y), tile.width * 4, atlas.at(cx + pad, cy + pad + y));
        cells[m] = {glm::vec2(float(cx + pad), float(cy + pad)) / float(size),
                    glm::vec2(float(tile.width), float(tile.height)) / float(size)};
    }
    return cells;
}

// Leaf uvs into the atlas cell: a primitive whose uvs span one tile is shifted into 0..1, any
// other is clamped (a leaf card never repeats its texture).
void remap_leaf_uvs(std::vector<vertex>& vertices, std::size_t first, const atlas_cell& cell) {
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (std::size_t i = first; i < vertices.size(); ++i)
        lo = glm::min(lo, vertices[i].uv), hi = glm::max(hi, vertices[i].uv);
    const glm::vec2 shift = glm::floor(lo);
    const bool one_tile = hi.x - shift.x <= 1.0f && hi.y - shift.y <= 1.0f;
    for (std::size_t i = first; i < vertices.size(); ++i) {
        glm::vec2 uv = one_tile ? vertices[i].uv - shift : glm::clamp(vertices[i].uv, 0.0f, 1.0f);
        vertices[i].uv = cell.origin + uv * cell.extent;
    }
}

void append(mesh_data& mesh, const std::vector<vertex>& vertices,
            const std::vector<std::uint32_t>& indices) {
    const auto base = std::uint32_t(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), vertices.begin(), vertices.end());
    for (const std::uint32_t i : indices) mesh.indices.push_back(base + i);
}

struct part_geometry {
    std::vector<vertex> vertices;
    std::vector<std::uint32_t> indices;
    std::vector<triangle_part> parts;  // per triangle of the full level
};

// meshoptimizer's edge-collapse simplifier; where seams lock too much of the mesh, the sloppy
// one (which ignores topology) finishes the job.
std::vector<std::uint32_t> simplify(const part_geometry& g, float fraction) {
    if (g.indices.empty()) return {};
    const std::size_t target =
        std::max<std::size_t>(3, std::size_t(float(g.indices.size()) * fraction) / 3 * 3);
    std::vector<std::uint32_t> out(g.indices.size());
    out.resize(meshopt_simplify(out.data(), g.indices.data(), g.indices.size(),
                                &g.vertices[0].position.x, g.vertices.size(), sizeof(vertex),
                                target, 0.05f, 0, nullptr));
    if (out.size() > target * 3 / 2) {
        std::vector<std::uint32_t> sloppy(g.indices.size());
        sloppy.resize(meshopt_simplifySloppy(sloppy.data(), g.indices.data(), g.indices.size(),
                                             &g.vertices[0].position.x, g.vertices.size(),
                                             sizeof(vertex), target, 1.0f, nullptr));
        if (!sloppy.empty()) out = std::move(sloppy);
    }
    return out;
}

// Keeps a seeded subset of whole leaves, each scaled about its centroid by 1/sqrt(fraction) so
// the foliage keeps its area (and so its coverage) with fewer cards.
std::vector<std::uint32_t> thin_leaves(part_geometry& g, float fraction) {
    std::uint32_t count = 0;
    const std::vector<std::uint32_t> component = triangle_components(g.vertices, g.indices, count);
    if (float(count) < 1.0f / fraction)
        return simplify(g, fraction);  // a few big pieces: not cards
    const auto keep =
        std::max<std::uint32_t>(1, std::uint32_t(std::lround(float(count) * fraction)));
    std::vector<std::uint32_t> order(count);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return hash_combine(0x6c656166u, a) < hash_combine(0x6c656166u, b);
    });
    std::vector<bool> kept(count, false);
    for (std::uint32_t i = 0; i < keep; ++i) kept[order[i]] = true;
    const float scale = 1.0f / std::sqrt(float(keep) / float(count));
    std::vector<glm::vec3> centroid(count, glm::vec3(0.0f));
    std::vector<float> corners(count, 0.0f);
    for (std::size_t t = 0; t < component.size(); ++t)
        for (int k = 0; k < 3; ++k)
            centroid[component[t]] += g.vertices[g.indices[3 * t + std::size_t(k)]].position,
                corners[component[t]] += 1;
    part_geometry out;
    std::unordered_map<std::uint32_t, std::uint32_t> remap;
    std::vector<std::uint32_t> indices;
    for (std::size_t t = 0; t < component.size(); ++t) {
        const std::uint32_t c = component[t];
        if (!kept[c]) continue;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t source = g.indices[3 * t + std::size_t(k)];
            auto [it, added] = remap.try_emplace(source, std::uint32_t(out.vertices.size()));
            if (added) {
                vertex v = g.vertices[source];
                const glm::vec3 centre = centroid[c] / corners[c];
                v.position = centre + (v.position - centre) * scale;
                out.vertices.push_back(v);
            }
            indices.push_back(it->second);
        }
    }
    g.vertices = std::move(out.vertices);
    return indices;
}

struct position_key {
    std::array<std::uint32_t, 3> bits{};
    bool operator==(const position_key&) const = default;
};
struct position_key_hash {
    std::size_t operator()(const position_key& k) const {
        return hash_combine(0, k.bits[0], k.bits[1], k.bits[2]);
    }
};

// One leaf_record per connected leaf piece (its area-weighted centre, mean facing and
// bounding-box diagonal); an import knows no branches, so parent_branch stays 0.
void record_leaves(mesh_data& mesh) {
    std::vector<std::uint32_t> indices;
    for (const submesh& s : mesh.submeshes)
        if (s.material == material_kind::leaf)
            indices.insert(indices.end(), mesh.indices.begin() + s.first_index,
                           mesh.indices.begin() + s.first_index + s.index_count);
    std::uint32_t count = 0;
    const std::vector<std::uint32_t> component = triangle_components(mesh.vertices, indices, count);
    struct sums {
        glm::vec3 centre{0.0f}, facing{0.0f}, lo{std::numeric_limits<float>::max()},
            hi{-std::numeric_limits<float>::max()};
        float area = 0;
    };
    std::vector<sums> pieces(count);
    for (std::size_t t = 0; t < component.size(); ++t) {
        const glm::vec3 a = mesh.vertices[indices[3 * t]].position,
                        b = mesh.vertices[indices[3 * t + 1]].position,
                        c = mesh.vertices[indices[3 * t + 2]].position;
        sums& p = pieces[component[t]];
        const glm::vec3 face = glm::cross(b - a, c - a);
        const float area = 0.5f * glm::length(face);
        p.centre += area * (a + b + c) / 3.0f;
        p.area += area;
        p.facing += face;
        p.lo = glm::min(glm::min(p.lo, a), glm::min(b, c));
        p.hi = glm::max(glm::max(p.hi, a), glm::max(b, c));
    }
    mesh.leaves.clear();
    for (const sums& p : pieces) {
        leaf_record r;
        r.center = p.area > 0 ? p.centre / p.area : 0.5f * (p.lo + p.hi);
        const float facing = glm::length(p.facing);
        r.normal = facing > 0 ? p.facing / facing : glm::vec3(0.0f, 1.0f, 0.0f);
        r.size = glm::length(p.hi - p.lo);
        mesh.leaves.push_back(r);
    }
}

mesh_data assemble(const part_geometry& bark, const part_geometry& leaves, float fraction) {
    mesh_data mesh;
    part_geometry b = bark, l = leaves;
    if (fraction < 1.0f) {
        b.indices = simplify(bark, fraction);
        l.indices = thin_leaves(l, fraction);
    }
    append(mesh, b.vertices, b.indices);
    mesh.submeshes.push_back({0, std::uint32_t(mesh.indices.size()), material_kind::bark});
    const auto leaf_first = std::uint32_t(mesh.indices.size());
    append(mesh, l.vertices, l.indices);
    mesh.submeshes.push_back(
        {leaf_first, std::uint32_t(mesh.indices.size()) - leaf_first, material_kind::leaf});
    std::erase_if(mesh.submeshes, [](const submesh& s) { return s.index_count == 0; });
    if (!mesh.vertices.empty()) {
        mesh.bounds_min = mesh.bounds_max = mesh.vertices[0].position;
        for (const vertex& v : mesh.vertices)
            mesh.bounds_min = glm::min(mesh.bounds_min, v.position),
            mesh.bounds_max = glm::max(mesh.bounds_max, v.position);
    }
    // Compact away vertices the simplifier no longer references.
    std::vector<std::uint32_t> remap(mesh.vertices.size());
    const std::size_t unique =
        meshopt_generateVertexRemap(remap.data(), mesh.indices.data(), mesh.indices.size(),
                                    mesh.vertices.data(), mesh.vertices.size(), sizeof(vertex));
    std::vector<vertex> compact(unique);
    meshopt_remapVertexBuffer(compact.data(), mesh.vertices.data(), mesh.vertices.size(),
                              sizeof(vertex), remap.data());
    meshopt_remapIndexBuffer(mesh.indices.data(), mesh.indices.data(), mesh.indices.size(),
                             remap.data());
    mesh.vertices = std::move(compact);
    record_leaves(mesh);
    return mesh;
}

}  // namespace

std::vector<std::uint32_t> triangle_components(const std::vector<vertex>& vertices,
                                               const std::vector<std::uint32_t>& indices,
                                               std::uint32_t& count) {
    // Weld by exact position, then union-find over triangle corners.
    std::vector<std::uint32_t> weld(vertices.size());
    {
        std::unordered_map<position_key, std::uint32_t, position_key_hash> first;
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            position_key key;
            std::memcpy(key.bits.data(), &vertices[i].position, sizeof(glm::vec3));
            weld[i] = first.try_emplace(key, std::uint32_t(i)).first->second;
        }
    }
    std::vector<std::uint32_t> parent(vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto find = [&](std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = find(weld[indices[t]]);
        for (int k = 1; k < 3; ++k) parent[find(weld[indices[t + std::size_t(k)]])] = a;
    }
    std::unordered_map<std::uint32_t, std::uint32_t> ids;
    std::vector<std::uint32_t> component(indices.size() / 3);
    for (std::size_t t = 0; t < component.size(); ++t)
        component[t] =
            ids.try_emplace(find(weld[indices[3 * t]]), std::uint32_t(ids.size())).first->second;
    count = std::uint32_t(ids.size());
    return component;
}

void build_gltf_plant(const std::vector<gltf_source_material>& materials,
                      const std::vector<gltf_source_primitive>& primitives,
                      std::uint32_t texture_size, gltf_import_result& result) {
    part_geometry bark, leaves;
    std::vector<int> leaf_materials;
    std::vector<std::pair<std::size_t, int>> leaf_ranges;  // first vertex in `leaves`, material
    int bark_material = -2;
    for (const gltf_source_primitive& p : primitives) {
        const gltf_source_material* material =
            p.material >= 0 && std::size_t(p.material) < materials.size()
                ? &materials[std::size_t(p.material)]
                : nullptr;
        gltf_primitive_report r;
        r.label = p.label;
        r.material = material ? material->name : "(default)";
        r.triangles = std::uint32_t(p.indices.size() / 3);
        const std::vector<std::uint32_t> component =
            triangle_components(p.vertices, p.indices, r.components);
        std::vector<std::uint32_t> sizes(r.components, 0);
        for (const std::uint32_t c : component) ++sizes[c];
        r.largest_component_share =
            sizes.empty()
                ? 0.0f
                : float(*std::max_element(sizes.begin(), sizes.end())) / float(r.triangles);
        const texture_evidence e = look_at(material);
        r.alpha_ratio = e.alpha_ratio;
        r.green = e.green;
        r.leaf = classify(material, e, r);
        result.primitives.push_back(r);
        const int key = material ? p.material : -1;
        if (r.leaf) {
            if (std::find(leaf_materials.begin(), leaf_materials.end(), key) ==
                leaf_materials.end())
                leaf_materials.push_back(key);
            leaf_ranges.emplace_back(leaves.vertices.size(), key);
            leaves.parts.insert(leaves.parts.end(), r.triangles,
                                {p.branch, p.level, part_kind::leaf, p.parent_branch});
            const auto base = std::uint32_t(leaves.vertices.size());
            leaves.vertices.insert(leaves.vertices.end(), p.vertices.begin(), p.vertices.end());
            for (const std::uint32_t i : p.indices) leaves.indices.push_back(base + i);
        } else {
            if (bark_material == -2 || (bark_material == -1 && key >= 0)) bark_material = key;
            bark.parts.insert(bark.parts.end(), r.triangles,
                              {p.branch, p.level, part_kind::bark, p.parent_branch});
            const auto base = std::uint32_t(bark.vertices.size());
            bark.vertices.insert(bark.vertices.end(), p.vertices.begin(), p.vertices.end());
            for (const std::uint32_t i : p.indices) bark.indices.push_back(base + i);
        }
    }
    plant_model& model = result.model;
    const auto cells = pack_leaf_atlas(materials, leaf_materials, texture_size, model.leaf_texture);
    for (std::size_t i = 0; i < leaf_ranges.size(); ++i) {
        std::vector<vertex> tail(
            leaves.vertices.begin() + std::ptrdiff_t(leaf_ranges[i].first),
            i + 1 < leaf_ranges.size()
                ? leaves.vertices.begin() + std::ptrdiff_t(leaf_ranges[i + 1].first)
                : leaves.vertices.end());
        remap_leaf_uvs(tail, 0, cells.at(leaf_ranges[i].second));
        std::copy(tail.begin(), tail.end(),
                  leaves.vertices.begin() + std::ptrdiff_t(leaf_ranges[i].first));
    }
    model.bark_texture = material_texture(
        bark_material >= 0 ? &materials[std::size_t(bark_material)] : nullptr, texture_size);
    for (std::size_t lod = 0; lod < 3; ++lod)
        model.lods[lod] = assemble(bark, leaves, k_lod_fraction[lod]);
    // Only the full level keeps the triangle order of the source; the simplified ones are
    // "unknown".
    if (model.has_hierarchy) {
        model.lods[0].parts = bark.parts;
        model.lods[0].parts.insert(model.lods[0].parts.end(), leaves.parts.begin(),
                                   leaves.parts.end());
    }
}

}  // namespace sylva
