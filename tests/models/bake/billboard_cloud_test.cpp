// Billboard clouds (Behrendt 2005 §2): the billboard-count rule on hand-made boxes, the plane of
// a single flat cluster, and a baked broadleaf cloud: quads and uvs against the atlas layout,
// rectangles that never overlap, both sides of each billboard, the gaussian alpha, the minimum
// boxes against PCA boxes, byte-identical bakes on any thread count and the cache round trip.
#include "models/bake/billboard_cloud.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "models/cache/bake_cache.h"
#include "models/cache/billboard_cloud_io.h"
#include "models/gltf/gltf_export.h"
#include "models/gltf/gltf_import.h"
#include "models/generate/plant_library.h"

namespace sylva {
namespace {

using faces = std::vector<box_face>;

// Hand-computed with f = 0.5: ab when √(ab) > 0.5c, ac when √(ac) > 0.5b, bc when √(bc) > 0.5a.
TEST(billboard_faces, follow_the_papers_rule_on_hand_made_boxes) {
    EXPECT_EQ(k_billboard_shape_factor, 0.5f);
    // Two long sides, one short: √1 = 1 > 0.05; √0.1 = 0.32 < 0.5 twice. One billboard.
    EXPECT_EQ(billboard_faces({1.0f, 1.0f, 0.1f}), (faces{box_face::ab}));
    // One long side: √0.1 = 0.32 > 0.05 for ab and ac; bc: 0.1 < 0.5. Two crossed billboards.
    EXPECT_EQ(billboard_faces({1.0f, 0.1f, 0.1f}), (faces{box_face::ab, box_face::ac}));
    EXPECT_EQ(billboard_faces({4.0f, 1.0f, 1.0f}), (faces{box_face::ab, box_face::ac}));  // bc: 1 < 2
    // Roughly cubic: three crossed billboards.
    EXPECT_EQ(billboard_faces({1.0f, 1.0f, 1.0f}), (faces{box_face::ab, box_face::ac, box_face::bc}));
    EXPECT_EQ(billboard_faces({1.9f, 1.0f, 1.0f}), (faces{box_face::ab, box_face::ac, box_face::bc}));  // 1 > 0.95
    // The rule is strict: at √(bc) = f·a exactly there is no third billboard, nor a second at
    // √(ac) = f·b.
    EXPECT_EQ(billboard_faces({2.0f, 1.0f, 1.0f}), (faces{box_face::ab, box_face::ac}));
    EXPECT_EQ(billboard_faces({1.0f, 1.0f, 0.25f}), (faces{box_face::ab}));
    // A slab only a third as thick already gets all three when the other sides are equal:
    // √(1 · 0.36) = 0.6 > 0.5 for ac and bc alike.
    EXPECT_EQ(billboard_faces({1.0f, 1.0f, 0.36f}), (faces{box_face::ab, box_face::ac, box_face::bc}));
    // Flat (c = 0): one; a line or a point has no area to show.
    EXPECT_EQ(billboard_faces({1.0f, 1.0f, 0.0f}), (faces{box_face::ab}));
    EXPECT_EQ(billboard_faces({1.0f, 0.0f, 0.0f}), faces{});
    // f scales the thresholds: f = 2 needs √(ab) > 2c.
    EXPECT_EQ(billboard_faces({1.0f, 1.0f, 1.0f}, 2.0f), faces{});
    EXPECT_EQ(billboard_faces({1.0f, 1.0f, 0.4f}, 2.0f), (faces{box_face::ab}));
}

TEST(billboard_faces, unsorted_or_negative_sides_are_named) {
    EXPECT_THROW(billboard_faces({1.0f, 2.0f, 0.5f}), std::invalid_argument);
    EXPECT_THROW(billboard_faces({1.0f, 0.5f, -0.1f}), std::invalid_argument);
    EXPECT_THROW(billboard_faces({1.0f, 0.5f, 0.1f}, 0.0f), std::invalid_argument);
    EXPECT_THROW(billboard_faces({std::nanf(""), 0.5f, 0.1f}), std::invalid_argument);
}

image_rgba8 solid(std::uint8_t r, std::uint8_t g, std::uint8_t b) {
    return {2, 2, std::vector<std::uint8_t>{r, g, b, 255, r, g, b, 255, r, g, b, 255, r, g, b, 255}};
}

// A one-leaf plant: an opaque 2 m x 1 m card from `at` along `right` (2 m) and `up` (1 m), every
// vertex normal `n`, baked as one cluster into a 64 x 32 atlas.
billboard_cloud bake_one_card(glm::vec3 at, glm::vec3 right, glm::vec3 up, glm::vec3 n) {
    plant_model plant;
    plant.name = "card";
    mesh_data& mesh = plant.lods[0];
    mesh.vertices = {{at, n, {0, 1}}, {at + 2.0f * right, n, {1, 1}}, {at + 2.0f * right + up, n, {1, 0}}, {at + up, n, {0, 0}}};
    mesh.indices = {0, 1, 2, 0, 2, 3};
    mesh.submeshes = {{0, 6, material_kind::leaf}};
    plant.leaf_texture = solid(40, 160, 30);
    plant.bark_texture = solid(120, 80, 40);
    billboard_cloud_settings s;
    s.clustering.target_clusters = 1;
    s.atlas_width = 64;
    s.atlas_height = 32;
    return bake_billboard_cloud(plant, s);
}

// One opaque 2 m x 1 m card in a tilted plane, as a one-leaf plant: one cluster with a flat box,
// so one billboard exactly over the card, facing the way the card does (or away).
TEST(billboard_cloud, a_flat_card_gets_one_billboard_in_its_own_plane) {
    const glm::vec3 right = glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f));
    const glm::vec3 up = glm::normalize(glm::vec3(0.0f, 1.0f, 0.3f) - right * glm::dot(glm::vec3(0.0f, 1.0f, 0.3f), right));
    const glm::vec3 at(3.0f, 1.0f, 0.0f);
    const glm::vec3 n = glm::cross(right, up);
    const billboard_cloud cloud = bake_one_card(at, right, up, n);
    ASSERT_EQ(cloud.clusters.size(), 1u);
    ASSERT_EQ(cloud.billboards.size(), 1u);
    const billboard_plane& p = cloud.billboards[0].plane;
    EXPECT_NEAR(glm::length(p.axis_u) * glm::length(p.axis_v), 2.0f, 0.01f);
    EXPECT_NEAR(std::abs(glm::dot(p.normal(), n)), 1.0f, 1e-4f);
    EXPECT_LT(glm::length(p.origin + 0.5f * (p.axis_u + p.axis_v) - (at + right + 0.5f * up)), 1e-4f);
    EXPECT_GT(p.axis_v.y, 0.0f);  // the more vertical side points up
    // The card fills both images: every texel is covered in the normal page, and the albedo
    // page carries the leaf colour.
    const atlas_rect r = cloud.billboards[0].rect;
    std::size_t covered = 0;
    for (std::uint32_t y = r.y; y < r.y + r.height; ++y)
        for (std::uint32_t x = r.x; x < r.x + r.width; ++x) {
            covered += cloud.page(cloud_atlas_page::normal).at(x, y)[3] == 255;
            EXPECT_EQ(cloud.page(cloud_atlas_page::albedo).at(x, y)[1], 160);
        }
    EXPECT_GE(double(covered), 0.9 * double(r.width) * double(r.height));
}

// glTF's normal texture is in tangent space: x along the side's axis_u, y along axis_v, z toward
// its viewer. A card whose vertex normals lean toward `right` must read (dot(n, u), dot(n, v),
// dot(n, normal)) on the front half and the same with the back side's frame on the back half,
// where the baker turned the normal toward that viewer.
TEST(billboard_cloud, the_tangent_space_normal_page_uses_each_side_s_own_frame) {
    const glm::vec3 right(1.0f, 0.0f, 0.0f), up(0.0f, 1.0f, 0.0f), facing(0.0f, 0.0f, 1.0f);
    const glm::vec3 n = glm::normalize(facing + 0.5f * right);
    const glm::vec3 at(2.0f, 0.0f, 3.0f);
    const billboard_cloud cloud = bake_one_card(at, right, up, n);
    ASSERT_EQ(cloud.billboards.size(), 1u);
    const image_rgba8 page = tangent_space_normal_page(cloud);
    const cloud_billboard& b = cloud.billboards[0];
    for (const bool back : {false, true}) {
        const billboard_plane side = back ? back_side(b.plane) : b.plane;
        // The baker turns the leaf's normal toward whichever side sees it.
        const glm::vec3 seen = glm::dot(n, side.normal()) >= 0.0f ? n : -n;
        const glm::vec3 expected(glm::dot(seen, glm::normalize(side.axis_u)), glm::dot(seen, glm::normalize(side.axis_v)),
                                 glm::dot(seen, side.normal()));
        const std::uint32_t x = b.rect.x + b.rect.width / 4 + (back ? b.rect.width / 2 : 0);
        const std::uint8_t* texel = page.at(x, b.rect.y + b.rect.height / 2);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(texel[k], (expected[k] * 0.5f + 0.5f) * 255.0f, 2.0f) << "back " << back << " channel " << k;
        EXPECT_GT(expected.z, 0.8f);
        EXPECT_GT(std::abs(expected.x), 0.4f);  // the lean shows in x, not y
    }
    EXPECT_EQ(page.at(0, 0)[2], 255);  // outside every billboard: flat
}

constexpr std::uint32_t k_atlas_w = 512;
constexpr std::uint32_t k_atlas_h = 256;

billboard_cloud_settings broadleaf_settings() {
    billboard_cloud_settings s;
    s.atlas_width = k_atlas_w;
    s.atlas_height = k_atlas_h;
    s.supersampling = 2;
    return s;
}

const plant_model& broadleaf() {
    static const plant_model model = generate_plant_model("broadleaf", 7, 64);
    return model;
}

const billboard_cloud& broadleaf_cloud() {
    static const billboard_cloud cloud = bake_billboard_cloud(broadleaf(), broadleaf_settings());
    return cloud;
}

TEST(billboard_cloud, broadleaf_has_the_papers_billboard_count_and_hierarchy_clusters) {
    const billboard_cloud& cloud = broadleaf_cloud();
    EXPECT_EQ(cloud.method, clustering_method::hierarchy);
    EXPECT_EQ(cloud.branching_level, 1);
    EXPECT_GE(cloud.billboards.size(), 50u);  // Behrendt 2005 §2.1: 50-200 for trees
    EXPECT_LE(cloud.billboards.size(), 200u);
    EXPECT_EQ(cloud.atlas_bytes(), std::size_t(k_atlas_w) * k_atlas_h * 4 * k_cloud_atlas_pages);
    // Every cluster has 1..3 billboards, by the rule on its own box.
    std::vector<std::size_t> per_cluster(cloud.clusters.size(), 0);
    for (const cloud_billboard& b : cloud.billboards) ++per_cluster[b.cluster];
    for (std::size_t c = 0; c < cloud.clusters.size(); ++c)
        EXPECT_EQ(per_cluster[c], billboard_faces(2.0f * cloud.clusters[c].box.half_extent).size()) << c;
}

TEST(billboard_cloud, quads_come_in_front_and_back_pairs_with_uvs_on_their_rectangle_halves) {
    const billboard_cloud& cloud = broadleaf_cloud();
    const mesh_data& mesh = cloud.mesh;
    ASSERT_EQ(mesh.vertices.size(), cloud.billboards.size() * 8);
    ASSERT_EQ(mesh.triangle_count(), cloud.billboards.size() * 4);
    ASSERT_EQ(mesh.submeshes.size(), 1u);
    EXPECT_EQ(mesh.submeshes[0].material, material_kind::billboard);
    for (std::size_t i = 0; i < cloud.billboards.size(); ++i) {
        const atlas_rect r = cloud.billboards[i].rect;
        for (int side = 0; side < 2; ++side) {
            const vertex* q = &mesh.vertices[i * 8 + std::size_t(side) * 4];
            const float s0 = float(r.x + std::uint32_t(side) * r.width / 2) / float(k_atlas_w);
            const float s1 = float(r.x + std::uint32_t(side + 1) * r.width / 2) / float(k_atlas_w);
            for (int k = 0; k < 4; ++k) {
                EXPECT_GE(q[k].uv.x, s0 - 1e-6f);
                EXPECT_LE(q[k].uv.x, s1 + 1e-6f);
                EXPECT_GE(q[k].uv.y, float(r.y) / float(k_atlas_h) - 1e-6f);
                EXPECT_LE(q[k].uv.y, float(r.y + r.height) / float(k_atlas_h) + 1e-6f);
            }
            // Counter-clockwise seen from the side the normal points to.
            const glm::vec3 winding = glm::cross(q[1].position - q[0].position, q[2].position - q[0].position);
            EXPECT_GT(glm::dot(winding, q[0].normal), 0.0f) << "billboard " << i << " side " << side;
        }
        EXPECT_NEAR(glm::dot(mesh.vertices[i * 8].normal, mesh.vertices[i * 8 + 4].normal), -1.0f, 1e-5f);
        EXPECT_EQ(mesh.vertices[i * 8].position, mesh.vertices[i * 8 + 5].position);  // same plane, mirrored
    }
}

TEST(billboard_cloud, atlas_rectangles_never_overlap_and_stay_inside) {
    const billboard_cloud& cloud = broadleaf_cloud();
    for (std::size_t i = 0; i < cloud.billboards.size(); ++i) {
        const atlas_rect& a = cloud.billboards[i].rect;
        EXPECT_LE(a.x + a.width, k_atlas_w);
        EXPECT_LE(a.y + a.height, k_atlas_h);
        EXPECT_EQ(a.width % 2, 0u);
        for (std::size_t j = 0; j < i; ++j) ASSERT_FALSE(overlaps(a, cloud.billboards[j].rect)) << i << " " << j;
    }
}

// Both sides are the same cluster seen from opposite directions: orthographically they have the
// same silhouette, so the back image's coverage is the front's mirrored.
TEST(billboard_cloud, the_back_side_shows_the_mirrored_silhouette_of_the_front) {
    const billboard_cloud& cloud = broadleaf_cloud();
    const image_rgba8& normal = cloud.page(cloud_atlas_page::normal);
    std::size_t covered = 0, mismatched = 0;
    for (const cloud_billboard& b : cloud.billboards) {
        const std::uint32_t w = b.rect.width / 2;
        for (std::uint32_t y = b.rect.y; y < b.rect.y + b.rect.height; ++y)
            for (std::uint32_t x = 0; x < w; ++x) {
                const bool front = normal.at(b.rect.x + x, y)[3] > 0;
                const bool back = normal.at(b.rect.x + w + (w - 1 - x), y)[3] > 0;
                covered += front;
                mismatched += front != back;
            }
    }
    EXPECT_GT(covered, 5000u);
    EXPECT_LT(double(mismatched), 0.02 * double(covered));
}

// Albedo alpha = coverage (the normal page's alpha) x exp(-(x² + y²) / 2σ²), σ = 1.
TEST(billboard_cloud, albedo_alpha_is_coverage_times_the_gaussian) {
    const billboard_cloud& cloud = broadleaf_cloud();
    const image_rgba8& albedo = cloud.page(cloud_atlas_page::albedo);
    const image_rgba8& normal = cloud.page(cloud_atlas_page::normal);
    std::size_t checked = 0;
    for (const cloud_billboard& b : cloud.billboards) {
        const std::uint32_t w = b.rect.width / 2;
        for (std::uint32_t y = 0; y < b.rect.height; ++y)
            for (std::uint32_t x = 0; x < b.rect.width; ++x) {
                const float fx = 2.0f * (float(x % w) + 0.5f) / float(w) - 1.0f;
                const float fy = 2.0f * (float(y) + 0.5f) / float(b.rect.height) - 1.0f;
                const float g = std::exp(-(fx * fx + fy * fy) / 2.0f);
                const float coverage = normal.at(b.rect.x + x, b.rect.y + y)[3];
                ASSERT_NEAR(albedo.at(b.rect.x + x, b.rect.y + y)[3], coverage * g, 0.51f);
                checked += coverage > 0;
            }
    }
    EXPECT_GT(checked, 5000u);
}

// The paper prefers minimum-volume boxes to eigenvector boxes; the search never does worse than
// its PCA start and, on a real tree, does better on most clusters.
TEST(billboard_cloud, minimum_boxes_are_never_larger_than_pca_boxes) {
    const billboard_cloud& cloud = broadleaf_cloud();
    std::size_t smaller = 0;
    for (const cloud_cluster& c : cloud.clusters) {
        EXPECT_LE(c.box.volume(), c.pca_volume * (1.0f + 1e-4f));
        smaller += c.box.volume() < 0.99f * c.pca_volume;
    }
    EXPECT_GT(2 * smaller, cloud.clusters.size());
}

TEST(billboard_cloud, bakes_byte_identically_twice_and_on_one_thread) {
    const std::vector<std::byte> bytes = serialize_billboard_cloud(broadleaf_cloud());
    billboard_cloud single;
    tbb::task_arena one(1);
    one.execute([&] { single = bake_billboard_cloud(broadleaf(), broadleaf_settings()); });
    EXPECT_EQ(serialize_billboard_cloud(single), bytes);
}

TEST(billboard_cloud, round_trips_through_the_bake_cache_byte_identically) {
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / ("sylva_cloud_test_" + std::to_string(::getpid()));
    fs::remove_all(root);
    const std::vector<std::byte> bytes = serialize_billboard_cloud(broadleaf_cloud());
    bake_cache(root).store("billboard_clouds", 7, bytes);
    const auto loaded = bake_cache(root).load("billboard_clouds", 7);
    ASSERT_TRUE(loaded);
    const billboard_cloud back = deserialize_billboard_cloud(*loaded);
    EXPECT_EQ(serialize_billboard_cloud(back), bytes);
    EXPECT_EQ(back.page(cloud_atlas_page::albedo).texels, broadleaf_cloud().page(cloud_atlas_page::albedo).texels);
    EXPECT_EQ(back.billboards.size(), broadleaf_cloud().billboards.size());
    fs::remove_all(root);

    std::vector<std::byte> truncated(bytes.begin(), bytes.end() - 5);
    EXPECT_THROW(deserialize_billboard_cloud(truncated), std::runtime_error);
    std::vector<std::byte> other_version = bytes;
    other_version[4] = std::byte(0xee);
    EXPECT_THROW(deserialize_billboard_cloud(other_version), std::runtime_error);
}

TEST(billboard_cloud, default_settings_follow_the_papers_ranges_by_plant_size) {
    const billboard_cloud_settings tree = default_billboard_cloud_settings(broadleaf());
    EXPECT_EQ(tree.clustering.target_clusters, 60u);
    EXPECT_EQ(tree.atlas_width, 1024u);
    EXPECT_EQ(tree.atlas_height, 512u);
    const billboard_cloud_settings small = default_billboard_cloud_settings(generate_plant_model("grass", 1, 8));
    EXPECT_EQ(small.clustering.target_clusters, 25u);
    EXPECT_EQ(small.atlas_width, 512u);
    EXPECT_EQ(small.atlas_height, 256u);
}

// Behrendt 2005 §2.1 for models from other tools: a tree imported from glTF has no branch
// hierarchy (one node), so its clusters come from the geometric clustering, which still keeps
// the importer's leaves (told apart by texture alpha and colour) and bark apart.
TEST(billboard_cloud, an_imported_tree_without_hierarchy_bakes_with_leaves_and_bark_apart) {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("sylva_cloud_import_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    export_plant_glb(broadleaf(), plant_lod::full, dir / "broadleaf.glb");
    const plant_model imported = import_plant_model(dir / "broadleaf.glb", 64);
    fs::remove_all(dir);
    ASSERT_FALSE(imported.has_hierarchy);
    const billboard_cloud cloud = bake_billboard_cloud(imported, broadleaf_settings());
    EXPECT_EQ(cloud.method, clustering_method::geometric);
    EXPECT_GE(cloud.billboards.size(), 50u);
    EXPECT_LE(cloud.billboards.size(), 200u);
    // No cluster mixes the two: each cluster's triangles are all leaf or all bark.
    const triangle_clusters clusters = plan_billboard_cloud(imported, broadleaf_settings()).clustering;
    const mesh_data& mesh = imported.lods[0];
    std::vector<int> kinds(clusters.count, 0);
    for (const submesh& sub : mesh.submeshes)
        for (std::uint32_t t = sub.first_index / 3; t < (sub.first_index + sub.index_count) / 3; ++t)
            kinds[clusters.cluster_of[t]] |= sub.material == material_kind::leaf ? 2 : 1;
    EXPECT_EQ(std::count(kinds.begin(), kinds.end(), 3), 0);
    EXPECT_GT(std::count(kinds.begin(), kinds.end(), 1), 0);
    EXPECT_GT(std::count(kinds.begin(), kinds.end(), 2), 0);
}

TEST(billboard_cloud, bad_settings_are_named) {
    billboard_cloud_settings s = broadleaf_settings();
    s.atlas_width = 0;
    EXPECT_THROW(bake_billboard_cloud(broadleaf(), s), std::invalid_argument);
    s = broadleaf_settings();
    s.supersampling = 0;
    EXPECT_THROW(bake_billboard_cloud(broadleaf(), s), std::invalid_argument);
    s = broadleaf_settings();
    s.gaussian_sigma = -1.0f;
    EXPECT_THROW(bake_billboard_cloud(broadleaf(), s), std::invalid_argument);
    s = broadleaf_settings();
    s.atlas_width = 16;
    s.atlas_height = 16;
    try {
        bake_billboard_cloud(broadleaf(), s);
        FAIL() << "no exception";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("16 x 16"), std::string::npos) << e.what();
    }
}

TEST(billboard_cloud, light_factor_is_ambient_plus_the_lit_and_transmitted_share) {
    const glm::vec3 up(0.0f, 1.0f, 0.0f);
    EXPECT_FLOAT_EQ(light_factor(up, up, 1.0f, 0.3f), 1.0f);                 // 0.3 + 0.7·1
    EXPECT_FLOAT_EQ(light_factor(up, up, 0.0f, 0.3f), 0.3f);                 // in shadow: ambient
    EXPECT_FLOAT_EQ(light_factor(-up, up, 1.0f, 0.3f), 0.3f + 0.7f * 0.35f);  // lit from behind: 0.545
    const glm::vec3 l = glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f));
    EXPECT_NEAR(light_factor(up, l, 0.5f, 0.3f), 0.3f + 0.7f * 0.5f * 0.70710678f, 1e-6f);  // 0.5475
}

// Behrendt 2005 §2.3, pre-lighting "for a single light-position including all shadows": two
// horizontal 1 m x 0.5 m cards, one 2 m above the other, lit straight from above. The upper card
// is lit fully (factor 1: the pre-lit colour is the albedo), the lower one lies in its shadow
// (factor = ambient 0.3: 160 green becomes 48).
TEST(billboard_cloud, the_pre_lit_page_holds_the_plant_s_own_shadows) {
    plant_model plant;
    plant.name = "two cards";
    mesh_data& mesh = plant.lods[0];
    const glm::vec3 n(0.0f, 1.0f, 0.0f);
    for (const float y : {0.0f, 2.0f}) {
        const auto base = std::uint32_t(mesh.vertices.size());
        mesh.vertices.push_back({{0.0f, y, 0.0f}, n, {0, 1}});
        mesh.vertices.push_back({{1.0f, y, 0.0f}, n, {1, 1}});
        mesh.vertices.push_back({{1.0f, y, -0.5f}, n, {1, 0}});
        mesh.vertices.push_back({{0.0f, y, -0.5f}, n, {0, 0}});
        for (const std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + k);
    }
    mesh.submeshes = {{0, 12, material_kind::leaf}};
    plant.leaf_texture = solid(40, 160, 30);
    plant.bark_texture = solid(120, 80, 40);
    billboard_cloud_settings s;
    s.clustering.method = clustering_method::kmeans;
    s.clustering.target_clusters = 2;
    s.atlas_width = 128;
    s.atlas_height = 64;
    s.pre_light_direction = n;
    s.pre_light_ambient = 0.3f;
    const billboard_cloud cloud = bake_billboard_cloud(plant, s);
    ASSERT_EQ(cloud.clusters.size(), 2u);
    const image_rgba8& albedo = cloud.page(cloud_atlas_page::albedo);
    const image_rgba8& pre_lit = cloud.page(cloud_atlas_page::pre_lit);
    // Per billboard, the centre texel of the side seen from above (its plane normal up).
    std::vector<std::pair<float, int>> greens;  // (height, pre-lit green)
    for (const cloud_billboard& b : cloud.billboards) {
        const bool front_up = b.plane.normal().y > 0.5f;
        const std::uint32_t half = b.rect.width / 2;
        const std::uint32_t x = b.rect.x + (front_up ? 0 : half) + half / 2, y = b.rect.y + b.rect.height / 2;
        ASSERT_EQ(albedo.at(x, y)[1], 160);
        EXPECT_EQ(pre_lit.at(x, y)[3], albedo.at(x, y)[3]);  // alpha as the colour page's
        greens.emplace_back(b.plane.origin.y, pre_lit.at(x, y)[1]);
    }
    ASSERT_EQ(greens.size(), 2u);
    std::sort(greens.begin(), greens.end());
    EXPECT_EQ(greens[0].second, 48);   // the lower card: 160 · 0.3
    EXPECT_EQ(greens[1].second, 160);  // the upper card: 160 · 1
}

}  // namespace
}  // namespace sylva
