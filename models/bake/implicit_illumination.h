#pragma once
// Expressive foliage illumination from implicit surfaces (Luft, Balzer & Deussen 2007): a
// preprocessing step that only rewrites a plant's vertex normals.
//
//   - Generator points at the centres of mass of the foliage triangles (§3.1), a seeded random
//     fraction of them (§3.1: "randomly selecting just a fraction ... producing very similar
//     results"), each with the same radius of influence ρ.
//   - The density field F(q) = Σ D_i(q) − τ, D_i(q) = (1 − (|q − p_i| / ρ)²)² inside ρ
//     (Eq. 2, Eq. 3).
//   - Its iso-surface F = 0, extracted by OpenVDB's volume-to-mesh from F sampled on a grid
//     (§2.3: "a Marching Cube algorithm [LC87] or one of its derivatives").
//   - Per vertex of the plant (foliage, trunk and branches alike, §3.2 end): the ambient
//     coefficient k_a by Eq. 4, and the normal of the nearest iso-surface vertex (§3.3),
//     optionally blended with the original. Eq. 4's input d_v is by default the vertex's depth
//     below the iso-surface (ambient_source::depth), not the paper's F(v) (ambient_source::
//     density, kept): see ambient_source.
//   - Stored as the normal scaled by k_a (§3.2 end: "the normal vector of each vertex is scaled by
//     the corresponding ambient reflection coefficient"), so the vertex format does not grow; a
//     shader decodes k_a as the normal's length.
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <string_view>
#include <vector>

#include "models/mesh.h"
#include "models/plant_model.h"

namespace sylva {

// True when a vertex normal carries Luft 2007's k_a as its length (apply_implicit_illumination),
// not a plain unit normal: bakes made from the model keep the length where it does.
inline bool carries_ambient(const vertex& v) { return std::abs(glm::length(v.normal) - 1.0f) >= 1e-4f; }

// What Eq. 4 maps to k_a. Luft 2007 §3.2 motivates the ambient term by "a gradual darkening from
// the outer to the inner parts of the foliage" and then takes the density at the vertex,
// d_v = F(v). F measures how many leaves lie within ρ, not how deep the vertex is: our crowns
// bear their leaves on the outer twigs, so the densest foliage is near the crown's skin and the
// inside is sparse, and F ranked ray-cast occlusion no better than 0.698 (broadleaf) whatever ρ
// (`sylva implicit-ao --ambient-from density`, docs/results/implicit_lighting.md). The depth below
// the paper's own iso-surface F = 0 - the distance to the nearest surface vertex, which §3.3's
// realignment finds anyway, positive inside and negative outside - is that darkening from outer
// to inner itself: it ranks occlusion 0.80 on broadleaf, and better on every generated tree.
enum class ambient_source : std::uint8_t {
    depth,    // d_v = depth below the iso-surface, in metres (d_min: depth_min_m)
    density,  // d_v = F(v), the paper's (d_min: d_min)
};
// The source a scenario's "ambient_from" names ("depth" or "density", scenarios/scenario.h).
inline ambient_source ambient_source_named(std::string_view name) {
    return name == "density" ? ambient_source::density : ambient_source::depth;
}

// The paper's parameters. 0 for rho_m, tau, d_min or depth_min_m: derived from the model
// (implicit_defaults).
struct implicit_settings {
    float generator_fraction = 1.0f;  // §3.1: generators' share of foliage triangles (scenario.h)
    std::uint64_t seed = 1;
    float rho_m = 0.0f;        // ρ, every generator's radius of influence (Eq. 2)
    float tau = 0.0f;          // τ, the threshold (Eq. 3)
    float ka_min = 0.3f;       // k_a,min (Eq. 4)
    float d_min = 0.0f;        // d_min (Eq. 4) for d_v = F(v): the density of the foliage's core
    ambient_source source = ambient_source::depth;  // Eq. 4's d_v
    float depth_min_m = 0.0f;  // d_min (Eq. 4) for d_v = depth: the depth of the foliage's core
    float exponent = 1.0f;     // n (Eq. 4)
    float blend = 1.0f;        // N' = normalize(mix(N, N_s, blend)); the paper uses 1 (§3.3)
    float cells_per_rho = 4.0f;  // the grid F is sampled on for the iso-surface: ρ / this
    bool operator==(const implicit_settings&) const = default;
};

// Eq. 2: one generator's density at squared distance `d2` for radius `rho`.
inline float generator_density(float d2, float rho) {
    const float s2 = d2 / (rho * rho);
    return s2 < 1.0f ? (1.0f - s2) * (1.0f - s2) : 0.0f;
}

// Eq. 4: the ambient coefficient at d = d_v (F(v) or the depth below the surface).
float ambient_coefficient(float d, float ka_min, float d_min, float exponent);

// The density field of a generator set (Eq. 3), with a k-d tree over the generators (nanoflann).
class implicit_field {
public:
    implicit_field(std::vector<glm::vec3> generators, float rho, float tau);
    ~implicit_field();
    implicit_field(implicit_field&&) noexcept;
    implicit_field& operator=(implicit_field&&) noexcept;

    // F(q) = Σ D_i(q) − τ.
    float value(const glm::vec3& q) const { return density(q) - m_tau; }
    // Σ D_i(q), the field before its threshold.
    float density(const glm::vec3& q) const;
    // The outward unit normal of the level set through q: −∇F / |∇F| (∇D_i = −4(1 − s²)(q − p_i)/ρ²);
    // zero where no generator reaches.
    glm::vec3 outward_normal(const glm::vec3& q) const;

    const std::vector<glm::vec3>& generators() const { return m_generators; }
    float rho() const { return m_rho; }
    float tau() const { return m_tau; }

private:
    struct tree;
    std::vector<glm::vec3> m_generators;
    float m_rho = 1.0f;
    float m_tau = 0.0f;
    std::unique_ptr<tree> m_tree;
};

// Σ D_i sampled on a regular grid that covers every generator's reach, read back by trilinear
// interpolation (issue 22: "the density field F (Eq. 2, 3) sampled on a grid"). Summing Eq. 3
// exactly at each vertex of a 180k-vertex plant visits about a thousand generators per vertex
// (5 s for broadleaf_hd on 2 cores); F is a sum of C¹ quartic bumps of radius ρ, so samples ρ/4
// apart reproduce it closely (tests/models/bake: within 2 % of the foliage's median density) and
// the same samples feed marching cubes.
struct density_grid {
    glm::vec3 origin{0.0f};  // the sample (0, 0, 0)
    float cell_m = 1.0f;
    glm::ivec3 size{0};      // samples per axis
    std::vector<float> sums;  // Σ D_i at origin + (x, y, z)·cell_m, x fastest
    // Σ D_i at q by trilinear interpolation; 0 outside the grid (beyond every generator's ρ).
    float density_at(const glm::vec3& q) const;
};
density_grid sample_density(const implicit_field& field, float cell_m);

// The iso-surface F = 0 as vertices with outward normals (triangles are not needed: §3.3 takes
// the nearest vertex's normal).
struct iso_surface {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
};
iso_surface extract_iso_surface(const implicit_field& field, float cell_m);
// The same from samples already taken (field gives τ and the surface normals' exact gradient).
iso_surface extract_iso_surface(const implicit_field& field, const density_grid& grid);

// The foliage triangles' centres of mass (submeshes of material leaf), a seeded random
// `fraction` of them (at least one when there is foliage).
std::vector<glm::vec3> foliage_generators(const mesh_data& mesh, float fraction, std::uint64_t seed);

// `settings` with ρ, τ and d_min filled in from the generators where they are 0:
//   ρ = 0.2 × the radius of the generators' bounding sphere (§3.1: "values that provide
//   adequate results can be automatically specified with regard to the size of the model");
//   m = the median of Σ D_i at the generators themselves (the foliage's own density);
//   τ = m / 4, so the surface lies where the density falls to a quarter of the foliage's;
//   d_min = 2 (m − τ), so the foliage's typical density sits halfway down Eq. 4's ramp and only
//   the densest core reaches k_a,min (§3.2: "the core of the foliage where no variant ambient
//   lighting is observed"). Measured: with m − τ the crown of single_tree lost 11.6 % of its
//   mean luma and 42-51 % of a tree's vertices tied at k_a,min; with 2 (m − τ) 2.6 % and about
//   10 %, and k_a ranks ray-cast occlusion better (docs/results/implicit_lighting.md);
//   depth_min_m = 2 × the generators' median depth below the iso-surface, by the same rule (the
//   typical leaf halfway down the ramp): about 5 % of a tree's vertices at k_a,min.
// The median is read from the sampled density (density_grid) at cells of ρ / cells_per_rho.
// depth_min_m needs the iso-surface: implicit_defaults leaves it 0, the bake fills it in.
implicit_settings implicit_defaults(const std::vector<glm::vec3>& generators, implicit_settings settings);

// The depth of q below the iso-surface from F(q) and the squared distance to the surface's
// nearest vertex: that distance, positive where F(q) > 0 (inside), negative outside.
inline float depth_below_surface(float f_at_q, float nearest_d2) {
    const float d = std::sqrt(nearest_d2);
    return f_at_q > 0.0f ? d : -d;
}

// depth_below_surface at every point of `points` (F from `grid` less τ); none inside when the
// surface is empty.
std::vector<float> depths_below_surface(const std::vector<glm::vec3>& points,
                                        const density_grid& grid, const iso_surface& surface,
                                        float tau);

// depth_min_m's default: 2 × the generators' median depth below `surface` (F from `grid` less
// τ), at least one of grid's cells.
float default_depth_min(const std::vector<glm::vec3>& generators, const density_grid& grid,
                        const iso_surface& surface, float tau);

// What the bake did, for `sylva inspect` and the tests.
struct implicit_report {
    implicit_settings used;       // with the derived values
    std::size_t generators = 0;
    std::size_t surface_vertices = 0;
    float mean_ka = 1.0f;         // over the full mesh's vertices
};

// Rewrites every vertex normal of `mesh` as normalize(mix(N, N_s, blend)) × k_a, F at a vertex
// read from `grid` (less settings.tau), k_a by Eq. 4 of settings.source's d_v (depth_min_m must
// be filled in for the depth).
void apply_implicit_illumination(mesh_data& mesh, const density_grid& grid, const iso_surface& surface,
                                 const implicit_settings& settings);

// The whole bake on a plant: generators from its full mesh's foliage, the field, the surface,
// and every level's normals rewritten from the same field.
implicit_report bake_implicit_illumination(plant_model& plant, const implicit_settings& settings);

}  // namespace sylva
