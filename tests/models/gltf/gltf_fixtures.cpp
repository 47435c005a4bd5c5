// The fixture writer: a tiny model builder over tinygltf plus procedural trunks, leaf cards and
// textures, so no binary test data is checked in.
#include "tests/models/gltf/gltf_fixtures.h"

#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "models/gltf/gltf_image_codec.h"
#include "models/gltf/gltf_tinygltf.h"
#include "models/random.h"
#include "models/generate/textures.h"

namespace sylva::test {
namespace {

struct geometry {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;
};

// A closed-sided cylinder standing on `base`: one connected component.
geometry cylinder(glm::vec3 base, float height, float radius, int sides = 12, int rings = 8) {
    geometry g;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= sides; ++s) {
            const float a = 6.2831853f * float(s) / float(sides);
            const float taper = 1.0f - 0.5f * float(r) / float(rings);
            g.positions.push_back(base + glm::vec3(std::cos(a) * radius * taper,
                                                   height * float(r) / float(rings),
                                                   std::sin(a) * radius * taper));
            g.normals.emplace_back(std::cos(a), 0.0f, std::sin(a));
            g.uvs.emplace_back(float(s) / float(sides),
                               4.0f * float(r) / float(rings));  // bark repeats along v
        }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < sides; ++s) {
            const auto i = std::uint32_t(r * (sides + 1) + s), j = i + std::uint32_t(sides + 1);
            g.indices.insert(g.indices.end(), {i, j, i + 1, i + 1, j, j + 1});
        }
    return g;
}

// Separate quads (two triangles each) scattered in a sphere: the typical foliage of a game tree.
geometry leaf_cards(glm::vec3 centre, float radius, std::uint32_t count, float size,
                    std::uint64_t seed) {
    geometry g;
    rng random(seed);
    for (std::uint32_t c = 0; c < count; ++c) {
        const glm::vec3 p =
            centre + radius * glm::vec3(random.uniform(-1.0f, 1.0f), random.uniform(-1.0f, 1.0f),
                                        random.uniform(-1.0f, 1.0f));
        const glm::vec3 n = glm::normalize(
            glm::vec3(random.uniform(-1.0f, 1.0f), 1.0f, random.uniform(-1.0f, 1.0f)));
        const glm::vec3 t = glm::normalize(glm::cross(n, glm::vec3(0.0f, 0.0f, 1.0f)));
        const glm::vec3 b = glm::cross(t, n);
        const auto base = std::uint32_t(g.positions.size());
        const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (const glm::vec2 uv : corners) {
            g.positions.push_back(p + size * ((uv.x - 0.5f) * t + (uv.y - 0.5f) * b));
            g.normals.push_back(n);
            g.uvs.push_back(uv);
        }
        g.indices.insert(g.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return g;
}

// A leaf: an ellipse, opaque inside, transparent outside (about 55 % of texels cut away).
image_rgba8 leaf_image(glm::vec3 tint) {
    image_rgba8 image{64, 64, std::vector<std::uint8_t>(64 * 64 * 4)};
    for (std::uint32_t y = 0; y < 64; ++y)
        for (std::uint32_t x = 0; x < 64; ++x) {
            const float u = (float(x) + 0.5f) / 32.0f - 1.0f, v = (float(y) + 0.5f) / 32.0f - 1.0f;
            const bool inside = (u * u) / 0.16f + v * v < 1.0f;
            std::uint8_t* t = image.at(x, y);
            t[0] = std::uint8_t(tint.r * 255.0f), t[1] = std::uint8_t(tint.g * 255.0f),
            t[2] = std::uint8_t(tint.b * 255.0f);
            t[3] = inside ? 255 : 0;
        }
    return image;
}

image_rgba8 bark_image() {
    image_rgba8 image{32, 32, std::vector<std::uint8_t>(32 * 32 * 4)};
    for (std::uint32_t i = 0; i < 32 * 32; ++i) {
        const auto stripe = std::uint8_t((i % 32) % 4 == 0 ? 20 : 0);
        image.texels[4 * i] = std::uint8_t(110 - stripe),
                         image.texels[4 * i + 1] = std::uint8_t(80 - stripe);
        image.texels[4 * i + 2] = std::uint8_t(55 - stripe), image.texels[4 * i + 3] = 255;
    }
    return image;
}

enum class storage { embedded, external, external_jpeg, missing };

class model_builder {
public:
    model_builder() {
        m_model.asset.version = "2.0";
        m_model.buffers.emplace_back();
        m_model.scenes.emplace_back();
        m_model.defaultScene = 0;
    }

    int material(const std::string& name, const image_rgba8* texture, glm::vec4 factor,
                 const std::string& mode, bool double_sided, storage where = storage::embedded) {
        tinygltf::Material m;
        m.name = name;
        m.pbrMetallicRoughness.baseColorFactor = {factor.r, factor.g, factor.b, factor.a};
        m.alphaMode = mode;
        m.doubleSided = double_sided;
        if (texture) {
            tinygltf::Image image;
            image.name = name;
            if (where == storage::embedded) {
                const std::vector<std::uint8_t> png = encode_png(*texture);
                image.mimeType = "image/png";
                image.bufferView = view(png.data(), png.size(), 0);
            } else {
                image.uri = name + (where == storage::external_jpeg ? ".jpg" : ".png");
                if (where != storage::missing) m_external_images.emplace_back(image.uri, *texture);
            }
            m_model.images.push_back(image);
            tinygltf::Texture t;
            t.source = int(m_model.images.size() - 1);
            m_model.textures.push_back(t);
            m.pbrMetallicRoughness.baseColorTexture.index = int(m_model.textures.size() - 1);
        }
        m_model.materials.push_back(m);
        return int(m_model.materials.size() - 1);
    }

    void primitive(const std::string& mesh_name, const geometry& g, int material,
                   int mode = TINYGLTF_MODE_TRIANGLES) {
        if (m_model.meshes.empty() || m_model.meshes.back().name != mesh_name) {
            m_model.meshes.emplace_back();
            m_model.meshes.back().name = mesh_name;
        }
        tinygltf::Primitive p;
        p.attributes["POSITION"] =
            accessor(g.positions.data(), g.positions.size(), TINYGLTF_TYPE_VEC3, true);
        p.attributes["NORMAL"] =
            accessor(g.normals.data(), g.normals.size(), TINYGLTF_TYPE_VEC3, false);
        p.attributes["TEXCOORD_0"] =
            accessor(g.uvs.data(), g.uvs.size(), TINYGLTF_TYPE_VEC2, false);
        tinygltf::Accessor a;
        a.bufferView =
            view(g.indices.data(), g.indices.size() * 4, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
        a.count = g.indices.size();
        a.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        a.type = TINYGLTF_TYPE_SCALAR;
        m_model.accessors.push_back(a);
        p.indices = int(m_model.accessors.size() - 1);
        p.material = material;
        p.mode = mode;
        m_model.meshes.back().primitives.push_back(p);
    }

    // A node holding the last mesh (or none); parent -1 makes it a scene root.
    int node(int parent, bool with_mesh, float scale = 1.0f) {
        tinygltf::Node n;
        n.name = "node " +
                 std::to_string(m_model.nodes.size());  // tinygltf writes an empty node as null
        if (with_mesh) n.mesh = int(m_model.meshes.size() - 1);
        if (scale != 1.0f) n.scale = {scale, scale, scale};
        m_model.nodes.push_back(n);
        const int index = int(m_model.nodes.size() - 1);
        if (parent < 0)
            m_model.scenes[0].nodes.push_back(index);
        else
            m_model.nodes[std::size_t(parent)].children.push_back(index);
        return index;
    }

    fs::path write(const fs::path& dir, const std::string& stem, bool binary) {
        fs::create_directories(dir);
        for (const auto& [uri, image] : m_external_images) write_image(image, dir / uri);
        const fs::path file = dir / (stem + (binary ? ".glb" : ".gltf"));
        if (m_model.buffers[0].data.empty())
            m_model.buffers.clear();
        else if (!binary)
            m_model.buffers[0].uri = stem + ".bin";
        tinygltf::TinyGLTF writer = make_gltf_loader();
        if (!writer.WriteGltfSceneToFile(&m_model, file.string(), false, binary, true, binary))
            throw std::runtime_error("cannot write the fixture " + file.string());
        return file;
    }

    tinygltf::Model& model() { return m_model; }

private:
    int view(const void* data, std::size_t size, int target) {
        auto& buffer = m_model.buffers[0].data;
        buffer.resize((buffer.size() + 3) / 4 * 4, 0);
        tinygltf::BufferView v;
        v.buffer = 0;
        v.byteOffset = buffer.size();
        v.byteLength = size;
        v.target = target;
        const auto* bytes = static_cast<const unsigned char*>(data);
        buffer.insert(buffer.end(), bytes, bytes + size);
        m_model.bufferViews.push_back(v);
        return int(m_model.bufferViews.size() - 1);
    }

    template <typename T>
    int accessor(const T* data, std::size_t count, int type, bool bounds) {
        tinygltf::Accessor a;
        a.bufferView = view(data, count * sizeof(T), TINYGLTF_TARGET_ARRAY_BUFFER);
        a.count = count;
        a.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
        a.type = type;
        if constexpr (std::is_same_v<T, glm::vec3>)
            if (bounds && count) {
                glm::vec3 lo(std::numeric_limits<float>::max()),
                    hi(-std::numeric_limits<float>::max());
                for (std::size_t i = 0; i < count; ++i)  // over finite values: JSON has no inf
                    if (std::isfinite(data[i].x) && std::isfinite(data[i].y) &&
                        std::isfinite(data[i].z))
                        lo = glm::min(lo, glm::vec3(data[i])), hi = glm::max(hi, glm::vec3(data[i]));
                a.minValues = {lo.x, lo.y, lo.z};
                a.maxValues = {hi.x, hi.y, hi.z};
            }
        m_model.accessors.push_back(a);
        return int(m_model.accessors.size() - 1);
    }

    tinygltf::Model m_model;
    std::vector<std::pair<std::string, image_rgba8>> m_external_images;
};

const glm::vec3 k_leaf_green{0.25f, 0.55f, 0.15f};
const glm::vec3 k_crown{0.0f, 5.0f, 0.0f};

// Trunk + crown in one node, the leaf material as given.
fs::path simple_tree(const fs::path& dir, const std::string& stem, bool binary,
                     const std::string& leaf_mode, bool double_sided, storage where,
                     float unit = 1.0f, float root_scale = 1.0f) {
    model_builder b;
    const image_rgba8 bark = bark_image(), leaf = leaf_image(k_leaf_green);
    const int bark_material = b.material("bark", &bark, glm::vec4(1.0f), "OPAQUE", false,
                                         where == storage::missing ? storage::embedded : where);
    const int leaf_material =
        b.material("leaves", &leaf, glm::vec4(1.0f), leaf_mode, double_sided, where);
    geometry trunk = cylinder(glm::vec3(0.0f), k_fixture_trunk_height * unit, 0.2f * unit);
    geometry crown = leaf_cards(k_crown * unit, 1.5f * unit, k_fixture_leaf_cards, 0.3f * unit, 7);
    b.primitive("tree", trunk, bark_material);
    b.primitive("tree", crown, leaf_material);
    b.node(-1, true, root_scale);
    return b.write(dir, stem, binary);
}

void truncate_file(const fs::path& file, std::uintmax_t size) {
    fs::resize_file(file, size);
}

}  // namespace

fs::path write_opaque_leaves(const fs::path& dir, bool binary) {
    return simple_tree(dir, binary ? "opaque_leaves" : "opaque_leaves_external", binary, "OPAQUE",
                       false, binary ? storage::embedded : storage::external);
}

fs::path write_many_materials(const fs::path& dir) {
    model_builder b;
    const image_rgba8 bark = bark_image();
    b.primitive("trunk", cylinder(glm::vec3(0.0f), k_fixture_trunk_height, 0.2f),
                b.material("bark_trunk", &bark, glm::vec4(1.0f), "OPAQUE", false));
    b.primitive(
        "trunk", cylinder(glm::vec3(0.0f, 3.0f, 0.0f), 2.0f, 0.08f),
        b.material("bark_branch", &bark, glm::vec4(0.8f, 0.8f, 0.8f, 1.0f), "OPAQUE", false));
    for (int i = 0; i < 6; ++i) {
        const image_rgba8 leaf =
            leaf_image(k_leaf_green + glm::vec3(0.05f * float(i), 0.04f * float(i), 0.0f));
        const int material = b.material("leaves_" + std::to_string(i), &leaf, glm::vec4(1.0f),
                                        i % 2 ? "MASK" : "OPAQUE", true);
        b.primitive("trunk", leaf_cards(k_crown, 1.5f, 40, 0.3f, std::uint64_t(100 + i)), material);
    }
    b.node(-1, true);
    return b.write(dir, "many_materials", true);
}

fs::path write_branch_hierarchy(const fs::path& dir) {
    model_builder b;
    const image_rgba8 bark = bark_image(), leaf = leaf_image(k_leaf_green);
    const int bark_material = b.material("bark", &bark, glm::vec4(1.0f), "OPAQUE", false);
    const int leaf_material = b.material("leaves", &leaf, glm::vec4(1.0f), "MASK", true);
    b.primitive("trunk", cylinder(glm::vec3(0.0f), k_fixture_trunk_height, 0.2f), bark_material);
    const int trunk = b.node(-1, true);
    b.primitive("branch", cylinder(glm::vec3(0.0f, 3.0f, 0.0f), 2.0f, 0.08f), bark_material);
    const int branch = b.node(trunk, true);
    b.primitive("twig", leaf_cards(k_crown, 1.5f, k_fixture_leaf_cards, 0.3f, 9), leaf_material);
    b.node(branch, true);
    return b.write(dir, "branch_hierarchy", true);
}

fs::path write_missing_texture(const fs::path& dir) {
    model_builder b;
    const image_rgba8 bark = bark_image(), leaf = leaf_image(k_leaf_green);
    b.primitive("tree", cylinder(glm::vec3(0.0f), k_fixture_trunk_height, 0.2f),
                b.material("bark", &bark, glm::vec4(1.0f), "OPAQUE", false));
    b.primitive("tree", leaf_cards(k_crown, 1.5f, k_fixture_leaf_cards, 0.3f, 7),
                b.material("missing_leaf", &leaf, glm::vec4(k_leaf_green, 1.0f), "MASK", true,
                           storage::missing));
    b.node(-1, true);
    return b.write(dir, "missing_texture", false);
}

fs::path write_centimetres_scaled(const fs::path& dir) {
    return simple_tree(dir, "centimetres_scaled", true, "MASK", true, storage::embedded, 100.0f,
                       0.01f);
}

fs::path write_centimetres_unscaled(const fs::path& dir) {
    return simple_tree(dir, "centimetres_unscaled", true, "MASK", true, storage::embedded, 100.0f,
                       1.0f);
}

fs::path write_blend_leaves(const fs::path& dir) {
    return simple_tree(dir, "blend_leaves", false, "BLEND", true, storage::embedded);
}

fs::path write_jpeg_bark_and_tiled_leaf_uvs(const fs::path& dir) {
    model_builder b;
    const image_rgba8 bark = bark_image(), leaf = leaf_image(k_leaf_green);
    geometry crown = leaf_cards(k_crown, 1.5f, k_fixture_leaf_cards, 0.3f, 7);
    for (glm::vec2& uv : crown.uvs) uv += glm::vec2(2.0f, -1.0f);
    b.primitive(
        "tree", cylinder(glm::vec3(0.0f), k_fixture_trunk_height, 0.2f),
        b.material("bark", &bark, glm::vec4(1.0f), "OPAQUE", false, storage::external_jpeg));
    b.primitive("tree", crown,
                b.material("leaves", &leaf, glm::vec4(1.0f), "MASK", true, storage::external));
    b.node(-1, true);
    return b.write(dir, "jpeg_bark", false);
}

fs::path write_truncated_glb(const fs::path& dir) {
    const fs::path file = simple_tree(dir, "truncated", true, "MASK", true, storage::embedded);
    truncate_file(file, fs::file_size(file) / 2);
    return file;
}

fs::path write_missing_buffer(const fs::path& dir) {
    const fs::path file =
        simple_tree(dir, "missing_buffer", false, "MASK", true, storage::embedded);
    fs::remove(dir / "missing_buffer.bin");
    return file;
}

fs::path write_lines_primitive(const fs::path& dir) {
    model_builder b;
    const image_rgba8 leaf = leaf_image(k_leaf_green);
    const int material = b.material("leaves", &leaf, glm::vec4(1.0f), "MASK", true);
    b.primitive("leaves", leaf_cards(k_crown, 1.5f, 10, 0.3f, 7), material);
    b.primitive("leaves", leaf_cards(k_crown, 1.5f, 10, 0.3f, 8), material, TINYGLTF_MODE_LINE);
    b.node(-1, true);
    return b.write(dir, "lines", false);
}

fs::path write_nan_position(const fs::path& dir) {
    model_builder b;
    geometry trunk = cylinder(glm::vec3(0.0f), k_fixture_trunk_height, 0.2f);
    trunk.positions[5].y = std::numeric_limits<float>::quiet_NaN();
    b.primitive("trunk", trunk, -1);
    b.node(-1, true);
    return b.write(dir, "nan_position", true);
}

fs::path write_infinite_position(const fs::path& dir, bool negative) {
    model_builder b;
    geometry trunk = cylinder(glm::vec3(0.0f), k_fixture_trunk_height, 0.2f);
    trunk.positions[k_fixture_infinite_vertex].x =
        negative ? -std::numeric_limits<float>::infinity() : std::numeric_limits<float>::infinity();
    b.primitive("trunk", cylinder(glm::vec3(0.0f, 3.0f, 0.0f), 2.0f, 0.08f), -1);
    b.primitive("trunk", trunk, -1);
    b.node(-1, true);
    return b.write(dir, negative ? "minus_infinity" : "plus_infinity", true);
}

// Appends k_fixture_zero_area_triangles triangles with no area to `g`: repeated indices,
// three coincident vertices, and three exactly collinear vertices (p, p + d, p + 2d in
// binary fractions, so the points are collinear in float too) in both orders.
void add_zero_area_triangles(geometry& g) {
    const auto first = std::uint32_t(g.positions.size());
    const glm::vec3 p{0.5f, 1.25f, -0.75f}, d{0.25f, 0.5f, 0.125f};
    for (const glm::vec3 q : {p, p, p, p + d, p + 2.0f * d}) {
        g.positions.push_back(q);
        g.normals.emplace_back(0.0f, 1.0f, 0.0f);
        g.uvs.emplace_back(0.5f, 0.5f);
    }
    g.indices.insert(g.indices.end(), {0, 0, 1,                          // repeated index
                                       2, 3, 3,                          // repeated index
                                       first, first + 1, first + 2,      // coincident points
                                       first, first + 3, first + 4,      // collinear
                                       first + 4, first, first + 3});    // collinear, reordered
}

fs::path write_zero_area_triangles(const fs::path& dir) {
    model_builder b;
    const image_rgba8 bark = bark_image(), leaf = leaf_image(k_leaf_green);
    geometry trunk = cylinder(glm::vec3(0.0f), k_fixture_trunk_height, 0.2f);
    add_zero_area_triangles(trunk);
    b.primitive("tree", trunk, b.material("bark", &bark, glm::vec4(1.0f), "OPAQUE", false));
    b.primitive("tree", leaf_cards(k_crown, 1.5f, k_fixture_leaf_cards, 0.3f, 7),
                b.material("leaves", &leaf, glm::vec4(1.0f), "MASK", true));
    b.node(-1, true);
    return b.write(dir, "zero_area", true);
}

fs::path write_only_zero_area_triangles(const fs::path& dir) {
    model_builder b;
    geometry g;
    g.positions = {{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {0.0f, 2.0f, 0.0f}};
    g.normals.assign(3, glm::vec3(1.0f, 0.0f, 0.0f));
    g.uvs.assign(3, glm::vec2(0.0f));
    g.indices = {0, 1, 2, 0, 0, 2};
    b.primitive("stick", g, -1);
    b.node(-1, true);
    return b.write(dir, "only_zero_area", false);
}

fs::path write_overflowing_scale(const fs::path& dir) {
    model_builder b;
    b.primitive("trunk", cylinder(glm::vec3(0.0f), k_fixture_trunk_height, 0.2f), -1);
    b.node(-1, true, 1e38f);  // 6 m x 1e38 is beyond the largest float (3.4e38)
    return b.write(dir, "overflowing_scale", true);
}

fs::path write_bad_json(const fs::path& dir) {
    fs::create_directories(dir);
    const fs::path file = dir / "bad_json.gltf";
    std::ofstream(file) << R"({"asset": {"version": "2.0"}, "meshes": [ {"primitives": )";
    return file;
}

fs::path write_draco_required(const fs::path& dir) {
    model_builder b;
    b.primitive("trunk", cylinder(glm::vec3(0.0f), k_fixture_trunk_height, 0.2f), -1);
    b.node(-1, true);
    b.model().extensionsUsed = {"KHR_draco_mesh_compression"};
    b.model().extensionsRequired = {"KHR_draco_mesh_compression"};
    return b.write(dir, "draco", false);
}

fs::path write_no_meshes(const fs::path& dir) {
    model_builder b;
    b.node(-1, false);
    return b.write(dir, "no_meshes", false);
}

}  // namespace sylva::test
