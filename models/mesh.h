#pragma once
// CPU-side meshes as produced by the generators (and later the glTF importer): one interleaved
// vertex array, one index array, and sub-meshes that each use one material.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace sylva {

// Mirrored by the vertex input layout in shaders/common.glsl (locations 0..2).
struct vertex {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec2 uv{0.0f};
};
static_assert(sizeof(vertex) == 32);

// How a material is shaded; the renderer picks its pipeline from this.
enum class material_kind : std::uint8_t {
    bark,    // opaque, textured
    leaf,    // alpha-tested (discard below 0.5), double-sided, translucent-ish diffuse
    ground,  // opaque terrain, tiled texture
    // A baked billboard (models/bake/crossed_billboard.h): alpha-tested (discard below 0.5),
    // double-sided, normal-mapped; shaded like leaves with the normal from its normal map.
    billboard,
    // A billboard-cloud quad (models/bake/billboard_cloud.h, Behrendt 2005 §2.3): one-sided (drawn
    // with back faces culled; each side of a billboard is its own quad), coverage alpha-tested
    // from the normal page and faded by a distance threshold on the gaussian colour alpha.
    // Appended last so serialized meshes keep the values above.
    billboard_cloud,
    // A crossed billboard whose vertex shader turns one quad to face the eye and collapses the
    // other (shaders/instance.glsl face_the_eye); otherwise drawn as `billboard`.
    facing_billboard,
};

// A baked billboard's images on quads: the crossed pair, or the pair with one quad facing the eye.
constexpr bool is_billboard(material_kind m) {
    return m == material_kind::billboard || m == material_kind::facing_billboard;
}

// How a mesh's indices are read: triangle lists for every model mesh; point and line lists for
// the point/line representation (models/bake/point_line_model.h), assembled when a scene is built.
enum class primitive_kind : std::uint8_t { triangles, points, lines };

struct submesh {
    std::uint32_t first_index = 0;
    std::uint32_t index_count = 0;
    material_kind material = material_kind::bark;
};

// What a triangle belongs to (DESIGN §4): representations that cluster by branch, draw long thin
// parts as lines or reduce by importance read this instead of guessing from geometry.
enum class part_kind : std::uint8_t {
    bark,    // a stem's tube
    leaf,    // a broad leaf card
    needle,  // a needle-shoot card (conifers): long thin parts
    blade,   // a grass blade strip: long thin parts
    petal,   // a blossom part: visually important, keep under reduction
    frond,   // a fern pinna card
};

// Per triangle: `branch` is the stem index in the plant's skeleton (for foliage, the stem that
// carries it), `level` its recursion level (trunk or ground stem 0; foliage one more than its
// stem), `parent_branch` the stem that `branch` grows from (a stem from the ground names
// itself). Foliage thus records its stem's parent too, which keeps a stem that has no bark
// triangles (the finest twigs) linked into the hierarchy.
struct triangle_part {
    std::uint32_t branch = 0;
    std::uint8_t level = 0;
    part_kind kind = part_kind::bark;
    std::uint32_t parent_branch = 0;
};

// One per foliage element (leaf card, needle shoot, blade, petal, pinna): where it is, which
// way its front faces, its longest extent in metres and the stem that carries it.
struct leaf_record {
    glm::vec3 center{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    float size = 0.0f;
    std::uint32_t parent_branch = 0;
    part_kind kind = part_kind::leaf;
};

// A vertex's precomputed radiance transfer (Behrendt 2005 §4, models/bake/radiance_transfer.h) as the
// renderer streams it: 9 SH coefficients for light on the side the normal faces, then 9 for the
// other side, as IEEE half floats (2 bands: coefficients 4..8 are zero), 2 halves of padding.
// Mirrored by the transfer attributes in shaders/surface.vert (locations 5..9).
struct vertex_transfer {
    std::uint16_t half[20] = {};
};
static_assert(sizeof(vertex_transfer) == 40);

struct mesh_data {
    std::vector<vertex> vertices;
    std::vector<std::uint32_t> indices;  // triangle list
    std::vector<submesh> submeshes;
    glm::vec3 bounds_min{0.0f};
    glm::vec3 bounds_max{0.0f};
    std::vector<triangle_part> parts;  // one per triangle, empty when unknown
    std::vector<leaf_record> leaves;   // one per foliage element, empty when unknown
    // Not serialised (models/cache/mesh_io.h): every cached mesh is a triangle list.
    primitive_kind primitive = primitive_kind::triangles;
    // Not serialised either (the transfer bake has its own cache entry): one per vertex when the
    // mesh is lit by precomputed radiance transfer, else empty.
    std::vector<vertex_transfer> transfer;

    std::size_t triangle_count() const { return indices.size() / 3; }
};

}  // namespace sylva
