#include "models/radiance_transfer.h"

#include <embree3/rtcore.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "models/random.h"
#include "models/texture_sampling.h"
#include "systems/lighting/spherical_harmonics.h"

namespace sylva {
namespace {

constexpr double k_pi = std::numbers::pi;
// Ramamoorthi & Hanrahan 2001, Eqs. 7-9: the clamped cosine max(cos, 0) in SH is A_l Y_lm(n)
// per band l, A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4.
constexpr std::array<double, 9> k_clamped_cosine = {k_pi,         2 * k_pi / 3, 2 * k_pi / 3,
                                                    2 * k_pi / 3, k_pi / 4,     k_pi / 4,
                                                    k_pi / 4,     k_pi / 4,     k_pi / 4};
// Ray origins sit this fraction of the occluder's bounding diagonal off the receiver, along
// +-n: far enough that float rounding of a hit on the receiver's own surface cannot count,
// near enough (2 mm on a 20 m tree) that a leaf resting on a twig still shadows it.
constexpr float k_origin_offset = 1e-4f;
// Receivers per task. The result does not depend on it (each receiver is independent); it only
// trades scheduling overhead against balance.
constexpr std::size_t k_receiver_chunk = 64;
// GL's alpha test discards below 0.5 (bilinear_alpha returns 0..255).
constexpr float k_alpha_cutoff = 127.5f;

// How a geometry's candidate hits are judged (filter_hits).
enum class surface : std::uint8_t {
    one_sided,     // opaque materials: hits from behind are ignored
    double_sided,  // leaves without a texture: every hit counts
    alpha_tested,  // leaves: hits on cut-out texels are ignored, either side counts
};

// What an occlusion filter needs to judge a candidate hit on one geometry's triangle.
struct filter_data {
    surface kind = surface::one_sided;
    std::vector<std::uint32_t> indices;  // 3 per triangle, into the full mesh's vertices
    const std::vector<vertex>* vertices = nullptr;
    const image_rgba8* texture = nullptr;  // for alpha_tested
};

glm::vec3 interpolate_normal(const filter_data& d, unsigned prim, float u, float v) {
    const std::uint32_t* t = &d.indices[std::size_t(prim) * 3];
    const auto& vs = *d.vertices;
    // Embree's barycentrics: p = (1 - u - v) p0 + u p1 + v p2.
    return (1.0f - u - v) * vs[t[0]].normal + u * vs[t[1]].normal + v * vs[t[2]].normal;
}

glm::vec2 interpolate_uv(const filter_data& d, unsigned prim, float u, float v) {
    const std::uint32_t* t = &d.indices[std::size_t(prim) * 3];
    const auto& vs = *d.vertices;
    return (1.0f - u - v) * vs[t[0]].uv + u * vs[t[1]].uv + v * vs[t[2]].uv;
}

// Leaves: a hit where the texture is cut away lets the ray through (the renderer discards
// that texel). Opaque materials are closed, outward-facing surfaces (bark tubes), so a ray that
// meets one from behind started inside it: a lower level's vertex sunk into the full mesh's
// stem, or a branch's base inside its parent. That hit is the receiver's own surface, not a
// shadow, and is ignored; a ray from outside always meets a front face first.
void filter_hits(const RTCFilterFunctionNArguments* args) {
    const auto& d = *static_cast<const filter_data*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const float u = RTCHitN_u(args->hit, args->N, i);
        const float v = RTCHitN_v(args->hit, args->N, i);
        if (d.kind == surface::alpha_tested) {
            if (bilinear_alpha(*d.texture, interpolate_uv(d, prim, u, v)) < k_alpha_cutoff) args->valid[i] = 0;
            continue;
        }
        const glm::vec3 dir(RTCRayN_dir_x(args->ray, args->N, i), RTCRayN_dir_y(args->ray, args->N, i),
                            RTCRayN_dir_z(args->ray, args->N, i));
        if (glm::dot(dir, interpolate_normal(d, prim, u, v)) > 0.0f) args->valid[i] = 0;
    }
}

// Uniform random rotation from three uniforms (Shoemake 1992, "Uniform Random Rotations",
// Graphics Gems III, pp. 124-132): a unit quaternion uniform on S^3.
glm::mat3 uniform_rotation(rng& random) {
    const double u1 = random.uniform_double();
    const double a = 2 * k_pi * random.uniform_double();
    const double b = 2 * k_pi * random.uniform_double();
    const double r1 = std::sqrt(1 - u1);
    const double r2 = std::sqrt(u1);
    const glm::dquat q(r2 * std::cos(b), r1 * std::sin(a), r1 * std::cos(a), r2 * std::sin(b));
    return glm::mat3(glm::mat3_cast(q));
}

// N directions that split the sphere into N cells of equal area (the spherical Fibonacci
// point set: z_i = 1 - (2i + 1)/N, azimuth_i = 2 pi i / golden ratio; Keinert, Innmann, Sanger
// & Stamminger 2015, "Spherical Fibonacci Mapping", ACM TOG 34(6)). Each stands for 4 pi / N sr.
std::vector<glm::vec3> fibonacci_sphere(std::uint32_t n) {
    const double golden = (1 + std::sqrt(5.0)) / 2;
    std::vector<glm::vec3> dirs(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const double z = 1 - (2.0 * i + 1) / n;
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        const double phi = 2 * k_pi * std::fmod(i / golden, 1.0);
        dirs[i] = glm::vec3(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
    }
    return dirs;
}

glm::vec3 unit_normal(const vertex& v) {
    const float len = glm::length(v.normal);
    return len > 0.0f ? v.normal / len : glm::vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace

struct transfer_occluders::scene {
    RTCDevice device = nullptr;
    RTCScene rtc = nullptr;
    std::vector<vertex> vertices;
    image_rgba8 leaf_texture;
    filter_data opaque;
    filter_data leaf;
    float offset = 0.0f;  // ray origin offset, metres

    ~scene() {
        if (rtc) rtcReleaseScene(rtc);
        if (device) rtcReleaseDevice(device);
    }

    void attach(filter_data& data) {
        if (data.indices.empty()) return;
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* p = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), vertices.size()));
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            p[3 * i] = vertices[i].position.x, p[3 * i + 1] = vertices[i].position.y;
            p[3 * i + 2] = vertices[i].position.z;
        }
        auto* t = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), data.indices.size() / 3));
        std::copy(data.indices.begin(), data.indices.end(), t);
        data.vertices = &vertices;
        rtcSetGeometryUserData(g, &data);
        if (data.kind != surface::double_sided) {
            rtcSetGeometryOccludedFilterFunction(g, filter_hits);
            rtcSetGeometryIntersectFilterFunction(g, filter_hits);
        }
        rtcCommitGeometry(g);
        rtcAttachGeometry(rtc, g);
        rtcReleaseGeometry(g);
    }

    bool occluded(glm::vec3 origin, glm::vec3 dir) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray{origin.x, origin.y, origin.z, 0.0f, dir.x, dir.y, dir.z, 0.0f,
                   std::numeric_limits<float>::infinity(), ~0u, 0u, 0u};
        rtcOccluded1(rtc, &context, &ray);
        return ray.tfar < 0.0f;  // Embree sets tfar to -inf on an occlusion
    }
};

transfer_occluders::transfer_occluders(const mesh_data& full, const image_rgba8& leaf_texture)
    : m_scene(std::make_unique<scene>()) {
    scene& s = *m_scene;
    s.vertices = full.vertices;
    s.leaf_texture = leaf_texture;
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const vertex& v : s.vertices) lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
    s.offset = s.vertices.empty() ? 0.0f : std::max(k_origin_offset * glm::length(hi - lo), 1e-7f);
    // Without a texture a leaf cannot be cut out, so it is opaque (but still double-sided).
    s.leaf.kind = s.leaf_texture.texels.empty() ? surface::double_sided : surface::alpha_tested;
    s.leaf.texture = &s.leaf_texture;
    for (const submesh& sm : full.submeshes) {
        std::vector<std::uint32_t>& dst = sm.material == material_kind::leaf ? s.leaf.indices : s.opaque.indices;
        const auto first = full.indices.begin() + sm.first_index;
        dst.insert(dst.end(), first, first + sm.index_count);
    }
    s.device = rtcNewDevice(nullptr);
    if (!s.device) throw std::runtime_error("radiance transfer: Embree device creation failed");
    s.rtc = rtcNewScene(s.device);
    s.attach(s.opaque);
    s.attach(s.leaf);
    rtcCommitScene(s.rtc);
    if (const RTCError e = rtcGetDeviceError(s.device); e != RTC_ERROR_NONE)
        throw std::runtime_error("radiance transfer: Embree error " + std::to_string(int(e)) + " building the scene");
}

transfer_occluders::~transfer_occluders() = default;

radiance_transfer transfer_occluders::bake(std::span<const vertex> receivers, const transfer_settings& settings) const {
    if (settings.bands != 2 && settings.bands != 3)
        throw std::invalid_argument("radiance transfer: bands must be 2 or 3, not " + std::to_string(settings.bands));
    if (settings.rays_per_receiver == 0) throw std::invalid_argument("radiance transfer: zero rays per receiver");
    if (settings.interreflection)
        throw std::invalid_argument("radiance transfer: interreflection is not implemented yet");
    const std::size_t count = std::size_t(settings.bands) * settings.bands;
    radiance_transfer out;
    out.bands = settings.bands;
    out.front.resize(receivers.size() * count);
    out.back.resize(receivers.size() * count);
    const std::vector<glm::vec3> lattice = fibonacci_sphere(settings.rays_per_receiver);
    const double ray_weight = 4 * k_pi / settings.rays_per_receiver;
    const scene& s = *m_scene;

    auto bake_one = [&](std::size_t r) {
        const vertex& receiver = receivers[r];
        const glm::vec3 n = unit_normal(receiver);
        rng random(hash_combine(settings.seed, std::uint64_t(r)));
        const glm::mat3 rotation = uniform_rotation(random);
        // The occluded part of each side's integral, in double and in ray order (deterministic).
        std::array<double, 9> front_occluded{}, back_occluded{};
        for (const glm::vec3& l : lattice) {
            const glm::vec3 w = rotation * l;
            const float c = glm::dot(n, w);
            if (c == 0.0f) continue;  // zero weight on both sides
            const glm::vec3 origin = receiver.position + (c > 0.0f ? s.offset : -s.offset) * n;
            if (!s.occluded(origin, w)) continue;
            const sh9 y = sh_basis(w);
            std::array<double, 9>& sum = c > 0.0f ? front_occluded : back_occluded;
            const double weight = ray_weight * std::abs(double(c));
            for (std::size_t k = 0; k < count; ++k) sum[k] += weight * y[k];
        }
        const sh9 y_front = sh_basis(n);
        const sh9 y_back = sh_basis(-n);
        for (std::size_t k = 0; k < count; ++k) {
            out.front[r * count + k] = float(k_clamped_cosine[k] * y_front[k] - front_occluded[k]);
            out.back[r * count + k] = float(k_clamped_cosine[k] * y_back[k] - back_occluded[k]);
        }
    };
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, receivers.size(), k_receiver_chunk),
        [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t r = range.begin(); r != range.end(); ++r) bake_one(r);
        },
        tbb::simple_partitioner());
    return out;
}

}  // namespace sylva
