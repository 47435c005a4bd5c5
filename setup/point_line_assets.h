#pragma once
// Puts a species' point/line representation (models/bake/point_line_model.h) into a scene: for every
// part of the plant, a mesh of its triangles in their random order and a mesh of its points or
// lines, each drawn by prefix, and the part's entry in species_library::lod_parts, scaled to the
// species' size. Only scenes whose LOD policy can select the representation call this.
#include "models/bake/point_line_model.h"
#include "resources/scene_assets.h"

namespace sylva {

// `scale` is the species' model-to-world scale (height_m over the model's height).
// `importance` multiplies every part's baked importance (the species' user factor, §4.3).
// `transfer` (optional, precomputed radiance transfer, models/mesh.h vertex_transfer): one record
// per vertex of model.triangles, of model.points and of model.lines; the part meshes take theirs.
struct point_line_records {
    std::vector<vertex_transfer> triangles;
    std::vector<vertex_transfer> points;
    std::vector<vertex_transfer> lines;
};
void add_point_line_parts(scene_assets& assets, species_entry& entry, const point_line_model& model,
                          float scale, float importance,
                          const point_line_records* transfer = nullptr);

// The triangles [first_index, first_index + index_count) of `mesh` as a mesh of their own, with
// only the vertices they use (the order of the triangles kept), and their transfer records when
// `mesh` has them.
mesh_data extract_triangles(const mesh_data& mesh, std::uint32_t first_index, std::uint32_t index_count,
                            material_kind material);

// A mesh that lists `vertices` in order as points (one index each) or lines (two each).
// `transfer`: none, or one record per vertex.
mesh_data primitive_mesh(std::vector<vertex> vertices, primitive_kind primitive,
                         material_kind material, std::vector<vertex_transfer> transfer = {});

// Adds a point or line mesh drawn by prefix (drawn_as points, `primitives` of them) to the scene
// and returns its id; throws when the scene would pass the 65,535 meshes a sort key can name.
std::uint16_t add_sample_mesh(scene_assets& assets, mesh_data mesh, std::uint32_t primitives);

}  // namespace sylva
