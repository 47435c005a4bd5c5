#include "models/bake/implicit_illumination.h"

#include <openvdb/openvdb.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <memory>
#include <nanoflann.hpp>
#include <stdexcept>

#include "ecs/parallel.h"
#include "models/bake/nanoflann_points.h"
#include "models/random.h"

namespace sylva {

namespace {

using point_cloud = nanoflann_points;
using point_tree = point_kd_tree;

// Fixed chunks: the result never depends on how many threads ran them.
constexpr std::size_t k_chunk = 1024;

}  // namespace

float ambient_coefficient(float d, float ka_min, float d_min, float exponent) {
    // Luft 2007 Eq. 4.
    if (!(d > 0.0f)) return 1.0f;
    if (!(d < d_min)) return ka_min;
    return ka_min + (1.0f - ka_min) * std::pow(1.0f - d / d_min, exponent);
}

struct implicit_field::tree {
    point_cloud cloud;
    point_tree index;
    explicit tree(const std::vector<glm::vec3>* points)
        : cloud{points}, index(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {
        index.buildIndex();
    }
};

implicit_field::implicit_field(std::vector<glm::vec3> generators, float rho, float tau)
    : m_generators(std::move(generators)), m_rho(rho), m_tau(tau) {
    if (!(rho > 0.0f) || !std::isfinite(rho)) throw std::invalid_argument("implicit_field: ρ must be positive");
    if (!(tau >= 0.0f)) throw std::invalid_argument("implicit_field: τ must be >= 0 (Luft 2007 Eq. 3)");
    m_tree = std::make_unique<tree>(&m_generators);
}
implicit_field::~implicit_field() = default;
implicit_field::implicit_field(implicit_field&& other) noexcept
    : m_generators(std::move(other.m_generators)), m_rho(other.m_rho), m_tau(other.m_tau),
      m_tree(std::move(other.m_tree)) {
    if (m_tree) m_tree->cloud.points = &m_generators;  // the adaptor points at our vector now
}
implicit_field& implicit_field::operator=(implicit_field&& other) noexcept {
    m_generators = std::move(other.m_generators);
    m_rho = other.m_rho;
    m_tau = other.m_tau;
    m_tree = std::move(other.m_tree);
    if (m_tree) m_tree->cloud.points = &m_generators;
    return *this;
}

float implicit_field::density(const glm::vec3& q) const {
    // Eq. 3 over the generators within ρ (Eq. 2 is zero beyond), before τ.
    std::vector<std::pair<std::uint32_t, float>> near;
    nanoflann::SearchParams params;
    params.sorted = false;
    m_tree->index.radiusSearch(&q.x, m_rho * m_rho, near, params);
    // Summed in generator order: the same sum whatever order the tree returned them in.
    std::sort(near.begin(), near.end());
    float sum = 0.0f;
    for (const auto& [i, d2] : near) sum += generator_density(d2, m_rho);
    return sum;
}

glm::vec3 implicit_field::outward_normal(const glm::vec3& q) const {
    std::vector<std::pair<std::uint32_t, float>> near;
    nanoflann::SearchParams params;
    params.sorted = false;
    m_tree->index.radiusSearch(&q.x, m_rho * m_rho, near, params);
    std::sort(near.begin(), near.end());
    glm::vec3 g(0.0f);  // −∇F = Σ 4(1 − s²)(q − p_i)/ρ²
    for (const auto& [i, d2] : near) {
        const float s2 = d2 / (m_rho * m_rho);
        if (s2 < 1.0f) g += 4.0f * (1.0f - s2) * (q - m_generators[i]) / (m_rho * m_rho);
    }
    const float length = glm::length(g);
    return length > 0.0f ? g / length : glm::vec3(0.0f);
}

density_grid sample_density(const implicit_field& field, float cell_m) {
    density_grid out;
    out.cell_m = cell_m;
    if (field.generators().empty()) return out;
    if (!(cell_m > 0.0f)) throw std::invalid_argument("sample_density: the cell must be positive");
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : field.generators()) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // Σ D_i is 0 beyond ρ of every generator: one cell more than ρ holds all of it.
    lo -= glm::vec3(field.rho() + cell_m);
    hi += glm::vec3(field.rho() + cell_m);
    out.origin = lo;
    out.size = glm::ivec3(glm::ceil((hi - lo) / cell_m)) + 1;
    const std::size_t count = std::size_t(out.size.x) * std::size_t(out.size.y) * std::size_t(out.size.z);
    if (count > 64u * 1024u * 1024u)
        throw std::invalid_argument("sample_density: " + std::to_string(count) +
                                    " grid samples; raise the cell size (implicit.cells_per_rho)");
    // Sampled in parallel into a dense array (fixed chunks).
    out.sums.resize(count);
    const std::size_t chunks = (count + k_chunk - 1) / k_chunk;
    ecs::parallel_for_each_index(chunks, [&](std::size_t chunk) {
        const std::size_t end = std::min(count, (chunk + 1) * k_chunk);
        for (std::size_t i = chunk * k_chunk; i < end; ++i) {
            const int x = int(i % std::size_t(out.size.x));
            const int y = int((i / std::size_t(out.size.x)) % std::size_t(out.size.y));
            const int z = int(i / (std::size_t(out.size.x) * std::size_t(out.size.y)));
            out.sums[i] = field.density(lo + glm::vec3(x, y, z) * cell_m);
        }
    });
    return out;
}

float density_grid::density_at(const glm::vec3& q) const {
    if (sums.empty()) return 0.0f;
    const glm::vec3 g = (q - origin) / cell_m;
    if (!(g.x >= 0.0f && g.y >= 0.0f && g.z >= 0.0f)) return 0.0f;
    const glm::ivec3 c = glm::ivec3(glm::floor(g));
    if (c.x + 1 >= size.x || c.y + 1 >= size.y || c.z + 1 >= size.z) return 0.0f;
    const glm::vec3 f = g - glm::vec3(c);
    const auto at = [&](int dx, int dy, int dz) {
        return sums[(std::size_t(c.z + dz) * std::size_t(size.y) + std::size_t(c.y + dy)) * std::size_t(size.x) +
                    std::size_t(c.x + dx)];
    };
    const float x00 = glm::mix(at(0, 0, 0), at(1, 0, 0), f.x), x10 = glm::mix(at(0, 1, 0), at(1, 1, 0), f.x);
    const float x01 = glm::mix(at(0, 0, 1), at(1, 0, 1), f.x), x11 = glm::mix(at(0, 1, 1), at(1, 1, 1), f.x);
    return glm::mix(glm::mix(x00, x10, f.y), glm::mix(x01, x11, f.y), f.z);
}

iso_surface extract_iso_surface(const implicit_field& field, float cell_m) {
    return extract_iso_surface(field, sample_density(field, cell_m));
}

iso_surface extract_iso_surface(const implicit_field& field, const density_grid& grid) {
    iso_surface out;
    if (grid.sums.empty()) return out;
    // OpenVDB meshes the level set with "inside" below the isovalue: the grid holds −Σ D_i and
    // the isovalue is −τ, so F = Σ D_i − τ > 0 is inside.
    openvdb::initialize();
    openvdb::FloatGrid::Ptr vdb = openvdb::FloatGrid::create(0.0f);
    vdb->setTransform(openvdb::math::Transform::createLinearTransform(double(grid.cell_m)));
    auto access = vdb->getAccessor();
    for (std::size_t i = 0; i < grid.sums.size(); ++i) {
        if (grid.sums[i] == 0.0f) continue;  // the background: no generator reaches
        const int x = int(i % std::size_t(grid.size.x));
        const int y = int((i / std::size_t(grid.size.x)) % std::size_t(grid.size.y));
        const int z = int(i / (std::size_t(grid.size.x) * std::size_t(grid.size.y)));
        access.setValue(openvdb::Coord(x, y, z), -grid.sums[i]);
    }
    std::vector<openvdb::Vec3s> points;
    std::vector<openvdb::Vec4I> quads;
    openvdb::tools::volumeToMesh(*vdb, points, quads, -double(field.tau()));
    out.positions.reserve(points.size());
    for (const openvdb::Vec3s& p : points) out.positions.push_back(grid.origin + glm::vec3(p.x(), p.y(), p.z()));
    out.normals.resize(out.positions.size());
    const std::size_t point_chunks = (out.positions.size() + k_chunk - 1) / k_chunk;
    ecs::parallel_for_each_index(point_chunks, [&](std::size_t chunk) {
        const std::size_t end = std::min(out.positions.size(), (chunk + 1) * k_chunk);
        for (std::size_t i = chunk * k_chunk; i < end; ++i) out.normals[i] = field.outward_normal(out.positions[i]);
    });
    return out;
}

std::vector<glm::vec3> foliage_generators(const mesh_data& mesh, float fraction, std::uint64_t seed) {
    // Luft 2007 §3.1: one generator per foliage primitive at its centre of mass, a random fraction.
    std::vector<glm::vec3> all;
    for (const submesh& s : mesh.submeshes) {
        if (s.material != material_kind::leaf) continue;
        for (std::uint32_t i = s.first_index; i + 2 < s.first_index + s.index_count; i += 3) {
            const glm::vec3& a = mesh.vertices[mesh.indices[i]].position;
            const glm::vec3& b = mesh.vertices[mesh.indices[i + 1]].position;
            const glm::vec3& c = mesh.vertices[mesh.indices[i + 2]].position;
            all.push_back((a + b + c) / 3.0f);
        }
    }
    if (all.empty() || !(fraction < 1.0f)) return all;
    rng r(seed, 0x4c554654);  // "LUFT"
    std::vector<glm::vec3> chosen;
    for (const glm::vec3& p : all)
        if (r.uniform() < fraction) chosen.push_back(p);
    if (chosen.empty()) chosen.push_back(all[all.size() / 2]);
    return chosen;
}

namespace {

// §3.1: ρ "with regard to the size of the model": a fifth of the generators' bounding radius.
float default_rho(const std::vector<glm::vec3>& generators) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : generators) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    return std::max(0.2f * 0.5f * glm::length(hi - lo), 1e-3f);
}

// τ and d_min from the foliage's own density m, read from `grid` at the generators.
implicit_settings thresholds_from(const std::vector<glm::vec3>& generators, implicit_settings s,
                                  const density_grid& grid) {
    if (s.tau > 0.0f && s.d_min > 0.0f) return s;
    std::vector<float> own(generators.size());
    for (std::size_t i = 0; i < generators.size(); ++i) own[i] = grid.density_at(generators[i]);
    std::nth_element(own.begin(), own.begin() + std::ptrdiff_t(own.size() / 2), own.end());
    const float m = own[own.size() / 2];
    if (!(s.tau > 0.0f)) s.tau = 0.25f * m;
    if (!(s.d_min > 0.0f)) s.d_min = std::max(2.0f * (m - s.tau), 1e-6f);
    return s;
}

// The settings with ρ, τ and d_min filled in, and Σ D_i sampled at the cells they give: the bake
// reads the same samples for the defaults' median, the iso-surface and every vertex's F.
struct sampled_defaults {
    implicit_settings used;
    density_grid grid;
};

sampled_defaults sample_with_defaults(const std::vector<glm::vec3>& generators, implicit_settings s) {
    if (!(s.rho_m > 0.0f)) s.rho_m = default_rho(generators);
    density_grid grid = sample_density(implicit_field(generators, s.rho_m, 0.0f), s.rho_m / s.cells_per_rho);
    return {thresholds_from(generators, s, grid), std::move(grid)};
}

}  // namespace

std::vector<float> depths_below_surface(const std::vector<glm::vec3>& points,
                                        const density_grid& grid, const iso_surface& surface,
                                        float tau) {
    std::vector<float> depths(points.size(), -std::numeric_limits<float>::infinity());
    if (surface.positions.empty()) return depths;
    const point_cloud cloud{&surface.positions};
    point_tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree.buildIndex();
    for (std::size_t i = 0; i < points.size(); ++i) {
        std::uint32_t j = 0;
        float d2 = 0.0f;
        tree.knnSearch(&points[i].x, 1, &j, &d2);
        depths[i] = depth_below_surface(grid.density_at(points[i]) - tau, d2);
    }
    return depths;
}

float default_depth_min(const std::vector<glm::vec3>& generators, const density_grid& grid,
                        const iso_surface& surface, float tau) {
    // implicit_defaults' rule for d_min, in depth: twice the foliage's median depth. The nearest
    // surface vertex lies on a marching-cubes cell edge, so a depth reads up to about a cell
    // long; at least one cell, the depth's own resolution.
    float median = 0.0f;
    if (!surface.positions.empty() && !generators.empty()) {
        std::vector<float> depths = depths_below_surface(generators, grid, surface, tau);
        std::nth_element(depths.begin(), depths.begin() + std::ptrdiff_t(depths.size() / 2),
                         depths.end());
        median = depths[depths.size() / 2];
    }
    return std::max(2.0f * median, grid.cell_m);
}

implicit_settings implicit_defaults(const std::vector<glm::vec3>& generators, implicit_settings s) {
    if (generators.empty()) return s;
    if (s.tau > 0.0f && s.d_min > 0.0f) {
        if (!(s.rho_m > 0.0f)) s.rho_m = default_rho(generators);
        return s;
    }
    return sample_with_defaults(generators, s).used;
}

void apply_implicit_illumination(mesh_data& mesh, const density_grid& grid, const iso_surface& surface,
                                 const implicit_settings& settings) {
    std::unique_ptr<point_tree> nearest;
    const point_cloud cloud{&surface.positions};
    if (!surface.positions.empty()) {
        nearest = std::make_unique<point_tree>(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
        nearest->buildIndex();
    }
    const std::size_t chunks = (mesh.vertices.size() + k_chunk - 1) / k_chunk;
    ecs::parallel_for_each_index(chunks, [&](std::size_t chunk) {
        const std::size_t end = std::min(mesh.vertices.size(), (chunk + 1) * k_chunk);
        for (std::size_t i = chunk * k_chunk; i < end; ++i) {
            vertex& v = mesh.vertices[i];
            const float f = grid.density_at(v.position) - settings.tau;  // F = Σ D_i − τ (Eq. 3)
            // §3.3: the normal of the nearest iso-surface vertex, or a mix with the original.
            glm::vec3 n = glm::length(v.normal) > 0.0f ? glm::normalize(v.normal) : glm::vec3(0.0f, 1.0f, 0.0f);
            float depth = -std::numeric_limits<float>::infinity();  // no surface: nothing is inside
            if (nearest) {
                std::uint32_t j = 0;
                float d2 = 0.0f;
                nearest->knnSearch(&v.position.x, 1, &j, &d2);
                depth = depth_below_surface(f, d2);
                const glm::vec3 mixed = glm::mix(n, surface.normals[j], settings.blend);
                if (glm::length(mixed) > 1e-6f) n = glm::normalize(mixed);
            }
            // §3.2, Eq. 4: k_a from d_v, the depth below the surface or F itself (ambient_source).
            const float ka =
                settings.source == ambient_source::depth
                    ? ambient_coefficient(depth, settings.ka_min, settings.depth_min_m,
                                          settings.exponent)
                    : ambient_coefficient(f, settings.ka_min, settings.d_min, settings.exponent);
            // §3.2 end: the normal's length carries k_a; never 0, which would lose its direction.
            v.normal = n * std::max(ka, 1.0f / 256.0f);
        }
    });
}

implicit_report bake_implicit_illumination(plant_model& plant, const implicit_settings& settings) {
    implicit_report report;
    const std::vector<glm::vec3> generators =
        foliage_generators(plant.lods[0], settings.generator_fraction, settings.seed);
    report.used = settings;
    report.generators = generators.size();
    if (generators.empty()) return report;  // no foliage: nothing to light by its shape
    const auto [used, grid] = sample_with_defaults(generators, settings);
    report.used = used;
    const implicit_field field(generators, report.used.rho_m, report.used.tau);
    const iso_surface surface = extract_iso_surface(field, grid);
    report.surface_vertices = surface.positions.size();
    if (report.used.source == ambient_source::depth && !(report.used.depth_min_m > 0.0f))
        report.used.depth_min_m = default_depth_min(generators, grid, surface, report.used.tau);
    for (mesh_data& level : plant.lods) apply_implicit_illumination(level, grid, surface, report.used);
    double sum = 0.0;
    for (const vertex& v : plant.lods[0].vertices) sum += double(glm::length(v.normal));
    report.mean_ka = plant.lods[0].vertices.empty() ? 1.0f : float(sum / double(plant.lods[0].vertices.size()));
    return report;
}

}  // namespace sylva
