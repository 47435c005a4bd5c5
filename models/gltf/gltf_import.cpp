// Reading glTF with tinygltf: errors, the node walk, units (an accessor's elements are read by
// gltf_accessors.cpp). Classification, the leaf atlas and the levels of detail are in
// gltf_plant_builder.cpp.
#include "models/gltf/gltf_import.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "models/gltf/gltf_accessors.h"
#include "models/gltf/gltf_container.h"
#include "models/gltf/gltf_plant_builder.h"
#include "models/gltf/gltf_tinygltf.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;
using gltf_accessors::import_context;
using gltf_accessors::read_floats;
using gltf_accessors::read_triangles;

// Above this height a model without a unit scale is taken to be in centimetres: no plant
// Sylva draws is 100 m tall.
constexpr float k_centimetre_height = 100.0f;
glm::mat4 local_transform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::dmat4 m = glm::make_mat4(node.matrix.data());
        return glm::mat4(m);
    }
    glm::mat4 t(1.0f);
    if (node.translation.size() == 3)
        t = glm::translate(
            t, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
        t *= glm::mat4_cast(glm::quat(float(node.rotation[3]), float(node.rotation[0]),
                                      float(node.rotation[1]), float(node.rotation[2])));
    if (node.scale.size() == 3)
        t = glm::scale(t, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
    return t;
}

// Keeps the triangles with area; returns how many were dropped.
std::uint32_t drop_degenerate_triangles(const std::vector<vertex>& vertices,
                                        std::vector<std::uint32_t>& indices) {
    std::size_t kept = 0;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
        if (is_zero_area_triangle(vertices[i0].position, vertices[i1].position, vertices[i2].position))
            continue;
        indices[kept++] = i0, indices[kept++] = i1, indices[kept++] = i2;
    }
    const auto dropped = std::uint32_t((indices.size() - kept) / 3);
    indices.resize(kept);
    return dropped;
}

std::string format_position(glm::vec3 p) {
    const auto number = [](float v) {
        if (std::isnan(v)) return std::string("nan");
        if (std::isinf(v)) return std::string(v > 0 ? "+inf" : "-inf");
        char text[32];
        std::snprintf(text, sizeof(text), "%g", double(v));
        return std::string(text);
    };
    return "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ")";
}

bool is_finite(glm::vec3 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

std::string mesh_label(const tinygltf::Mesh& mesh, std::size_t index) {
    return mesh.name.empty() ? "mesh " + std::to_string(index) : "mesh '" + mesh.name + "'";
}

// `dropped_triangles` receives how many zero-area triangles were left out.
gltf_source_primitive read_primitive(const import_context& c, const tinygltf::Primitive& p,
                                     const std::string& part, const glm::mat4& transform,
                                     std::uint32_t& dropped_triangles) {
    gltf_source_primitive out;
    out.label = part;
    out.material = p.material;
    const auto attribute = [&](const char* name) {
        const auto it = p.attributes.find(name);
        return it == p.attributes.end() ? -1 : it->second;
    };
    if (attribute("POSITION") < 0) c.fail(part, "has no POSITION attribute");
    const std::vector<float> positions =
        read_floats(c, attribute("POSITION"), 3, part + " POSITION");
    const std::size_t n = positions.size() / 3;
    std::vector<float> normals, uvs;
    if (attribute("NORMAL") >= 0)
        normals = read_floats(c, attribute("NORMAL"), 3, part + " NORMAL");
    if (attribute("TEXCOORD_0") >= 0)
        uvs = read_floats(c, attribute("TEXCOORD_0"), 2, part + " TEXCOORD_0");
    // The spec gives every attribute of a primitive the same count; a shorter one would be read
    // past its end (found by the glTF fuzz target, tests/fuzz/regressions/gltf_import/).
    for (const auto& [name, values, components] :
         {std::tuple<const char*, const std::vector<float>&, std::size_t>{"NORMAL", normals, 3},
          {"TEXCOORD_0", uvs, 2}})
        if (!values.empty() && values.size() / components != n)
            c.fail(part, std::string(name) + " has " + std::to_string(values.size() / components) +
                             " elements but POSITION has " + std::to_string(n));
    const glm::mat3 normal_matrix = glm::inverseTranspose(glm::mat3(transform));
    out.vertices.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 local(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        // A NaN or infinite vertex cannot be drawn or bounded: reject the model, never draw it.
        if (!is_finite(local))
            c.fail(part, "vertex " + std::to_string(i) + " has a non-finite position " +
                             format_position(local) + "; positions must be finite numbers");
        vertex& v = out.vertices[i];
        v.position = glm::vec3(transform * glm::vec4(local, 1.0f));
        if (!is_finite(v.position))
            c.fail(part, "vertex " + std::to_string(i) + " at " + format_position(local) +
                             " is not finite after its node transforms " +
                             format_position(v.position));
        if (!normals.empty()) {
            const glm::vec3 nrm =
                normal_matrix * glm::vec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]);
            const float len = glm::length(nrm);
            v.normal = std::isfinite(len) && len > 1e-12f ? nrm / len : glm::vec3(0, 1, 0);
        }
        if (!uvs.empty()) v.uv = {uvs[2 * i], uvs[2 * i + 1]};
    }
    out.indices = read_triangles(c, p, n, part);
    dropped_triangles = drop_degenerate_triangles(out.vertices, out.indices);
    if (glm::determinant(glm::mat3(transform)) < 0)  // a mirroring transform flips the winding
        for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3)
            std::swap(out.indices[t + 1], out.indices[t + 2]);
    if (normals
            .empty()) {  // the spec asks for flat normals; area-weighted smooth ones suit foliage
        for (vertex& v : out.vertices) v.normal = glm::vec3(0.0f);
        for (std::size_t t = 0; t + 2 < out.indices.size(); t += 3) {
            vertex* tri[3] = {&out.vertices[out.indices[t]], &out.vertices[out.indices[t + 1]],
                              &out.vertices[out.indices[t + 2]]};
            const glm::vec3 face = glm::cross(tri[1]->position - tri[0]->position,
                                              tri[2]->position - tri[0]->position);
            for (vertex* v : tri) v->normal += face;
        }
        for (vertex& v : out.vertices) {
            const float len = glm::length(v.normal);
            v.normal = len > 1e-20f ? v.normal / len : glm::vec3(0, 1, 0);
        }
    }
    return out;
}

// A primitive whose triangles were all degenerate.
struct degenerate_primitive {
    std::string label;
    std::uint32_t dropped = 0;
};

struct walk_state {
    std::vector<gltf_source_primitive> primitives;
    std::vector<degenerate_primitive> degenerate;  // every primitive that lost triangles
    std::uint32_t mesh_nodes = 0;
    std::uint32_t max_depth = 0;
};

void walk(const import_context& c, int node_index, const glm::mat4& parent,
          std::uint32_t mesh_depth, int parent_mesh_node, int guard, walk_state& state) {
    const tinygltf::Model& m = *c.model;
    if (node_index < 0 || std::size_t(node_index) >= m.nodes.size())
        c.fail("node " + std::to_string(node_index), "does not exist");
    if (guard > 256) c.fail("node " + std::to_string(node_index), "the node hierarchy has a cycle");
    const tinygltf::Node& node = m.nodes[std::size_t(node_index)];
    const glm::mat4 transform = parent * local_transform(node);
    if (node.mesh >= 0) {
        if (std::size_t(node.mesh) >= m.meshes.size())
            c.fail("node " + std::to_string(node_index),
                   "mesh " + std::to_string(node.mesh) + " does not exist");
        const tinygltf::Mesh& mesh = m.meshes[std::size_t(node.mesh)];
        ++state.mesh_nodes;
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const std::string part =
                mesh_label(mesh, std::size_t(node.mesh)) + " primitive " + std::to_string(p);
            std::uint32_t dropped = 0;
            gltf_source_primitive primitive =
                read_primitive(c, mesh.primitives[p], part, transform, dropped);
            if (dropped) state.degenerate.push_back({part, dropped});
            if (primitive.indices.empty()) continue;  // nothing left to draw
            state.primitives.push_back(std::move(primitive));
            state.primitives.back().branch = std::uint32_t(node_index);
            state.primitives.back().level = std::uint8_t(std::min<std::uint32_t>(mesh_depth, 255));
            state.primitives.back().parent_branch =
                std::uint32_t(parent_mesh_node >= 0 ? parent_mesh_node : node_index);
        }
        state.max_depth = std::max(state.max_depth, ++mesh_depth);
        parent_mesh_node = node_index;
    }
    for (const int child : node.children)
        walk(c, child, transform, mesh_depth, parent_mesh_node, guard + 1, state);
}

float uniform_scale(const tinygltf::Node& node) {
    const glm::mat3 m(local_transform(node));
    const glm::vec3 s(glm::length(m[0]), glm::length(m[1]), glm::length(m[2]));
    return std::abs(s.x - s.y) < 1e-4f * s.x && std::abs(s.x - s.z) < 1e-4f * s.x ? s.x : 1.0f;
}

gltf_source_material read_material(const import_context& c, std::size_t index,
                                   std::vector<std::string>& warnings) {
    const tinygltf::Material& source = c.model->materials[index];
    gltf_source_material out;
    out.name = source.name.empty() ? "material " + std::to_string(index) : source.name;
    const auto& pbr = source.pbrMetallicRoughness;
    for (int k = 0; k < 4 && std::size_t(k) < pbr.baseColorFactor.size(); ++k)
        out.factor[k] = float(pbr.baseColorFactor[std::size_t(k)]);
    out.alpha_mode = source.alphaMode == "MASK"    ? gltf_alpha_mode::mask
                     : source.alphaMode == "BLEND" ? gltf_alpha_mode::blend
                                                   : gltf_alpha_mode::opaque;
    out.double_sided = source.doubleSided;
    const int texture = pbr.baseColorTexture.index;
    if (texture < 0) return out;
    const tinygltf::Model& m = *c.model;
    const int image =
        std::size_t(texture) < m.textures.size() ? m.textures[std::size_t(texture)].source : -1;
    if (image < 0 || std::size_t(image) >= m.images.size() ||
        m.images[std::size_t(image)].image.empty()) {
        const std::string uri = image >= 0 && std::size_t(image) < m.images.size()
                                    ? m.images[std::size_t(image)].uri
                                    : "";
        warnings.push_back(c.file + ": material '" + out.name + "': base-colour texture " +
                           (uri.empty() ? std::to_string(texture) : "'" + uri + "'") +
                           " could not be loaded; using its base-colour factor");
        return out;
    }
    const tinygltf::Image& img = m.images[std::size_t(image)];
    out.texture.width = std::uint32_t(img.width);
    out.texture.height = std::uint32_t(img.height);
    out.texture.texels = img.image;
    for (std::size_t i = 0; i < out.texture.texels.size();
         ++i)  // glTF: base colour = texture x factor
        out.texture.texels[i] = std::uint8_t(
            std::lround(out.texture.texels[i] * std::clamp(out.factor[int(i % 4)], 0.0f, 1.0f)));
    return out;
}

}  // namespace

bool is_zero_area_triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::dvec3 ab = glm::dvec3(b) - glm::dvec3(a), ac = glm::dvec3(c) - glm::dvec3(a),
                     bc = glm::dvec3(c) - glm::dvec3(b);
    const double longest_squared =
        std::max({glm::dot(ab, ab), glm::dot(ac, ac), glm::dot(bc, bc)});
    return glm::length(glm::cross(ab, ac)) <= k_zero_area_height_ratio * longest_squared;
}

gltf_import_result import_gltf_plant(const fs::path& file, std::uint32_t texture_size) {
    return import_gltf_source(read_gltf_source(file), texture_size);
}

gltf_import_result import_gltf_source(const gltf_source& source, std::uint32_t texture_size,
                                      gltf_import_stage stage) {
    import_context c;
    c.file = source.name;
    tinygltf::Model model;
    parse_gltf(source, model);
    c.model = &model;
    for (const std::string& required : model.extensionsRequired)
        if (required != "KHR_mesh_quantization" && required != "KHR_materials_unlit")
            throw std::runtime_error(c.file + ": requires the extension " + required +
                                     ", which is not supported");
    gltf_import_result result;
    for (std::size_t i = 0; i < model.materials.size(); ++i)
        result.materials.push_back(model.materials[i].name);
    std::vector<gltf_source_material> materials;
    for (std::size_t i = 0; i < model.materials.size(); ++i)
        materials.push_back(read_material(c, i, result.warnings));
    for (const std::string& w : result.warnings) spdlog::warn("{}", w);

    walk_state state;
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    std::vector<int> roots;
    if (std::size_t(scene) < model.scenes.size()) {
        roots = model.scenes[std::size_t(scene)].nodes;
    } else {  // no scene: every node nobody points to is a root
        std::vector<bool> child(model.nodes.size(), false);
        for (const auto& n : model.nodes)
            for (int k : n.children)
                if (k >= 0 && std::size_t(k) < child.size()) child[std::size_t(k)] = true;
        for (std::size_t i = 0; i < model.nodes.size(); ++i)
            if (!child[i]) roots.push_back(int(i));
    }
    float unit_scale = 1.0f;
    for (const int root : roots) {
        if (root >= 0 && std::size_t(root) < model.nodes.size() &&
            std::abs(uniform_scale(model.nodes[std::size_t(root)]) - 0.01f) < 1e-5f)
            unit_scale = 0.01f;
        walk(c, root, glm::mat4(1.0f), 0, -1, 0, state);
    }
    for (const degenerate_primitive& d : state.degenerate) {
        result.dropped_degenerate_triangles += d.dropped;
        result.warnings.push_back(c.file + ": " + d.label + ": dropped " +
                                  std::to_string(d.dropped) +
                                  " zero-area triangles (repeated or collinear vertices)");
        spdlog::warn("{}", result.warnings.back());
    }
    if (state.primitives.empty())
        throw std::runtime_error(c.file + (state.degenerate.empty()
                                               ? ": no meshes in the scene"
                                               : ": no triangles with area in the scene (" +
                                                     std::to_string(
                                                         result.dropped_degenerate_triangles) +
                                                     " zero-area triangles dropped)"));
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const auto& p : state.primitives)
        for (const vertex& v : p.vertices)
            lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
    if (unit_scale == 1.0f && hi.y - lo.y > k_centimetre_height) {
        unit_scale = 0.01f;
        for (auto& p : state.primitives)
            for (vertex& v : p.vertices) v.position *= unit_scale;
        result.warnings.push_back(c.file + ": " + std::to_string(hi.y - lo.y) +
                                  " units tall with no unit scale; assuming centimetres");
        spdlog::info("{}", result.warnings.back());
    }
    result.mesh_nodes = state.mesh_nodes;
    result.hierarchy_depth = state.max_depth;
    // A branch structure needs at least trunk -> branch -> twig as nested mesh nodes.
    result.model.has_hierarchy = state.max_depth >= 3;
    if (stage == gltf_import_stage::read) return result;
    build_gltf_plant(materials, state.primitives, texture_size, result);
    result.model.name = fs::path(source.name).stem().string();
    result.model.source_unit_scale = unit_scale;
    return result;
}

plant_model import_plant_model(const fs::path& file, std::uint32_t texture_size) {
    return import_gltf_plant(file, texture_size).model;
}

}  // namespace sylva
