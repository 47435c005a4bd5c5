#include "models/terrain/terrain.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "io/input_file.h"
#include "models/noise.h"

namespace sylva {
namespace {

constexpr double k_rad_to_deg = 57.295779513082320876;

// Continuous grid coordinate (0 .. resolution-1) of a world coordinate, clamped to the field.
double grid_coordinate(const heightfield& f, double world) {
    const double g = (world + 0.5 * f.size_m) / f.spacing();
    return std::clamp(g, 0.0, double(f.resolution - 1));
}

struct gradient {
    double dx;  // dh/dx
    double dz;  // dh/dz
};

// Central differences over one grid spacing: the slope a walker feels at the scale the terrain
// is sampled at. The sample points are clamped to the field and the difference divided by their
// actual distance, so at the border it becomes a one-sided difference instead of halving.
gradient gradient_at(const heightfield& f, double x, double z) {
    const double half = 0.5 * f.size_m;
    const double h = 0.5 * f.spacing();
    const double x0 = std::max(x - h, -half);
    const double x1 = std::min(x + h, half);
    const double z0 = std::max(z - h, -half);
    const double z1 = std::min(z + h, half);
    const double cx = std::clamp(x, -half, half);
    const double cz = std::clamp(z, -half, half);
    return {(double(f.height_at(x1, cz)) - double(f.height_at(x0, cz))) / std::max(x1 - x0, 1e-12),
            (double(f.height_at(cx, z1)) - double(f.height_at(cx, z0))) / std::max(z1 - z0, 1e-12)};
}

void validate(double size_m, std::uint32_t resolution) {
    if (resolution < 2) throw std::invalid_argument("generate_terrain: resolution must be >= 2");
    if (!(size_m > 0.0)) throw std::invalid_argument("generate_terrain: size_m must be > 0");
}

}  // namespace

float heightfield::height_at(double x, double z) const {
    const double gx = grid_coordinate(*this, x);
    const double gz = grid_coordinate(*this, z);
    const auto c0 = std::min(static_cast<std::uint32_t>(gx), resolution - 2);
    const auto r0 = std::min(static_cast<std::uint32_t>(gz), resolution - 2);
    const double fx = gx - c0;
    const double fz = gz - r0;
    const double top = at(c0, r0) + (double(at(c0 + 1, r0)) - at(c0, r0)) * fx;
    const double bottom = at(c0, r0 + 1) + (double(at(c0 + 1, r0 + 1)) - at(c0, r0 + 1)) * fx;
    return static_cast<float>(top + (bottom - top) * fz);
}

glm::vec3 heightfield::normal_at(double x, double z) const {
    const gradient g = gradient_at(*this, x, z);
    // Normal of the surface y = h(x, z) is (-dh/dx, 1, -dh/dz), normalised.
    return glm::normalize(glm::vec3(float(-g.dx), 1.0f, float(-g.dz)));
}

float heightfield::slope_deg_at(double x, double z) const {
    const gradient g = gradient_at(*this, x, z);
    return static_cast<float>(std::atan(std::hypot(g.dx, g.dz)) * k_rad_to_deg);
}

heightfield generate_terrain(double size_m, std::uint32_t resolution, float height_m,
                             std::uint32_t octaves, float frequency, std::uint64_t seed) {
    validate(size_m, resolution);
    heightfield f;
    f.resolution = resolution;
    f.size_m = size_m;
    f.heights.resize(std::size_t(resolution) * resolution);
    const fbm_settings settings{std::max(octaves, 1u), 2.0, 0.5f, 0};
    const double spacing = f.spacing();
    const double half = 0.5 * size_m;
    for (std::uint32_t row = 0; row < resolution; ++row) {
        for (std::uint32_t column = 0; column < resolution; ++column) {
            // World-space coordinates, so a terrain of another resolution is the same landscape.
            const double x = (column * spacing - half) * frequency;
            const double z = (row * spacing - half) * frequency;
            f.heights[std::size_t(row) * resolution + column] = 0.5f * height_m * fbm(x, z, seed, settings);
        }
    }
    const auto [lo, hi] = std::minmax_element(f.heights.begin(), f.heights.end());
    f.min_height = *lo;
    f.max_height = *hi;
    return f;
}

namespace {

// The grid mesh over vertex columns [c0, c1] and rows [r0, r1] (inclusive). Every vertex is a
// function of (field, column, row) only, so two grids sharing an edge repeat it bit for bit.
// The samples a grid over [first, last] at `stride` uses: every stride-th from the first, and the
// last (so neighbouring grids of one stride share their edge).
std::vector<std::uint32_t> grid_samples(std::uint32_t first, std::uint32_t last, std::uint32_t stride) {
    std::vector<std::uint32_t> samples;
    for (std::uint32_t i = first; i < last; i += stride) samples.push_back(i);
    samples.push_back(last);
    return samples;
}

// The grid vertex of sample (column, row): every grid and skirt repeats it bit for bit.
vertex grid_vertex(const heightfield& field, std::uint32_t column, std::uint32_t row,
                   float uv_per_m) {
    const double x = column * field.spacing() - 0.5 * field.size_m;
    const double z = row * field.spacing() - 0.5 * field.size_m;
    vertex v;
    v.position = glm::vec3(float(x), field.at(column, row), float(z));
    v.normal = field.normal_at(x, z);
    v.uv = glm::vec2(float(x) * uv_per_m, float(z) * uv_per_m);
    return v;
}

float uv_per_metre(float uv_scale_m) {
    return uv_scale_m > 0.0f ? 1.0f / uv_scale_m : 1.0f;
}

mesh_data grid_mesh(const heightfield& field, std::uint32_t c0, std::uint32_t c1, std::uint32_t r0,
                    std::uint32_t r1, float uv_scale_m, std::uint32_t stride = 1) {
    const float uv_per_m = uv_per_metre(uv_scale_m);
    const std::vector<std::uint32_t> column_samples = grid_samples(c0, c1, stride);
    const std::vector<std::uint32_t> row_samples = grid_samples(r0, r1, stride);
    const auto columns = std::uint32_t(column_samples.size());
    const auto rows = std::uint32_t(row_samples.size());
    mesh_data mesh;
    mesh.vertices.reserve(std::size_t(columns) * rows);
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(std::numeric_limits<float>::lowest());
    for (std::uint32_t row : row_samples) {
        for (std::uint32_t column : column_samples) {
            const vertex v = grid_vertex(field, column, row, uv_per_m);
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
            mesh.vertices.push_back(v);
        }
    }
    mesh.indices.reserve(std::size_t(columns - 1) * (rows - 1) * 6);
    for (std::uint32_t row = 0; row + 1 < rows; ++row) {
        for (std::uint32_t column = 0; column + 1 < columns; ++column) {
            const std::uint32_t i = row * columns + column;
            const std::uint32_t n = columns;
            // Counter-clockwise seen from +y (x right, z towards the viewer).
            mesh.indices.insert(mesh.indices.end(), {i, i + n, i + 1, i + 1, i + n, i + n + 1});
        }
    }
    mesh.submeshes.push_back({0, std::uint32_t(mesh.indices.size()), material_kind::ground});
    mesh.bounds_min = lo;
    mesh.bounds_max = hi;
    return mesh;
}

// The skirts of the grid over vertex columns [c0, c1] and rows [r0, r1] at `stride`: on each side
// inside the terrain (not on its border), a vertical strip from the grid's edge samples down by
// depth_m, both rows of vertices with the edge's normal and uv. Each side is walked so that its
// triangles (top a, bottom a', top b), (b, a', b') face out of the tile: the face normal
// (a' - a) x (b - a) = (-depth·dz, 0, depth·dx) for a step (dx, dz) along the edge, so the
// south side (+z out) runs towards +x, the north (-z) towards -x, the east (+x) towards -z and
// the west (-x) towards +z.
mesh_data skirt_mesh(const heightfield& field, std::uint32_t c0, std::uint32_t c1, std::uint32_t r0,
                     std::uint32_t r1, float uv_scale_m, std::uint32_t stride, float depth_m) {
    const float uv_per_m = uv_per_metre(uv_scale_m);
    const std::uint32_t last = field.resolution - 1;
    const std::vector<std::uint32_t> columns = grid_samples(c0, c1, stride);
    const std::vector<std::uint32_t> rows = grid_samples(r0, r1, stride);
    mesh_data mesh;
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(std::numeric_limits<float>::lowest());
    auto side = [&](auto sample_count, auto sample_at) {
        const auto base = std::uint32_t(mesh.vertices.size());
        for (std::size_t i = 0; i < sample_count; ++i) {
            const auto [column, row] = sample_at(i);
            vertex top = grid_vertex(field, column, row, uv_per_m);
            vertex bottom = top;
            bottom.position.y -= depth_m;
            lo = glm::min(lo, bottom.position);
            hi = glm::max(hi, top.position);
            mesh.vertices.push_back(top);
            mesh.vertices.push_back(bottom);
        }
        for (std::uint32_t i = 0; i + 1 < std::uint32_t(sample_count); ++i) {
            const std::uint32_t a = base + 2 * i, b = a + 2;
            mesh.indices.insert(mesh.indices.end(), {a, a + 1, b, b, a + 1, b + 1});
        }
    };
    // Edges that cannot part need no skirt.
    if (!(depth_m > 0.0f)) return mesh;
    using sample = std::pair<std::uint32_t, std::uint32_t>;  // (column, row)
    const std::size_t nc = columns.size(), nr = rows.size();
    if (r1 < last) side(nc, [&](std::size_t i) { return sample{columns[i], r1}; });        // south
    if (r0 > 0) side(nc, [&](std::size_t i) { return sample{columns[nc - 1 - i], r0}; });  // north
    if (c1 < last) side(nr, [&](std::size_t i) { return sample{c1, rows[nr - 1 - i]}; });  // east
    if (c0 > 0) side(nr, [&](std::size_t i) { return sample{c0, rows[i]}; });              // west
    if (!mesh.indices.empty()) {
        mesh.submeshes.push_back({0, std::uint32_t(mesh.indices.size()), material_kind::ground});
        mesh.bounds_min = lo;
        mesh.bounds_max = hi;
    }
    return mesh;
}

// First cell of tile `tile` when `cells` cells are split into `tiles` nearly equal runs.
std::uint32_t tile_start(std::uint32_t cells, std::uint32_t tiles, std::uint32_t tile) {
    return static_cast<std::uint32_t>(std::uint64_t(cells) * tile / tiles);
}

}  // namespace

mesh_data terrain_mesh(const heightfield& field, float uv_scale_m) {
    if (field.resolution < 2) throw std::invalid_argument("terrain_mesh: empty heightfield");
    const std::uint32_t last = field.resolution - 1;
    mesh_data mesh = grid_mesh(field, 0, last, 0, last, uv_scale_m);
    const double half = 0.5 * field.size_m;
    mesh.bounds_min = glm::vec3(float(-half), field.min_height, float(-half));
    mesh.bounds_max = glm::vec3(float(half), field.max_height, float(half));
    return mesh;
}

namespace {

// Calls visit(c0, c1, r0, r1) for every tile of the terrain split into tiles_per_side^2 (row-major),
// with its first and last vertex column and row; checks the arguments both tile functions take.
template <class Visit>
void for_each_tile(const char* caller, const heightfield& field, std::uint32_t tiles_per_side, std::uint32_t stride,
                   const Visit& visit) {
    if (field.resolution < 2) throw std::invalid_argument(std::string(caller) + ": empty heightfield");
    if (stride == 0) throw std::invalid_argument(std::string(caller) + ": stride must be at least 1");
    const std::uint32_t cells = field.resolution - 1;
    const std::uint32_t tiles = std::clamp(tiles_per_side, 1u, cells);
    for (std::uint32_t tz = 0; tz < tiles; ++tz)
        for (std::uint32_t tx = 0; tx < tiles; ++tx)
            visit(tile_start(cells, tiles, tx), tile_start(cells, tiles, tx + 1), tile_start(cells, tiles, tz),
                  tile_start(cells, tiles, tz + 1));
}

}  // namespace

std::vector<mesh_data> terrain_tile_meshes(const heightfield& field, std::uint32_t tiles_per_side,
                                           float uv_scale_m, std::uint32_t stride) {
    std::vector<mesh_data> meshes;
    for_each_tile("terrain_tile_meshes", field, tiles_per_side, stride,
                  [&](std::uint32_t c0, std::uint32_t c1, std::uint32_t r0, std::uint32_t r1) {
                      meshes.push_back(grid_mesh(field, c0, c1, r0, r1, uv_scale_m, stride));
                  });
    return meshes;
}

std::vector<mesh_data> terrain_tile_skirts(const heightfield& field, std::uint32_t tiles_per_side,
                                           float uv_scale_m, std::uint32_t stride,
                                           std::span<const float> depth_m) {
    std::vector<mesh_data> meshes;
    for_each_tile(
        "terrain_tile_skirts", field, tiles_per_side, stride,
        [&](std::uint32_t c0, std::uint32_t c1, std::uint32_t r0, std::uint32_t r1) {
            const std::size_t tile = meshes.size();
            if (tile >= depth_m.size())
                throw std::invalid_argument("terrain_tile_skirts: a depth per tile is needed (" +
                                            std::to_string(depth_m.size()) + " given)");
            meshes.push_back(skirt_mesh(field, c0, c1, r0, r1, uv_scale_m, stride, depth_m[tile]));
        });
    return meshes;
}

std::vector<float> terrain_tile_errors(const heightfield& field, std::uint32_t tiles_per_side, std::uint32_t stride) {
    std::vector<float> errors;
    for_each_tile("terrain_tile_errors", field, tiles_per_side, stride,
                  [&](std::uint32_t c0, std::uint32_t c1, std::uint32_t r0, std::uint32_t r1) {
        const std::vector<std::uint32_t> columns = grid_samples(c0, c1, stride);
        const std::vector<std::uint32_t> rows = grid_samples(r0, r1, stride);
        float worst = 0.0f;
        // Each coarse cell's samples against its two triangles (grid_mesh's diagonal runs from
        // (column + 1, row) to (column, row + 1)).
        for (std::size_t j = 0; j + 1 < rows.size(); ++j) {
            for (std::size_t i = 0; i + 1 < columns.size(); ++i) {
                const std::uint32_t ca = columns[i], cb = columns[i + 1], ra = rows[j], rb = rows[j + 1];
                const float h00 = field.at(ca, ra), h10 = field.at(cb, ra), h01 = field.at(ca, rb),
                            h11 = field.at(cb, rb);
                for (std::uint32_t r = ra; r <= rb; ++r) {
                    for (std::uint32_t c = ca; c <= cb; ++c) {
                        const float u = float(c - ca) / float(cb - ca), v = float(r - ra) / float(rb - ra);
                        const float coarse = u + v <= 1.0f ? h00 + u * (h10 - h00) + v * (h01 - h00)
                                                           : h11 + (1.0f - u) * (h01 - h11) + (1.0f - v) * (h10 - h11);
                        worst = std::max(worst, std::abs(field.at(c, r) - coarse));
                    }
                }
            }
        }
        errors.push_back(worst);
    });
    return errors;
}

heightfield load_heightmap(const std::filesystem::path& path, double size_m, float height_m) {
    const std::string name = path.string();
    if (!(size_m > 0.0))
        throw std::invalid_argument("load_heightmap: " + name + ": size_m must be > 0");
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw std::runtime_error("load_heightmap: " + name + ": no such file");
    check_input_file(path, k_max_image_bytes);  // a directory or device is refused here
    auto in = OIIO::ImageInput::open(name);
    if (!in)
        throw std::runtime_error("load_heightmap: cannot read " + name + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    check_image_dimensions("load_heightmap: " + name, spec.width, spec.height);
    if (spec.width != spec.height)
        throw std::runtime_error("load_heightmap: " + name + " is " + std::to_string(spec.width) +
                                 "x" + std::to_string(spec.height) +
                                 " pixels; heightmaps must be square");
    if (spec.width < 2 || spec.nchannels < 1)
        throw std::runtime_error("load_heightmap: " + name +
                                 ": needs at least 2x2 pixels and one channel");
    heightfield f;
    f.resolution = static_cast<std::uint32_t>(spec.width);
    f.size_m = size_m;
    f.heights.resize(std::size_t(f.resolution) * f.resolution);
    // Converting to float maps integer formats to 0..1 (PNG 0..65535) and keeps float data as is.
    if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, f.heights.data()))
        throw std::runtime_error("load_heightmap: cannot read " + name + ": " + in->geterror());
    in->close();
    for (float& h : f.heights) h *= height_m;
    const auto [lo, hi] = std::minmax_element(f.heights.begin(), f.heights.end());
    f.min_height = *lo;
    f.max_height = *hi;
    return f;
}

}  // namespace sylva
