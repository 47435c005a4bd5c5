#pragma once
// Small glTF files, written with tinygltf, that reproduce what real tree models from other tools
// do (and what broken files look like), for the importer's tests. Each writer puts its file(s)
// in `dir` and returns the path to import.
#include <cstdint>
#include <filesystem>
#include <string>

namespace sylva::test {

namespace fs = std::filesystem;

constexpr std::uint32_t k_fixture_leaf_cards = 200;  // per leaf primitive unless said otherwise
constexpr float k_fixture_trunk_height = 6.0f;       // metres

// Trunk + leaf cards whose texture has alpha but whose material says OPAQUE, single-sided;
// one node, textures embedded; .glb when `binary`, else .gltf with external .bin and PNGs.
fs::path write_opaque_leaves(const fs::path& dir, bool binary);
// 6 leaf materials (each its own tinted leaf texture) and 2 bark materials, in one node.
fs::path write_many_materials(const fs::path& dir);
// Trunk -> branch -> twig as nested nodes with meshes (a branch hierarchy the importer keeps).
fs::path write_branch_hierarchy(const fs::path& dir);
// The leaf texture file named by the .gltf does not exist; leaf material MASK, green factor.
fs::path write_missing_texture(const fs::path& dir);
// Authored in centimetres: geometry 600 units tall under a root node scaled by 0.01.
fs::path write_centimetres_scaled(const fs::path& dir);
// Authored in centimetres with no unit scale at all (600 units tall).
fs::path write_centimetres_unscaled(const fs::path& dir);
// Leaves with alphaMode BLEND, double-sided.
fs::path write_blend_leaves(const fs::path& dir);
// Bark texture an external JPEG; leaf uvs in the tile (2..3, -1..0) instead of 0..1.
fs::path write_jpeg_bark_and_tiled_leaf_uvs(const fs::path& dir);

// Broken files.
fs::path write_truncated_glb(const fs::path& dir);
fs::path write_missing_buffer(const fs::path& dir);   // .gltf whose .bin was deleted
fs::path write_lines_primitive(const fs::path& dir);  // mesh 'leaves' primitive 1 is LINES
fs::path write_nan_position(const fs::path& dir);     // mesh 'trunk' has a NaN vertex
// mesh 'trunk' primitive 1 has vertex k_fixture_infinite_vertex at x = +inf (or -inf).
constexpr std::uint32_t k_fixture_infinite_vertex = 7;
fs::path write_infinite_position(const fs::path& dir, bool negative);
// Finite vertices under a root node scaled by 1e38: the trunk's top overflows to +inf.
fs::path write_overflowing_scale(const fs::path& dir);
fs::path write_bad_json(const fs::path& dir);

// Degenerate but readable: the trunk primitive (mesh 'tree' primitive 0) carries
// k_fixture_zero_area_triangles extra triangles with no area (repeated indices, coincident and
// collinear vertices) next to its real ones; the leaves (primitive 1) have none.
constexpr std::uint32_t k_fixture_zero_area_triangles = 5;
fs::path write_zero_area_triangles(const fs::path& dir);
// mesh 'stick' has two triangles, both zero-area (collinear points, repeated index).
fs::path write_only_zero_area_triangles(const fs::path& dir);
fs::path write_draco_required(const fs::path& dir);  // extensionsRequired names Draco
fs::path write_no_meshes(const fs::path& dir);

}  // namespace sylva::test
