#pragma once
// The terrain: a square heightfield centred on the origin, generated from fBm gradient noise or
// read from a heightmap image, and the grid meshes the renderer draws for it (whole or in tiles).
#include <cstdint>
#include <filesystem>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "models/mesh.h"

namespace sylva {

struct heightfield {
    std::uint32_t resolution = 0;  // vertices per side (>= 2)
    double size_m = 0.0;           // side length; spans [-size/2, size/2] in x and z
    std::vector<float> heights;    // row-major: z rows, x columns, resolution^2
    float min_height = 0.0f;
    float max_height = 0.0f;

    double spacing() const { return size_m / double(resolution - 1); }
    float at(std::uint32_t column, std::uint32_t row) const {
        return heights[std::size_t(row) * resolution + column];
    }
    // Bilinear height at world x, z (metres from the centre); clamped to the edge outside.
    float height_at(double x, double z) const;
    // Unit surface normal of the bilinear surface (central differences of height_at).
    glm::vec3 normal_at(double x, double z) const;
    // Angle between the surface and the horizontal plane, degrees.
    float slope_deg_at(double x, double z) const;
};

// fBm of gradient noise (Perlin 2002; Musgrave's fBm), `frequency` in cycles per metre for the
// first octave, heights within about ±height_m/2 (height_m is the peak-to-valley scale).
heightfield generate_terrain(double size_m, std::uint32_t resolution, float height_m,
                             std::uint32_t octaves, float frequency, std::uint64_t seed);

// One vertex per height sample, smooth normals, one material_kind::ground sub-mesh; positions
// relative to the terrain centre; uv = world xz / uv_scale_m (the texture repeats every
// uv_scale_m metres).
mesh_data terrain_mesh(const heightfield& field, float uv_scale_m);

// A heightmap image as a heightfield of size_m metres centred on the origin: one sample per
// pixel (resolution = the image side), image row 0 at z = -size_m/2, column 0 at x = -size_m/2.
// A 16-bit PNG maps 0..65535 to 0..height_m; an EXR (or any float image) maps 0..1 to
// 0..height_m. Only the first channel is read (grey, or R of RGB/RGBA). The image must be
// square and at least 2x2. Throws std::runtime_error naming the file (missing, unreadable,
// not square: "... is 300x200 pixels; heightmaps must be square").
heightfield load_heightmap(const std::filesystem::path& path, double size_m, float height_m);

// The terrain_mesh split into tiles_per_side^2 square tiles (row-major: z rows, x columns), for
// culling the ground per tile. Tiles split the grid's cells; neighbouring tiles repeat the
// vertices of their common edge with identical positions, normals and uvs (computed from the
// same samples), so the surface has no cracks. Each tile's bounds are its own. tiles_per_side
// is clamped to 1 .. resolution-1 (a tile holds at least one cell). Together the tiles have
// exactly the triangles of terrain_mesh.
//
// With `stride` > 1 the same tiles on a coarser grid, every stride-th sample of each tile and its
// last (so tiles of one stride share their edges; where strides differ the edges meet at
// T-junctions), for far surfaces that need not follow every sample (the shells' slices,
// systems/render/passes/shell_pass.h). Throws std::invalid_argument for stride 0.
std::vector<mesh_data> terrain_tile_meshes(const heightfield& field, std::uint32_t tiles_per_side,
                                           float uv_scale_m, std::uint32_t stride = 1);

// Skirts for terrain_tile_meshes(field, tiles_per_side, uv_scale_m, stride), by tile: on each
// side of the tile inside the terrain, a vertical strip hanging depth_m[tile] below the tile's
// edge at that stride, facing out of the tile, with the edge's normals and uvs (it shows as
// ground). Where neighbouring tiles are drawn at different strides their edges part at
// T-junctions; the higher edge's skirt fills the crack when it reaches below the lower edge
// (the skirts of Ulrich 2002's chunked LOD, cheaper than stitching index buffers per neighbour
// level; systems/select_ground_grid_system.h chooses the strides). Sides on the terrain's border
// get none, so a terrain of one tile gets empty meshes, as does a tile whose depth is 0 (a flat
// terrain, whose edges cannot part). Throws std::invalid_argument for stride
// 0 or fewer depths than tiles.
std::vector<mesh_data> terrain_tile_skirts(const heightfield& field, std::uint32_t tiles_per_side,
                                           float uv_scale_m, std::uint32_t stride,
                                           std::span<const float> depth_m);

// By tile (terrain_tile_meshes order), the largest vertical distance between a height sample
// and that tile's grid at `stride`: how far the coarse surface strays from the terrain.
std::vector<float> terrain_tile_errors(const heightfield& field, std::uint32_t tiles_per_side, std::uint32_t stride);

}  // namespace sylva
