#include "models/bake/billboard_cloud.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <stdexcept>
#include <string>

#include "ecs/parallel.h"

namespace sylva {
namespace {

// Each billboard side is at least this many texels wide and tall.
constexpr std::uint32_t k_min_side_texels = 2;
// A box side shorter than this share of the longest (flat leaves, straight twigs) is widened to
// it for the plane, so a billboard across it is never degenerate.
constexpr float k_min_side_ratio = 1e-3f;

std::string to_string_f(float v) { return std::to_string(v); }

void validate(const plant_model& model, const billboard_cloud_settings& s) {
    if (model.lods[0].triangle_count() == 0)
        throw std::invalid_argument("billboard cloud: model '" + model.name + "' has no triangles at full detail");
    if (s.atlas_width == 0 || s.atlas_height == 0)
        throw std::invalid_argument("billboard cloud: atlas size " + std::to_string(s.atlas_width) + " x " +
                                    std::to_string(s.atlas_height) + " is empty");
    if (s.supersampling == 0 || s.supersampling > 16)
        throw std::invalid_argument("billboard cloud: supersampling must be 1..16, got " +
                                    std::to_string(s.supersampling));
    if (!(s.shape_factor > 0.0f) || !std::isfinite(s.shape_factor))
        throw std::invalid_argument("billboard cloud: shape factor f must be positive, got " + to_string_f(s.shape_factor));
    if (!(s.gaussian_sigma > 0.0f) || !std::isfinite(s.gaussian_sigma))
        throw std::invalid_argument("billboard cloud: gaussian sigma must be positive, got " +
                                    to_string_f(s.gaussian_sigma));
    if (s.max_side_texels < k_min_side_texels)
        throw std::invalid_argument("billboard cloud: max_side_texels must be at least 2, got " +
                                    std::to_string(s.max_side_texels));
}

// The box with its axes sorted by extent, longest first, kept right-handed.
oriented_box sorted_axes(const oriented_box& box) {
    std::array<int, 3> order{0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return box.half_extent[a] > box.half_extent[b]; });
    oriented_box out = box;
    for (int k = 0; k < 3; ++k) {
        out.axes[std::size_t(k)] = box.axes[std::size_t(order[std::size_t(k)])];
        out.half_extent[k] = box.half_extent[order[std::size_t(k)]];
    }
    if (glm::dot(glm::cross(out.axes[0], out.axes[1]), out.axes[2]) < 0.0f) out.axes[2] = -out.axes[2];
    return out;
}

cloud_cluster box_cluster(const mesh_data& mesh, const std::vector<std::uint32_t>& triangles,
                          const min_box_settings& box_settings) {
    const std::vector<std::uint32_t> vertices = triangle_vertices(mesh, triangles);
    std::vector<glm::vec3> points(vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) points[i] = mesh.vertices[vertices[i]].position;
    cloud_cluster cluster;
    const oriented_box pca = pca_box(points);
    cluster.pca_volume = pca.volume();
    // Behrendt 2005 §2.2: the minimum-volume box, from the PCA box as the initial box.
    cluster.box = sorted_axes(minimum_volume_box(points, pca, box_settings));
    cluster.triangles = std::uint32_t(triangles.size());
    return cluster;
}

// The billboard through the box's centre parallel to two of its sides. The more vertical of the
// two becomes axis_v (pointing up), so images stand upright; axis_u is chosen so the front side
// faces away from the plant's vertical axis (outward).
billboard_plane face_plane(const oriented_box& box, box_face face) {
    const int p = face == box_face::bc ? 1 : 0;
    const int q = face == box_face::ab ? 1 : 2;
    const float longest = 2.0f * box.half_extent[0];
    const float min_side = std::max(k_min_side_ratio * longest, 1e-6f);
    glm::vec3 u = box.axes[std::size_t(p)];
    glm::vec3 v = box.axes[std::size_t(q)];
    float width = std::max(2.0f * box.half_extent[p], min_side);
    float height = std::max(2.0f * box.half_extent[q], min_side);
    if (std::abs(u.y) > std::abs(v.y)) {
        std::swap(u, v);
        std::swap(width, height);
    }
    if (v.y < 0.0f) v = -v;
    const glm::vec3 outward(box.center.x, 0.0f, box.center.z);
    if (glm::dot(glm::cross(u, v), outward) < 0.0f) u = -u;
    return {box.center - 0.5f * width * u - 0.5f * height * v, u * width, v * height};
}

std::uint32_t side_texels(float metres, float texels_per_metre, std::uint32_t max_side) {
    const double texels = std::ceil(double(metres) * double(texels_per_metre) - 1e-6);
    return std::uint32_t(std::clamp<double>(texels, k_min_side_texels, max_side));
}

// Each billboard's rectangle (front and back side by side) at a density.
std::vector<glm::uvec2> rect_sizes(const std::vector<cloud_billboard>& billboards, float density, std::uint32_t max_side) {
    std::vector<glm::uvec2> sizes;
    sizes.reserve(billboards.size());
    for (const cloud_billboard& b : billboards)
        sizes.emplace_back(2 * side_texels(glm::length(b.plane.axis_u), density, max_side),
                           side_texels(glm::length(b.plane.axis_v), density, max_side));
    return sizes;
}

// The largest density (texels per metre, within a percent) at which every rectangle fits.
float fit_density(const std::vector<cloud_billboard>& billboards, const billboard_cloud_settings& s,
                  std::vector<atlas_rect>& rects) {
    double area = 0.0;  // both sides, m²
    for (const cloud_billboard& b : billboards)
        area += 2.0 * double(glm::length(b.plane.axis_u)) * double(glm::length(b.plane.axis_v));
    auto fits = [&](double density) {
        auto packed = pack_atlas(rect_sizes(billboards, float(density), s.max_side_texels), s.atlas_width,
                                 s.atlas_height, s.gutter);
        if (packed) rects = std::move(*packed);
        return packed.has_value();
    };
    double high = std::sqrt(double(s.atlas_width) * double(s.atlas_height) / std::max(area, 1e-12));
    if (fits(high)) return float(high);
    double low = high / 64.0;
    if (!fits(low)) {
        low = 0.0;  // every side at the 2-texel minimum
        if (!fits(low))
            throw std::runtime_error("billboard cloud: " + std::to_string(billboards.size()) +
                                     " billboards do not fit a " + std::to_string(s.atlas_width) + " x " +
                                     std::to_string(s.atlas_height) + " atlas even at 2 x 2 texels a side");
    }
    for (int i = 0; i < 24 && high - low > 0.005 * high; ++i) {
        const double mid = 0.5 * (low + high);
        (fits(mid) ? low : high) = mid;
    }
    fits(low);  // leave `rects` holding the chosen packing
    return float(low);
}

// Behrendt 2005 §2.3: alpha multiplied by a gaussian at bake time (the curve in the header).
void apply_gaussian(image_rgba8& albedo, float sigma) {
    const float two_sigma2 = 2.0f * sigma * sigma;
    for (std::uint32_t y = 0; y < albedo.height; ++y)
        for (std::uint32_t x = 0; x < albedo.width; ++x) {
            const float fx = 2.0f * (float(x) + 0.5f) / float(albedo.width) - 1.0f;
            const float fy = 2.0f * (float(y) + 0.5f) / float(albedo.height) - 1.0f;
            std::uint8_t& a = albedo.at(x, y)[3];
            a = std::uint8_t(std::lround(float(a) * std::exp(-(fx * fx + fy * fy) / two_sigma2)));
        }
}

// The plant seen from the pre-lit page's light: a square plane through the middle of its bounds,
// facing the light, holding every triangle's nearest depth toward the light.
struct light_depth_map {
    billboard_plane plane;
    glm::vec3 u{0.0f}, v{0.0f}, l{0.0f};  // unit axes and the direction toward the light
    float side_m = 0.0f;
    billboard_image image;

    // Share of the light reaching model-space point p: 3x3 texels around its spot, each lit
    // unless a surface lies more than `bias_m` nearer the light there.
    float visibility(glm::vec3 p, float bias_m) const {
        const glm::vec3 rel = p - plane.origin;
        const float size = float(image.albedo.width);
        const int cx = int(std::floor(glm::dot(rel, u) / side_m * size));
        const int cy = int(std::floor((1.0f - glm::dot(rel, v) / side_m) * size));
        const float depth = glm::dot(rel, l);
        float lit = 0.0f;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const int x = cx + dx, y = cy + dy;
                const bool inside = x >= 0 && y >= 0 && x < int(size) && y < int(size);
                const std::size_t i = inside ? std::size_t(y) * std::size_t(size) + std::size_t(x) : 0;
                lit += !inside || image.covered[i] == 0 || image.depth[i] <= depth + bias_m ? 1.0f : 0.0f;
            }
        return lit / 9.0f;
    }
};

light_depth_map bake_light_depth(const plant_model& model, const billboard_cloud_settings& settings) {
    const mesh_data& mesh = model.lods[0];
    glm::vec3 lo(mesh.vertices[0].position), hi(lo);
    for (const vertex& vx : mesh.vertices) lo = glm::min(lo, vx.position), hi = glm::max(hi, vx.position);
    light_depth_map map;
    map.l = glm::normalize(settings.pre_light_direction);
    const glm::vec3 helper = std::abs(map.l.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    map.u = glm::normalize(glm::cross(helper, map.l));
    map.v = glm::cross(map.l, map.u);  // cross(u, v) = l: the plane faces the light
    map.side_m = std::max(glm::length(hi - lo), 1e-3f);
    const glm::vec3 centre = 0.5f * (lo + hi);
    map.plane = {centre - 0.5f * map.side_m * (map.u + map.v), map.side_m * map.u, map.side_m * map.v};
    billboard_bake_settings bake;
    bake.width = bake.height = settings.pre_light_map_size;
    bake.supersampling = 1;
    bake.dilation_texels = 0;
    map.image = bake_billboard({&mesh, &model.leaf_texture, &model.bark_texture, {}}, map.plane, bake);
    return map;
}

// Behrendt 2005 §2.3, pre-lighting: one side of one billboard lit by the map's light, with the
// plant's own shadows; alpha copied from the albedo (coverage x gaussian).
image_rgba8 pre_light(const billboard_image& image, const billboard_plane& side, const light_depth_map& light,
                      float ambient) {
    image_rgba8 out = image.albedo;
    const float bias = 2.0f * light.side_m / float(light.image.albedo.width);
    const glm::vec3 normal = side.normal();
    for (std::uint32_t y = 0; y < out.height; ++y)
        for (std::uint32_t x = 0; x < out.width; ++x) {
            const std::size_t i = std::size_t(y) * out.width + x;
            const std::uint8_t* nt = image.normal.at(x, y);
            const glm::vec3 n = glm::normalize(glm::vec3(nt[0], nt[1], nt[2]) / 127.5f - 1.0f);
            const glm::vec3 p = side.origin + (float(x) + 0.5f) / float(out.width) * side.axis_u +
                                (1.0f - (float(y) + 0.5f) / float(out.height)) * side.axis_v + image.depth[i] * normal;
            const float visible = image.covered[i] ? light.visibility(p, bias) : 1.0f;
            const float f = light_factor(n, light.l, visible, ambient, image.ambient[i]);
            std::uint8_t* t = out.at(x, y);
            for (int c = 0; c < 3; ++c) t[c] = std::uint8_t(std::lround(std::min(255.0f, float(t[c]) * f)));
        }
    return out;
}

void blit(image_rgba8& dst, const image_rgba8& src, std::uint32_t x0, std::uint32_t y0) {
    for (std::uint32_t y = 0; y < src.height; ++y)
        std::memcpy(dst.at(x0, y0 + y), src.at(0, y), std::size_t(src.width) * 4);
}

// The rectangle's edge colours copied `ring` texels outward at alpha 0, so filtering and the
// first mips near an edge average with the billboard's own colours, not the atlas background.
// `data_alpha`: the alpha channel is data (transfer pages) and is copied like the colour.
void extend_edges(image_rgba8& page, const atlas_rect& r, std::uint32_t ring,
                  bool data_alpha = false) {
    const auto x0 = std::int64_t(r.x) - ring, x1 = std::int64_t(r.x + r.width) + ring;
    const auto y0 = std::int64_t(r.y) - ring, y1 = std::int64_t(r.y + r.height) + ring;
    for (std::int64_t y = std::max<std::int64_t>(y0, 0); y < std::min<std::int64_t>(y1, page.height); ++y)
        for (std::int64_t x = std::max<std::int64_t>(x0, 0); x < std::min<std::int64_t>(x1, page.width); ++x) {
            const bool inside = x >= r.x && x < r.x + r.width && y >= r.y && y < r.y + r.height;
            if (inside) continue;
            const auto sx = std::uint32_t(std::clamp<std::int64_t>(x, r.x, r.x + r.width - 1));
            const auto sy = std::uint32_t(std::clamp<std::int64_t>(y, r.y, r.y + r.height - 1));
            std::uint8_t* to = page.at(std::uint32_t(x), std::uint32_t(y));
            std::memcpy(to, page.at(sx, sy), data_alpha ? 4 : 3);
            if (!data_alpha) to[3] = 0;
        }
}

// Texels of no billboard take the mean transfer of the covered texels: the coarse mip levels
// average rectangles with their surroundings, and zero transfer there would darken far clouds'
// edges (the colour pages need no such care: their alpha fades those texels out).
void fill_transfer_background(billboard_cloud& cloud, std::uint32_t ring) {
    const image_rgba8& albedo = cloud.pages[std::size_t(cloud_atlas_page::albedo)];
    std::vector<std::uint8_t> used(std::size_t(albedo.width) * albedo.height, 0);
    for (const cloud_billboard& b : cloud.billboards) {
        const std::uint32_t x0 = b.rect.x > ring ? b.rect.x - ring : 0,
                            y0 = b.rect.y > ring ? b.rect.y - ring : 0;
        const std::uint32_t x1 = std::min(albedo.width, b.rect.x + b.rect.width + ring);
        const std::uint32_t y1 = std::min(albedo.height, b.rect.y + b.rect.height + ring);
        for (std::uint32_t y = y0; y < y1; ++y)
            for (std::uint32_t x = x0; x < x1; ++x) used[std::size_t(y) * albedo.width + x] = 1;
    }
    for (image_rgba8& page : cloud.transfer_pages) {
        std::array<double, 4> sum{};
        std::size_t covered = 0;
        for (std::uint32_t y = 0; y < albedo.height; ++y)
            for (std::uint32_t x = 0; x < albedo.width; ++x)
                if (albedo.at(x, y)[3] > 0) {
                    for (int c = 0; c < 4; ++c) sum[std::size_t(c)] += page.at(x, y)[c];
                    ++covered;
                }
        if (covered == 0) continue;
        std::array<std::uint8_t, 4> mean{};
        for (int c = 0; c < 4; ++c)
            mean[std::size_t(c)] = std::uint8_t(std::lround(sum[std::size_t(c)] / double(covered)));
        for (std::uint32_t y = 0; y < albedo.height; ++y)
            for (std::uint32_t x = 0; x < albedo.width; ++x)
                if (!used[std::size_t(y) * albedo.width + x])
                    std::memcpy(page.at(x, y), mean.data(), 4);
    }
}

// One quad: `corners` lower-left, lower-right, upper-right, upper-left as its viewer sees them
// (counter-clockwise: GL's front face), uvs onto texels [x0, x0 + w) x [y0, y0 + h).
void add_quad(mesh_data& mesh, const std::array<glm::vec3, 4>& corners, glm::vec3 normal, std::uint32_t x0,
              std::uint32_t y0, std::uint32_t w, std::uint32_t h, std::uint32_t atlas_w, std::uint32_t atlas_h) {
    const auto base = std::uint32_t(mesh.vertices.size());
    const float s0 = float(x0) / float(atlas_w), s1 = float(x0 + w) / float(atlas_w);
    const float t0 = float(y0) / float(atlas_h), t1 = float(y0 + h) / float(atlas_h);
    mesh.vertices.push_back({corners[0], normal, {s0, t1}});
    mesh.vertices.push_back({corners[1], normal, {s1, t1}});
    mesh.vertices.push_back({corners[2], normal, {s1, t0}});
    mesh.vertices.push_back({corners[3], normal, {s0, t0}});
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}

// The front quad and the back quad (back_side(): its lower-left is the front's lower-right) on
// the very same four positions, so both sides rasterise to identical depths.
void add_billboard_quads(mesh_data& mesh, const cloud_billboard& b, std::uint32_t atlas_w, std::uint32_t atlas_h) {
    const billboard_plane& p = b.plane;
    const std::array<glm::vec3, 4> front{p.origin, p.origin + p.axis_u, p.origin + p.axis_u + p.axis_v,
                                         p.origin + p.axis_v};
    const std::uint32_t w = b.rect.width / 2;
    add_quad(mesh, front, p.normal(), b.rect.x, b.rect.y, w, b.rect.height, atlas_w, atlas_h);
    add_quad(mesh, {front[1], front[0], front[3], front[2]}, -p.normal(), b.rect.x + w, b.rect.y, w, b.rect.height,
             atlas_w, atlas_h);
}

}  // namespace

std::vector<box_face> billboard_faces(glm::vec3 sides, float f) {
    const float a = sides.x, b = sides.y, c = sides.z;
    if (!(a >= b && b >= c && c >= 0.0f) || !std::isfinite(a))
        throw std::invalid_argument("billboard_faces: sides must be finite, sorted a >= b >= c >= 0, got " +
                                    to_string_f(a) + ", " + to_string_f(b) + ", " + to_string_f(c));
    if (!(f > 0.0f) || !std::isfinite(f))
        throw std::invalid_argument("billboard_faces: f must be positive, got " + to_string_f(f));
    // Behrendt 2005 §2.2: a billboard parallel to sides x, y when √(x·y) > f·z, z the third side.
    std::vector<box_face> faces;
    if (std::sqrt(a * b) > f * c) faces.push_back(box_face::ab);
    if (std::sqrt(a * c) > f * b) faces.push_back(box_face::ac);
    if (std::sqrt(b * c) > f * a) faces.push_back(box_face::bc);
    return faces;
}

std::size_t billboard_cloud::atlas_bytes() const {
    std::size_t bytes = 0;
    for (const image_rgba8& p : pages) bytes += p.texels.size();
    for (const image_rgba8& p : transfer_pages) bytes += p.texels.size();
    return bytes;
}

float light_factor(glm::vec3 n, glm::vec3 l, float visible, float ambient, float ka) {
    const float n_dot_l = glm::dot(n, l);
    return ka * ambient + (1.0f - ambient) * visible * (std::max(n_dot_l, 0.0f) + 0.35f * std::max(-n_dot_l, 0.0f));
}

float plant_height(const plant_model& model) {
    const std::vector<vertex>& vertices = model.lods[0].vertices;
    if (vertices.empty()) return 0.0f;
    float low = vertices[0].position.y, high = low;
    for (const vertex& v : vertices) low = std::min(low, v.position.y), high = std::max(high, v.position.y);
    return high - low;
}

std::uint32_t default_cluster_target(const plant_model& model) { return plant_height(model) >= 4.0f ? 60 : 25; }

billboard_cloud_settings default_billboard_cloud_settings(const plant_model& model) {
    billboard_cloud_settings s;
    s.clustering.target_clusters = default_cluster_target(model);
    const bool tree = plant_height(model) >= 4.0f;
    s.atlas_width = tree ? 1024 : 512;
    s.atlas_height = tree ? 512 : 256;
    return s;
}

billboard_cloud_layout plan_billboard_cloud(const plant_model& model, const billboard_cloud_settings& settings) {
    validate(model, settings);
    const mesh_data& mesh = model.lods[0];
    clustering_settings clustering = settings.clustering;
    if (clustering.target_clusters == 0) clustering.target_clusters = default_cluster_target(model);
    billboard_cloud_layout layout;
    layout.clustering = cluster_triangles(mesh, model.has_hierarchy, clustering);
    const std::vector<std::vector<std::uint32_t>> members = layout.clustering.triangles();
    layout.clusters.resize(members.size());
    ecs::parallel_for_each_index(members.size(), [&](std::size_t c) {
        layout.clusters[c] = box_cluster(mesh, members[c], settings.box);
    });
    for (std::size_t c = 0; c < members.size(); ++c) {
        std::size_t foliage = 0;
        for (const submesh& sub : mesh.submeshes)
            if (sub.material == material_kind::leaf || sub.material == material_kind::billboard)
                for (std::uint32_t t : members[c])
                    foliage += t * 3 >= sub.first_index && t * 3 < sub.first_index + sub.index_count;
        layout.clusters[c].foliage = 2 * foliage > members[c].size();
        const oriented_box& box = layout.clusters[c].box;
        if (!(box.half_extent.x > 0.0f)) continue;  // every vertex in one point: nothing to show
        for (const box_face face : billboard_faces(2.0f * box.half_extent, settings.shape_factor))
            layout.billboards.push_back({face_plane(box, face), std::uint32_t(c), face, {}});
    }
    return layout;
}

billboard_cloud bake_billboard_cloud(const plant_model& model,
                                     const billboard_cloud_settings& settings,
                                     const radiance_transfer* transfer) {
    billboard_cloud_layout layout = plan_billboard_cloud(model, settings);
    billboard_cloud cloud;
    cloud.method = layout.clustering.method;
    cloud.branching_level = layout.clustering.branching_level;
    cloud.clusters = std::move(layout.clusters);
    cloud.billboards = std::move(layout.billboards);
    cloud.atlas_width = settings.atlas_width;
    cloud.atlas_height = settings.atlas_height;
    for (image_rgba8& page : cloud.pages) {
        page.width = settings.atlas_width;
        page.height = settings.atlas_height;
        page.texels.assign(std::size_t(page.width) * page.height * 4, 0);
    }
    if (transfer)
        cloud.transfer_pages = blank_transfer_pages(settings.atlas_width, settings.atlas_height);
    std::vector<atlas_rect> rects;
    cloud.texels_per_metre = fit_density(cloud.billboards, settings, rects);
    for (std::size_t i = 0; i < rects.size(); ++i) cloud.billboards[i].rect = rects[i];

    const std::vector<std::vector<std::uint32_t>> members = layout.clustering.triangles();
    const mesh_data& mesh = model.lods[0];
    const light_depth_map light = bake_light_depth(model, settings);
    ecs::parallel_for_each_index(cloud.billboards.size(), [&](std::size_t i) {
        const cloud_billboard& b = cloud.billboards[i];
        billboard_bake_settings bake;
        bake.width = b.rect.width / 2;
        bake.height = b.rect.height;
        bake.supersampling = settings.supersampling;
        const billboard_source source{&mesh, &model.leaf_texture, &model.bark_texture,
                                      members[b.cluster], transfer};
        for (const bool back : {false, true}) {
            const billboard_plane side = back ? back_side(b.plane) : b.plane;
            billboard_image image = bake_billboard(source, side, bake);
            apply_gaussian(image.albedo, settings.gaussian_sigma);
            // Each billboard writes only its own rectangle: no two tasks touch the same texels.
            const std::uint32_t x = b.rect.x + (back ? bake.width : 0);
            blit(cloud.pages[std::size_t(cloud_atlas_page::albedo)], image.albedo, x, b.rect.y);
            blit(cloud.pages[std::size_t(cloud_atlas_page::normal)], image.normal, x, b.rect.y);
            blit(cloud.pages[std::size_t(cloud_atlas_page::pre_lit)],
                 pre_light(image, side, light, settings.pre_light_ambient), x, b.rect.y);
            if (transfer) blit_transfer(cloud.transfer_pages, image, x, b.rect.y);
        }
    });
    for (const cloud_billboard& b : cloud.billboards) {
        for (image_rgba8& page : cloud.pages) extend_edges(page, b.rect, settings.gutter / 2);
        for (image_rgba8& page : cloud.transfer_pages)
            extend_edges(page, b.rect, settings.gutter / 2, true);
        add_billboard_quads(cloud.mesh, b, cloud.atlas_width, cloud.atlas_height);
    }
    if (transfer) fill_transfer_background(cloud, settings.gutter / 2);
    cloud.mesh.submeshes.push_back({0, std::uint32_t(cloud.mesh.indices.size()), material_kind::billboard});
    if (!cloud.mesh.vertices.empty()) {
        cloud.mesh.bounds_min = cloud.mesh.bounds_max = cloud.mesh.vertices[0].position;
        for (const vertex& v : cloud.mesh.vertices) {
            cloud.mesh.bounds_min = glm::min(cloud.mesh.bounds_min, v.position);
            cloud.mesh.bounds_max = glm::max(cloud.mesh.bounds_max, v.position);
        }
    }
    return cloud;
}

image_rgba8 tangent_space_normal_page(const billboard_cloud& cloud) {
    const image_rgba8& model_space = cloud.page(cloud_atlas_page::normal);
    image_rgba8 out = model_space;
    for (std::size_t i = 0; i < out.texels.size(); i += 4) {
        out.texels[i] = 128, out.texels[i + 1] = 128, out.texels[i + 2] = 255;
    }
    auto convert = [&](const cloud_billboard& b, std::int64_t x, std::int64_t y) {
        if (x < 0 || y < 0 || x >= std::int64_t(out.width) || y >= std::int64_t(out.height)) return;
        const billboard_plane side = x >= std::int64_t(b.rect.x + b.rect.width / 2) ? back_side(b.plane) : b.plane;
        const glm::vec3 t = glm::normalize(side.axis_u), bt = glm::normalize(side.axis_v), n = side.normal();
        const std::uint8_t* m = model_space.at(std::uint32_t(x), std::uint32_t(y));
        const glm::vec3 normal = glm::vec3(m[0], m[1], m[2]) / 127.5f - 1.0f;
        const glm::vec3 local(glm::dot(normal, t), glm::dot(normal, bt), glm::dot(normal, n));
        std::uint8_t* to = out.at(std::uint32_t(x), std::uint32_t(y));
        for (int k = 0; k < 3; ++k) to[k] = std::uint8_t(std::lround(std::clamp(local[k] * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f));
    };
    // The one-texel frame extend_edges filled first, then every rectangle's own texels, so a
    // frame never overwrites a neighbour however narrow the gutter.
    for (const cloud_billboard& b : cloud.billboards) {
        const auto x0 = std::int64_t(b.rect.x), y0 = std::int64_t(b.rect.y);
        const auto x1 = x0 + std::int64_t(b.rect.width), y1 = y0 + std::int64_t(b.rect.height);
        for (std::int64_t y = y0 - 1; y <= y1; ++y)
            for (std::int64_t x = x0 - 1; x <= x1; ++x)
                if (x < x0 || x >= x1 || y < y0 || y >= y1) convert(b, x, y);
    }
    for (const cloud_billboard& b : cloud.billboards)
        for (std::uint32_t y = b.rect.y; y < b.rect.y + b.rect.height; ++y)
            for (std::uint32_t x = b.rect.x; x < b.rect.x + b.rect.width; ++x) convert(b, x, y);
    return out;
}

}  // namespace sylva
