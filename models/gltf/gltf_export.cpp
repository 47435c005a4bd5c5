// glTF export through tinygltf's writer; the texture PNGs are encoded by OpenImageIO and stored
// in the binary chunk, so the writer never touches an image.
#include "models/gltf/gltf_export.h"

#include <algorithm>
#include <cmath>
#include <glm/vec4.hpp>
#include <cstring>
#include <glm/geometric.hpp>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.h"
#include "models/bake/implicit_illumination.h"
#include "models/gltf/gltf_image_codec.h"
#include "models/gltf/gltf_tinygltf.h"

namespace sylva {
namespace {

// Appends bytes at a 4-byte boundary (accessor alignment) and returns the buffer view index.
int add_view(tinygltf::Model& model, const void* data, std::size_t size, int target,
             int stride = 0) {
    std::vector<unsigned char>& buffer = model.buffers[0].data;
    buffer.resize((buffer.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = buffer.size();
    view.byteLength = size;
    view.byteStride = std::size_t(stride);
    view.target = target;
    const auto* bytes = static_cast<const unsigned char*>(data);
    buffer.insert(buffer.end(), bytes, bytes + size);
    model.bufferViews.push_back(view);
    return int(model.bufferViews.size() - 1);
}

int add_accessor(tinygltf::Model& model, int view, std::size_t offset, std::size_t count,
                 int component, int type) {
    tinygltf::Accessor a;
    a.bufferView = view;
    a.byteOffset = offset;
    a.count = count;
    a.componentType = component;
    a.type = type;
    model.accessors.push_back(a);
    return int(model.accessors.size() - 1);
}

int add_texture(tinygltf::Model& model, const image_rgba8& image, const std::string& name,
                int wrap) {
    const std::vector<std::uint8_t> png = encode_png(image);
    tinygltf::Image i;
    i.name = name;
    i.mimeType = "image/png";
    i.bufferView = add_view(model, png.data(), png.size(), 0);
    model.images.push_back(i);
    tinygltf::Sampler s;
    s.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    s.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    s.wrapS = s.wrapT = wrap;
    model.samplers.push_back(s);
    tinygltf::Texture t;
    t.name = name;
    t.source = int(model.images.size() - 1);
    t.sampler = int(model.samplers.size() - 1);
    model.textures.push_back(t);
    return int(model.textures.size() - 1);
}

image_rgba8 or_white(const image_rgba8& image) {
    return image.texels.empty() ? image_rgba8{1, 1, {255, 255, 255, 255}} : image;
}

// tinygltf's file writer checks none of its writes (a full disk or a directory in the file's
// place still "succeeds"), so the .glb is built in memory and written by write_atomically,
// which checks every write and the close and renames the whole file into place.
void write_glb(tinygltf::Model& model, const std::filesystem::path& file) {
    model.buffers[0].data.resize((model.buffers[0].data.size() + 3) / 4 * 4, 0);
    std::error_code ec;
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
    tinygltf::TinyGLTF writer = make_gltf_loader();
    std::ostringstream glb;
    if (!writer.WriteGltfSceneToStream(&model, glb, false, true))
        throw std::runtime_error(file.string() + ": cannot be written (the glTF writer failed)");
    write_atomically(file, glb.view());
}

void add_single_node_scene(tinygltf::Model& model, const std::string& name) {
    tinygltf::Node node;
    node.name = name;
    node.mesh = 0;
    model.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {0};
    model.scenes.push_back(scene);
    model.defaultScene = 0;
}

// The interleaved vertex buffer of a mesh (any vertex type with position, normal and uv
// members), its view and the position, normal and uv accessors (positions bounded by lo, hi).
struct vertex_accessors {
    int view = -1, position = -1, normal = -1, uv = -1;
};
template <typename Vertex>
vertex_accessors add_vertex_accessors(tinygltf::Model& model, const std::vector<Vertex>& vertices, glm::vec3 lo,
                                      glm::vec3 hi) {
    vertex_accessors a;
    a.view = add_view(model, vertices.data(), vertices.size() * sizeof(Vertex), TINYGLTF_TARGET_ARRAY_BUFFER,
                      int(sizeof(Vertex)));
    a.position = add_accessor(model, a.view, offsetof(Vertex, position), vertices.size(),
                              TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
    model.accessors[std::size_t(a.position)].minValues = {lo.x, lo.y, lo.z};
    model.accessors[std::size_t(a.position)].maxValues = {hi.x, hi.y, hi.z};
    a.normal = add_accessor(model, a.view, offsetof(Vertex, normal), vertices.size(), TINYGLTF_COMPONENT_TYPE_FLOAT,
                            TINYGLTF_TYPE_VEC3);
    a.uv = add_accessor(model, a.view, offsetof(Vertex, uv), vertices.size(), TINYGLTF_COMPONENT_TYPE_FLOAT,
                        TINYGLTF_TYPE_VEC2);
    return a;
}

}  // namespace

void export_plant_glb(const plant_model& plant, plant_lod lod, const std::filesystem::path& file) {
    const mesh_data& mesh = plant.lods[std::size_t(lod)];
    if (mesh.indices.empty())
        throw std::invalid_argument(plant.name + ": this level has no triangles to export");
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "sylva";
    model.buffers.emplace_back();

    // The validator rejects normals that are not unit length. A model baked with Luft 2007's
    // illumination keeps k_a as its normals' length (models/bake/implicit_illumination.h): the
    // normals go out unit and k_a goes to COLOR_0 as a grey (k_a, k_a, k_a), which glTF viewers
    // multiply into the base colour, the ambient darkening the paper bakes.
    std::vector<vertex> vertices = mesh.vertices;
    const bool ambient = std::any_of(vertices.begin(), vertices.end(), carries_ambient);
    std::vector<glm::vec3> grey;
    glm::vec3 lo(vertices[0].position), hi(vertices[0].position);
    for (vertex& v : vertices) {
        const float len = glm::length(v.normal);
        if (ambient) grey.emplace_back(std::isfinite(len) ? std::clamp(len, 0.0f, 1.0f) : 1.0f);
        v.normal = std::isfinite(len) && len > 1e-6f ? v.normal / len : glm::vec3(0, 1, 0);
        lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
    }
    const auto [vertex_view, position, normal, uv] = add_vertex_accessors(model, vertices, lo, hi);
    int colour = -1;
    if (ambient) {
        const int view = add_view(model, grey.data(), grey.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
        colour = add_accessor(model, view, 0, grey.size(), TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3);
    }
    const int index_view = add_view(model, mesh.indices.data(), mesh.indices.size() * 4,
                                    TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);

    for (const bool leaf : {false, true}) {
        tinygltf::Material m;
        m.name = leaf ? "leaf" : "bark";
        m.pbrMetallicRoughness.baseColorTexture.index =
            leaf ? add_texture(model, or_white(plant.leaf_texture), "leaf",
                               TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE)
                 : add_texture(model, or_white(plant.bark_texture), "bark",
                               TINYGLTF_TEXTURE_WRAP_REPEAT);
        m.pbrMetallicRoughness.metallicFactor = 0.0;
        m.pbrMetallicRoughness.roughnessFactor = 1.0;
        m.alphaMode = leaf ? "MASK" : "OPAQUE";
        m.alphaCutoff = 0.5;
        m.doubleSided = leaf;
        model.materials.push_back(m);
    }

    tinygltf::Mesh out_mesh;
    out_mesh.name = plant.name;
    for (const submesh& s : mesh.submeshes) {
        if (s.index_count == 0) continue;
        tinygltf::Primitive p;
        p.attributes = {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}};
        if (colour >= 0) p.attributes["COLOR_0"] = colour;
        p.indices = add_accessor(model, index_view, std::size_t(s.first_index) * 4, s.index_count,
                                 TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR);
        p.material = s.material == material_kind::leaf ? 1 : 0;
        p.mode = TINYGLTF_MODE_TRIANGLES;
        out_mesh.primitives.push_back(p);
    }
    model.meshes.push_back(out_mesh);
    add_single_node_scene(model, plant.name);
    write_glb(model, file);
}

void export_billboard_cloud_glb(const billboard_cloud& cloud, const std::string& name,
                                const std::filesystem::path& file) {
    const mesh_data& mesh = cloud.mesh;
    if (mesh.indices.empty()) throw std::invalid_argument(name + ": the billboard cloud has no billboards to export");
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "sylva billboard cloud (Behrendt 2005)";
    model.buffers.emplace_back();

    // Interleaved position, normal, uv, tangent: each quad is flat, its tangent its axis_u
    // (the direction of growing s) and w = +1, so the bitangent cross(normal, tangent) is
    // its axis_v (toward the top row, glTF's "up" in the normal texture).
    struct cloud_vertex {
        glm::vec3 position, normal;
        glm::vec2 uv;
        glm::vec4 tangent;
    };
    static_assert(sizeof(cloud_vertex) == 48);
    std::vector<cloud_vertex> vertices(mesh.vertices.size());
    glm::vec3 lo(mesh.vertices[0].position), hi(lo);
    for (std::size_t q = 0; q + 3 < mesh.vertices.size(); q += 4) {
        const glm::vec3 t = glm::normalize(mesh.vertices[q + 1].position - mesh.vertices[q].position);
        for (std::size_t k = q; k < q + 4; ++k) {
            const vertex& v = mesh.vertices[k];
            vertices[k] = {v.position, glm::normalize(v.normal), v.uv, glm::vec4(t, 1.0f)};
            lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
        }
    }
    const auto [vertex_view, position, normal, uv] = add_vertex_accessors(model, vertices, lo, hi);
    const int tangent = add_accessor(model, vertex_view, offsetof(cloud_vertex, tangent), vertices.size(),
                                     TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4);
    const int index_view = add_view(model, mesh.indices.data(), mesh.indices.size() * 4,
                                    TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);

    image_rgba8 colour = cloud.page(cloud_atlas_page::albedo);
    const image_rgba8& coverage = cloud.page(cloud_atlas_page::normal);
    for (std::size_t i = 3; i < colour.texels.size(); i += 4) colour.texels[i] = coverage.texels[i];
    tinygltf::Material m;
    m.name = "billboard_cloud";
    m.pbrMetallicRoughness.baseColorTexture.index =
        add_texture(model, colour, "billboard_cloud_colour", TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE);
    m.normalTexture.index =
        add_texture(model, tangent_space_normal_page(cloud), "billboard_cloud_normal", TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE);
    m.pbrMetallicRoughness.metallicFactor = 0.0;
    m.pbrMetallicRoughness.roughnessFactor = 1.0;
    m.alphaMode = "MASK";
    m.alphaCutoff = 0.5;
    m.doubleSided = false;
    model.materials.push_back(m);

    tinygltf::Mesh out_mesh;
    out_mesh.name = name + "_billboard_cloud";
    tinygltf::Primitive p;
    p.attributes = {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}, {"TANGENT", tangent}};
    p.indices = add_accessor(model, index_view, 0, mesh.indices.size(), TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                             TINYGLTF_TYPE_SCALAR);
    p.material = 0;
    p.mode = TINYGLTF_MODE_TRIANGLES;
    out_mesh.primitives.push_back(p);
    model.meshes.push_back(out_mesh);
    add_single_node_scene(model, name);
    write_glb(model, file);
}

}  // namespace sylva
