#include "models/bake/radiance_transfer.h"

#include <embree3/rtcore.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <limits>
#include <mutex>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "models/random.h"
#include "models/image/texture_sampling.h"
#include "lighting/spherical_harmonics.h"
#include "ecs/parallel.h"

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
    float albedo = k_default_albedo;       // for the interreflection bounce
};

// Mean colour (the mean of r, g and b, 0..1) of the texels the renderer keeps: a material's
// scalar albedo for the bounce. Cut-out texels (alpha below the test) are not its colour.
float mean_albedo(const image_rgba8& texture, bool alpha_tested) {
    double sum = 0.0;
    std::size_t kept = 0;
    for (std::size_t i = 0; i + 3 < texture.texels.size(); i += 4) {
        if (alpha_tested && texture.texels[i + 3] < k_alpha_cutoff) continue;
        sum += (texture.texels[i] + texture.texels[i + 1] + texture.texels[i + 2]) / (3.0 * 255.0);
        ++kept;
    }
    return kept ? float(sum / double(kept)) : k_default_albedo;
}

// Where a ray stopped: the hit geometry's data and Embree's barycentrics.
struct ray_hit {
    const filter_data* data = nullptr;
    unsigned prim = 0;
    float u = 0.0f;
    float v = 0.0f;
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
            if (bilinear_alpha(*d.texture, interpolate_uv(d, prim, u, v)) < k_alpha_cutoff)
                args->valid[i] = 0;
            continue;
        }
        const glm::vec3 dir(RTCRayN_dir_x(args->ray, args->N, i),
                            RTCRayN_dir_y(args->ray, args->N, i),
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
    std::array<const filter_data*, 2> by_geometry_id{};
    float offset = 0.0f;  // ray origin offset, metres
    // The occluder's own shadowed transfer, the light its surfaces reflect in the bounce; baked
    // on the first interreflected bake and kept for later ones with the same rays. Shared, so a
    // bake keeps its source alive while a bake with other settings replaces it.
    std::mutex bounce_mutex;
    std::optional<transfer_settings> bounce_settings;
    std::shared_ptr<const radiance_transfer> bounce_source;

    ~scene() {
        if (rtc) rtcReleaseScene(rtc);
        if (device) rtcReleaseDevice(device);
    }

    void attach(filter_data& data) {
        if (data.indices.empty()) return;
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* p = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertices.size()));
        for (std::size_t i = 0; i < vertices.size(); ++i) {
            p[3 * i] = vertices[i].position.x, p[3 * i + 1] = vertices[i].position.y;
            p[3 * i + 2] = vertices[i].position.z;
        }
        auto* t = static_cast<std::uint32_t*>(
            rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                    3 * sizeof(std::uint32_t), data.indices.size() / 3));
        std::copy(data.indices.begin(), data.indices.end(), t);
        data.vertices = &vertices;
        rtcSetGeometryUserData(g, &data);
        if (data.kind != surface::double_sided) {
            rtcSetGeometryOccludedFilterFunction(g, filter_hits);
            rtcSetGeometryIntersectFilterFunction(g, filter_hits);
        }
        rtcCommitGeometry(g);
        by_geometry_id.at(rtcAttachGeometry(rtc, g)) = &data;
        rtcReleaseGeometry(g);
    }

    bool occluded(glm::vec3 origin, glm::vec3 dir) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay ray{origin.x, origin.y, origin.z,
                   0.0f,     dir.x,    dir.y,
                   dir.z,    0.0f,     std::numeric_limits<float>::infinity(),
                   ~0u,      0u,       0u};
        rtcOccluded1(rtc, &context, &ray);
        return ray.tfar < 0.0f;  // Embree sets tfar to -inf on an occlusion
    }

    // The nearest hit the filters accept, for the bounce; nothing when the ray escapes.
    std::optional<ray_hit> nearest(glm::vec3 origin, glm::vec3 dir) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rh{};
        rh.ray = RTCRay{origin.x, origin.y, origin.z,
                        0.0f,     dir.x,    dir.y,
                        dir.z,    0.0f,     std::numeric_limits<float>::infinity(),
                        ~0u,      0u,       0u};
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(rtc, &context, &rh);
        if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
        return ray_hit{by_geometry_id.at(rh.hit.geomID), rh.hit.primID, rh.hit.u, rh.hit.v};
    }
};

transfer_occluders::transfer_occluders(const mesh_data& full, const image_rgba8& leaf_texture,
                                       const image_rgba8& bark_texture)
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
    s.leaf.albedo = mean_albedo(leaf_texture, true);
    s.opaque.albedo = mean_albedo(bark_texture, false);
    for (const submesh& sm : full.submeshes) {
        std::vector<std::uint32_t>& dst =
            sm.material == material_kind::leaf ? s.leaf.indices : s.opaque.indices;
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
        throw std::runtime_error("radiance transfer: Embree error " + std::to_string(int(e)) +
                                 " building the scene");
}

transfer_occluders::~transfer_occluders() = default;

namespace {

// Sums of one side of one receiver, in double and in ray order (deterministic).
struct side_sums {
    std::array<double, 9> occluded{};  // integral (1 - V) max(+-n.w, 0) Y dw
    std::array<double, 9> bounce{};    // integral (1 - V) max(+-n.w, 0) albedo/pi T(hit) dw
};

// The bounce source's transfer at a hit, interpolated over the hit triangle, on the side the
// ray meets (the front when it travels against the interpolated normal).
void add_bounce(const ray_hit& hit, glm::vec3 dir, const radiance_transfer& source,
                std::size_t count, double weight, std::array<double, 9>& sum) {
    const std::uint32_t* t = &hit.data->indices[std::size_t(hit.prim) * 3];
    const bool front = glm::dot(dir, interpolate_normal(*hit.data, hit.prim, hit.u, hit.v)) < 0.0f;
    const std::vector<float>& side = front ? source.front : source.back;
    const std::array<double, 3> bary = {1.0 - hit.u - hit.v, hit.u, hit.v};
    // Sloan, Kautz & Snyder 2002, §5 (interreflected transfer), one bounce: the light a hit
    // surface reflects toward the receiver is albedo/pi times its own shadowed transfer.
    const double scale = weight * hit.data->albedo / k_pi;
    for (std::size_t k = 0; k < count; ++k) {
        double tq = 0.0;
        for (std::size_t c = 0; c < 3; ++c) tq += bary[c] * side[t[c] * count + k];
        sum[k] += scale * tq;
    }
}

}  // namespace

radiance_transfer transfer_occluders::bake_pass(std::span<const vertex> receivers,
                                                const transfer_settings& settings,
                                                const radiance_transfer* bounce_source) const {
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
        side_sums front, back;
        for (const glm::vec3& l : lattice) {
            const glm::vec3 w = rotation * l;
            const float c = glm::dot(n, w);
            if (c == 0.0f) continue;  // zero weight on both sides
            const glm::vec3 origin = receiver.position + (c > 0.0f ? s.offset : -s.offset) * n;
            std::optional<ray_hit> hit;
            if (bounce_source) {
                hit = s.nearest(origin, w);
                if (!hit) continue;
            } else if (!s.occluded(origin, w)) {
                continue;
            }
            side_sums& side = c > 0.0f ? front : back;
            const double weight = ray_weight * std::abs(double(c));
            const sh9 y = sh_basis(w);
            for (std::size_t k = 0; k < count; ++k) side.occluded[k] += weight * y[k];
            if (hit) add_bounce(*hit, w, *bounce_source, count, weight, side.bounce);
        }
        const sh9 y_front = sh_basis(n);
        const sh9 y_back = sh_basis(-n);
        for (std::size_t k = 0; k < count; ++k) {
            out.front[r * count + k] =
                float(k_clamped_cosine[k] * y_front[k] - front.occluded[k] + front.bounce[k]);
            out.back[r * count + k] =
                float(k_clamped_cosine[k] * y_back[k] - back.occluded[k] + back.bounce[k]);
        }
    };
    // Receivers are independent: chunks of k_receiver_chunk, one task each (ecs/parallel.h).
    ecs::parallel_for(receivers.size(), k_receiver_chunk, [&](std::size_t begin, std::size_t end, std::size_t) {
        for (std::size_t r = begin; r != end; ++r) bake_one(r);
    });
    return out;
}

radiance_transfer transfer_occluders::bake(std::span<const vertex> receivers,
                                           const transfer_settings& settings) const {
    if (settings.bands != 2 && settings.bands != 3)
        throw std::invalid_argument("radiance transfer: bands must be 2 or 3, not " +
                                    std::to_string(settings.bands));
    if (settings.rays_per_receiver == 0)
        throw std::invalid_argument("radiance transfer: zero rays per receiver");
    if (!settings.interreflection) return bake_pass(receivers, settings, nullptr);
    scene& s = *m_scene;
    transfer_settings direct = settings;
    direct.interreflection = false;
    std::shared_ptr<const radiance_transfer> source;
    {
        const std::lock_guard lock(s.bounce_mutex);
        const auto same = [&](const transfer_settings& b) {
            return b.bands == direct.bands && b.rays_per_receiver == direct.rays_per_receiver &&
                   b.seed == direct.seed;
        };
        if (!s.bounce_settings || !same(*s.bounce_settings)) {
            s.bounce_source =
                std::make_shared<const radiance_transfer>(bake_pass(s.vertices, direct, nullptr));
            s.bounce_settings = direct;
        }
        source = s.bounce_source;
    }
    return bake_pass(receivers, settings, source.get());
}

}  // namespace sylva
