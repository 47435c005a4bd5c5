// The glTF importer against fixtures that reproduce real-world tree files (tests/models/
// gltf_fixtures.h): leaf/bark classification without trusting the material, units, bounds,
// the leaf atlas, the reduced levels, round trips through the exporter and named errors.
#include "models/gltf/gltf_import.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <glm/geometric.hpp>
#include <stdexcept>

#include "models/gltf/gltf_export.h"
#include "models/generate/textures.h"
#include "models/generate/tree_generator.h"
#include "tests/app/hostile_inputs.h"
#include "tests/models/gltf/gltf_fixtures.h"

#include <fstream>

namespace sylva {
namespace {

namespace fs = std::filesystem;
constexpr std::uint32_t k_texture_size = 128;

class gltf_import : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        m_dir = fs::temp_directory_path() /
                ("sylva_gltf_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    fs::path m_dir;
};

std::uint32_t triangles_of(const mesh_data& mesh, material_kind kind) {
    std::uint32_t n = 0;
    for (const submesh& s : mesh.submeshes)
        if (s.material == kind) n += s.index_count / 3;
    return n;
}

float leaf_area(const mesh_data& mesh) {
    float area = 0;
    for (const submesh& s : mesh.submeshes) {
        if (s.material != material_kind::leaf) continue;
        for (std::uint32_t i = s.first_index; i < s.first_index + s.index_count; i += 3) {
            const glm::vec3 a = mesh.vertices[mesh.indices[i]].position,
                            b = mesh.vertices[mesh.indices[i + 1]].position,
                            c = mesh.vertices[mesh.indices[i + 2]].position;
            area += 0.5f * glm::length(glm::cross(b - a, c - a));
        }
    }
    return area;
}

std::size_t texels_with_alpha_below(const image_rgba8& image, int alpha) {
    std::size_t n = 0;
    for (std::size_t i = 3; i < image.texels.size(); i += 4) n += image.texels[i] < alpha;
    return n;
}

// What every fixture tree shares: a 6 m trunk (bark) under a crown of 200 cards (leaf).
void expect_simple_tree(const gltf_import_result& r) {
    ASSERT_EQ(r.primitives.size(), 2u);
    EXPECT_FALSE(r.primitives[0].leaf) << r.primitives[0].label;
    EXPECT_TRUE(r.primitives[1].leaf) << r.primitives[1].label;
    const mesh_data& full = r.model.lods[0];
    EXPECT_EQ(triangles_of(full, material_kind::leaf), 2 * test::k_fixture_leaf_cards);
    EXPECT_EQ(triangles_of(full, material_kind::bark), 12u * 8u * 2u);
    EXPECT_NEAR(full.bounds_min.y, 0.0f, 1e-3f);
    EXPECT_GT(full.bounds_max.y, test::k_fixture_trunk_height);
    EXPECT_LT(full.bounds_max.y, 7.5f);
    EXPECT_EQ(r.model.leaf_texture.width, k_texture_size);
    EXPECT_EQ(r.model.leaf_texture.height, k_texture_size);
    EXPECT_EQ(r.model.bark_texture.width, k_texture_size);
    EXPECT_FALSE(r.model.has_hierarchy);
}

TEST_F(gltf_import, opaque_leaf_material_with_an_alpha_texture_is_classified_as_leaf) {
    const gltf_import_result r =
        import_gltf_plant(test::write_opaque_leaves(m_dir, true), k_texture_size);
    expect_simple_tree(r);
    EXPECT_GT(r.primitives[1].alpha_ratio, 0.4f);
    EXPECT_EQ(r.primitives[1].components, test::k_fixture_leaf_cards);
    EXPECT_EQ(r.primitives[0].components, 1u);
    ASSERT_EQ(r.model.lods[0].leaves.size(), test::k_fixture_leaf_cards);
    EXPECT_NEAR(r.model.lods[0].leaves[0].size, 0.3f * std::sqrt(2.0f), 0.2f);
    EXPECT_FLOAT_EQ(r.model.source_unit_scale, 1.0f);
    // The atlas keeps the cut-outs: leaves stay alpha-tested whatever the material said.
    EXPECT_GT(texels_with_alpha_below(r.model.leaf_texture, 128),
              r.model.leaf_texture.texels.size() / 4 / 4);
    EXPECT_EQ(texels_with_alpha_below(r.model.bark_texture, 255), 0u);
    EXPECT_EQ(r.model.name, "opaque_leaves");
}

TEST_F(gltf_import, embedded_and_external_textures_import_alike) {
    const gltf_import_result embedded =
        import_gltf_plant(test::write_opaque_leaves(m_dir, true), k_texture_size);
    const gltf_import_result external =
        import_gltf_plant(test::write_opaque_leaves(m_dir, false), k_texture_size);
    ASSERT_TRUE(fs::exists(m_dir / "leaves.png"));
    expect_simple_tree(external);
    EXPECT_TRUE(external.warnings.empty());
    EXPECT_EQ(embedded.model.leaf_texture.texels, external.model.leaf_texture.texels);
    EXPECT_EQ(embedded.model.lods[0].indices, external.model.lods[0].indices);
}

TEST_F(gltf_import, many_materials_merge_into_one_leaf_atlas_and_one_bark_texture) {
    const gltf_import_result r =
        import_gltf_plant(test::write_many_materials(m_dir), k_texture_size);
    EXPECT_EQ(r.materials.size(), 8u);
    ASSERT_EQ(r.primitives.size(), 8u);
    for (std::size_t i = 0; i < 8; ++i)
        EXPECT_EQ(r.primitives[i].leaf, i >= 2) << r.primitives[i].label;
    const mesh_data& full = r.model.lods[0];
    ASSERT_EQ(full.submeshes.size(), 2u);
    EXPECT_EQ(triangles_of(full, material_kind::leaf), 6u * 40u * 2u);
    // Six materials in a 3 x 3 grid: cells 0..5 hold a leaf, 6..8 stay empty.
    const std::uint32_t cell = k_texture_size / 3;
    for (std::uint32_t c = 0; c < 9; ++c) {
        const std::uint8_t* centre =
            r.model.leaf_texture.at(c % 3 * cell + cell / 2, c / 3 * cell + cell / 2);
        EXPECT_EQ(centre[3] > 128, c < 6) << "atlas cell " << c;
    }
    // Every leaf uv lands inside one of the six used cells.
    for (std::uint32_t i = full.submeshes[1].first_index;
         i < full.submeshes[1].first_index + full.submeshes[1].index_count; ++i) {
        const glm::vec2 uv = full.vertices[full.indices[i]].uv;
        ASSERT_GE(uv.x, 0.0f);
        ASSERT_LE(uv.x, 1.0f);
        ASSERT_LT(uv.y, 2.0f / 3.0f + 1e-4f);
    }
}

TEST_F(gltf_import, nested_mesh_nodes_give_a_hierarchy_and_a_single_node_does_not) {
    const gltf_import_result r =
        import_gltf_plant(test::write_branch_hierarchy(m_dir), k_texture_size);
    EXPECT_TRUE(r.model.has_hierarchy);
    EXPECT_EQ(r.hierarchy_depth, 3u);
    EXPECT_EQ(r.mesh_nodes, 3u);
    EXPECT_FALSE(r.primitives[0].leaf);
    EXPECT_FALSE(r.primitives[1].leaf);
    EXPECT_TRUE(r.primitives[2].leaf);
    // Every full-level triangle names its node: trunk (node 0, level 0) and branch (node 1,
    // level 1) bark first, then the twig's leaves (node 2, level 2, parent the branch).
    const mesh_data& full = r.model.lods[0];
    ASSERT_EQ(full.parts.size(), full.triangle_count());
    EXPECT_EQ(full.parts.front().branch, 0u);
    EXPECT_EQ(full.parts.front().kind, part_kind::bark);
    EXPECT_EQ(full.parts[full.submeshes[0].index_count / 3 - 1].level, 1u);
    EXPECT_EQ(full.parts.back().branch, 2u);
    EXPECT_EQ(full.parts.back().level, 2u);
    EXPECT_EQ(full.parts.back().parent_branch, 1u);
    EXPECT_EQ(full.parts.back().kind, part_kind::leaf);
    EXPECT_FALSE(import_gltf_plant(test::write_opaque_leaves(m_dir, true), k_texture_size)
                     .model.has_hierarchy);
}

TEST_F(gltf_import, missing_texture_warns_and_falls_back_to_the_base_colour_factor) {
    const gltf_import_result r =
        import_gltf_plant(test::write_missing_texture(m_dir), k_texture_size);
    expect_simple_tree(r);
    ASSERT_FALSE(r.warnings.empty());
    EXPECT_NE(r.warnings[0].find("missing_leaf.png"), std::string::npos) << r.warnings[0];
    const std::uint8_t* texel = r.model.leaf_texture.at(k_texture_size / 2, k_texture_size / 2);
    EXPECT_GT(texel[1], texel[0]);  // the green factor
    EXPECT_EQ(texel[3], 255);
}

TEST_F(gltf_import, centimetre_models_become_metres_with_or_without_a_root_scale) {
    for (const fs::path& file :
         {test::write_centimetres_scaled(m_dir), test::write_centimetres_unscaled(m_dir)}) {
        SCOPED_TRACE(file.filename().string());
        const gltf_import_result r = import_gltf_plant(file, k_texture_size);
        expect_simple_tree(r);
        EXPECT_FLOAT_EQ(r.model.source_unit_scale, 0.01f);
    }
}

TEST_F(gltf_import, jpeg_textures_decode_and_tiled_leaf_uvs_come_back_into_the_atlas) {
    const gltf_import_result r =
        import_gltf_plant(test::write_jpeg_bark_and_tiled_leaf_uvs(m_dir), k_texture_size);
    ASSERT_TRUE(fs::exists(m_dir / "bark.jpg"));
    expect_simple_tree(r);
    EXPECT_TRUE(r.warnings.empty());
    const std::uint8_t* bark = r.model.bark_texture.at(1, 1);
    EXPECT_GT(bark[0], bark[2]);  // brown, not the white of a missing texture
    const mesh_data& full = r.model.lods[0];
    for (std::uint32_t i = full.submeshes[1].first_index;
         i < full.submeshes[1].first_index + full.submeshes[1].index_count; ++i) {
        const glm::vec2 uv = full.vertices[full.indices[i]].uv;
        ASSERT_TRUE(uv.x == 0.0f || uv.x == 1.0f) << uv.x;
        ASSERT_TRUE(uv.y == 0.0f || uv.y == 1.0f) << uv.y;
    }
}

TEST_F(gltf_import, blend_leaves_are_leaves) {
    expect_simple_tree(import_gltf_plant(test::write_blend_leaves(m_dir), k_texture_size));
}

TEST_F(gltf_import, reduced_and_far_levels_shrink_bark_and_thin_leaves_keeping_leaf_area) {
    const plant_model m =
        import_plant_model(test::write_opaque_leaves(m_dir, true), k_texture_size);
    const auto full = float(m.lods[0].triangle_count());
    EXPECT_GT(m.lods[1].triangle_count(), 0u);
    EXPECT_LE(float(m.lods[1].triangle_count()), 0.16f * full);
    EXPECT_LE(float(m.lods[2].triangle_count()), 0.07f * full);
    EXPECT_GT(triangles_of(m.lods[2], material_kind::bark), 0u);
    EXPECT_GT(triangles_of(m.lods[2], material_kind::leaf), 0u);
    EXPECT_NEAR(leaf_area(m.lods[1]), leaf_area(m.lods[0]), 0.15f * leaf_area(m.lods[0]));
    EXPECT_NEAR(leaf_area(m.lods[2]), leaf_area(m.lods[0]), 0.15f * leaf_area(m.lods[0]));
}

void expect_error(const fs::path& file, const std::vector<std::string>& parts) {
    try {
        import_plant_model(file, k_texture_size);
        ADD_FAILURE() << file << " imported";
    } catch (const std::runtime_error& e) {
        for (const std::string& part : parts)
            EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
}

TEST_F(gltf_import, broken_files_throw_naming_the_file_and_the_part) {
    expect_error(test::write_lines_primitive(m_dir),
                 {"lines.gltf: mesh 'leaves' primitive 1: mode LINES is not supported"});
    expect_error(test::write_nan_position(m_dir),
                 {"nan_position.glb: mesh 'trunk' primitive 0", "non-finite"});
    expect_error(test::write_truncated_glb(m_dir), {"truncated.glb"});
    expect_error(test::write_missing_buffer(m_dir), {"missing_buffer.gltf", "missing_buffer.bin"});
    expect_error(test::write_bad_json(m_dir), {"bad_json.gltf"});
    expect_error(test::write_no_meshes(m_dir), {"no_meshes.gltf", "no meshes"});
    expect_error(m_dir / "absent.glb", {"absent.glb", "no such file"});
    expect_error(test::write_draco_required(m_dir), {"draco.gltf", "KHR_draco_mesh_compression"});
    fs::create_directories(m_dir);
    std::ofstream(m_dir / "tree.obj") << "v 0 0 0\n";
    expect_error(m_dir / "tree.obj", {"tree.obj", "not a glTF file"});
}

// --- hostile files (issue 19) -----------------------------------------------------------------

// On main indices went through float: 16,777,217 became 16,777,216 and 0xFFFFFFF0 became vertex
// 0 (the float 2^32 truncated), silently drawing a triangle to the wrong vertex.
TEST_F(gltf_import, indices_are_read_exactly) {
    fs::create_directories(m_dir);
    test::write_file(m_dir / "big_index.glb",
                     test::make_glb(test::triangle_json(), test::make_triangle_buffer(0, 1, 16777217).bytes));
    expect_error(m_dir / "big_index.glb", {"index 16777217 is past the last vertex"});
    test::write_file(m_dir / "wrapped.glb",
                     test::make_glb(test::triangle_json(), test::make_triangle_buffer(0, 1, 0xFFFFFFF0u).bytes));
    expect_error(m_dir / "wrapped.glb", {"index 4294967280 is past the last vertex"});
    test::write_file(m_dir / "good.glb", test::make_glb(test::triangle_json(), test::make_triangle_buffer().bytes));
    const gltf_import_result r = import_gltf_plant(m_dir / "good.glb", 16);
    EXPECT_EQ(r.model.lods[0].triangle_count(), 1u);
}

// On main a 2 KB file claiming 750 million elements allocated 3 GB before the bounds check.
TEST_F(gltf_import, counts_are_checked_against_the_buffer_before_allocating) {
    fs::create_directories(m_dir);
    test::write_file(m_dir / "liar.glb", test::make_glb(test::triangle_json("", 750000000),
                                                        test::make_triangle_buffer().bytes));
    expect_error(m_dir / "liar.glb", {"liar.glb", "750000000 elements", "reads past the end of its buffer"});
}

// Found by the glTF fuzz target: a NORMAL accessor shorter than POSITION was read past its end
// (a heap overflow under ASan, garbage normals without it, on main too).
TEST_F(gltf_import, attributes_shorter_than_position_are_refused) {
    fs::create_directories(m_dir);
    std::string json = test::triangle_json();
    const std::string position_only = R"("attributes":{"POSITION":1})";
    json.replace(json.find(position_only), position_only.size(), R"("attributes":{"POSITION":1,"NORMAL":2})");
    json.replace(json.rfind("]}"), 2,
                 R"(,{"bufferView":1,"componentType":5126,"count":2,"type":"VEC3"}]})");
    test::write_file(m_dir / "short_normals.glb", test::make_glb(json, test::make_triangle_buffer().bytes));
    expect_error(m_dir / "short_normals.glb", {"short_normals.glb", "NORMAL has 2 elements but POSITION has 3"});
}

TEST_F(gltf_import, json_nested_beyond_256_levels_never_reaches_tinygltf) {
    fs::create_directories(m_dir);
    const std::string extras = ",\"extras\":" + std::string(100000, '[') + std::string(100000, ']');
    test::write_file(m_dir / "deep.glb",
                     test::make_glb(test::triangle_json("", 3, extras), test::make_triangle_buffer().bytes));
    expect_error(m_dir / "deep.glb", {"deep.glb", "nests deeper than 256 levels"});
}

// On main "../../etc/passwd" was read, and tinygltf's size-mismatch message told its size.
TEST_F(gltf_import, external_files_must_be_inside_the_models_folder) {
    fs::create_directories(m_dir / "model");
    std::ofstream(m_dir / "outside.bin") << std::string(12345, 'o');
    const auto bin = test::make_triangle_buffer().bytes;
    test::write_file(m_dir / "model" / "tri.bin", std::string(bin.begin(), bin.end()));
    test::write_file(m_dir / "model" / "ok.gltf", test::triangle_json("tri.bin"));
    EXPECT_NO_THROW(import_gltf_plant(m_dir / "model" / "ok.gltf", 16));
    test::write_file(m_dir / "model" / "escape.gltf", test::triangle_json("../outside.bin"));
    expect_error(m_dir / "model" / "escape.gltf",
                 {"escape.gltf: buffer 0: URI '../outside.bin' leads outside the model's folder"});
    fs::create_symlink(m_dir / "outside.bin", m_dir / "model" / "link.bin");
    test::write_file(m_dir / "model" / "link.gltf", test::triangle_json("link.bin"));
    expect_error(m_dir / "model" / "link.gltf", {"URI 'link.bin' leads outside the model's folder"});
    try {
        import_gltf_plant(m_dir / "model" / "escape.gltf", 16);
    } catch (const std::exception& e) {
        EXPECT_EQ(std::string(e.what()).find("12345"), std::string::npos) << "reveals the size: " << e.what();
    }
}

TEST_F(gltf_import, image_dimensions_are_bounded_before_decoding) {
    fs::create_directories(m_dir / "model");
    const auto bin = test::make_triangle_buffer().bytes;
    test::write_file(m_dir / "model" / "tri.bin", std::string(bin.begin(), bin.end()));
    test::write_file(m_dir / "model" / "big.png", test::png_header_claiming(30000, 30000));
    test::write_file(m_dir / "model" / "tree.gltf",
                     test::triangle_json("tri.bin", 3, R"(,"images":[{"uri":"big.png"}],"textures":[{"source":0}])"));
    expect_error(m_dir / "model" / "tree.gltf", {"30000x30000 pixels is more than Sylva reads"});
}

plant_model generated_tree() {
    plant_model m;
    m.name = "broadleaf";
    m.lods = {generate_tree(tree_preset("broadleaf"), 3, tree_detail::full),
              generate_tree(tree_preset("broadleaf"), 3, tree_detail::reduced),
              generate_tree(tree_preset("broadleaf"), 3, tree_detail::far)};
    m.leaf_texture = generate_leaf_texture("broadleaf", k_texture_size);
    m.bark_texture = generate_bark_texture("broadleaf", k_texture_size);
    return m;
}

TEST_F(gltf_import, export_then_import_keeps_every_level_and_its_leaf_and_bark_triangles) {
    const plant_model source = generated_tree();
    fs::create_directories(m_dir);
    for (const plant_lod lod : {plant_lod::full, plant_lod::reduced, plant_lod::far}) {
        SCOPED_TRACE(int(lod));
        const mesh_data& expected = source.lods[std::size_t(lod)];
        const fs::path file = m_dir / ("tree_" + std::to_string(int(lod)) + ".glb");
        export_plant_glb(source, lod, file);
        const gltf_import_result r = import_gltf_plant(file, k_texture_size);
        EXPECT_EQ(r.model.lods[0].triangle_count(), expected.triangle_count());
        EXPECT_EQ(triangles_of(r.model.lods[0], material_kind::leaf),
                  triangles_of(expected, material_kind::leaf));
        EXPECT_EQ(triangles_of(r.model.lods[0], material_kind::bark),
                  triangles_of(expected, material_kind::bark));
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(r.model.lods[0].bounds_min[k], expected.bounds_min[k], 1e-3f);
            EXPECT_NEAR(r.model.lods[0].bounds_max[k], expected.bounds_max[k], 1e-3f);
        }
    }
}

TEST_F(gltf_import, exported_textures_survive_the_round_trip) {
    const plant_model source = generated_tree();
    fs::create_directories(m_dir);
    export_plant_glb(source, plant_lod::far, m_dir / "tree.glb");
    const plant_model back = import_plant_model(m_dir / "tree.glb", k_texture_size);
    EXPECT_EQ(back.bark_texture.texels, source.bark_texture.texels);
    EXPECT_EQ(back.leaf_texture.texels, source.leaf_texture.texels);
}

}  // namespace
}  // namespace sylva

namespace sylva {
namespace {

// Two trees from other makers and exporters (tests/data/trees/README.md): a Blender export with
// alpha-masked leaf cards and external PNGs, and a COLLADA2GLTF binary with alpha-blended cards
// and an untextured trunk. Every triangle is kept on the side its material says.
TEST(gltf_import_of_other_makers, both_trees_keep_their_leaves_and_bark) {
    const std::filesystem::path trees = std::filesystem::path(SYLVA_SOURCE_DIR) / "tests/data/trees";
    const plant_model quaternius = import_plant_model(trees / "quaternius_common_tree_1/CommonTree_1.gltf", 256);
    EXPECT_EQ(triangles_of(quaternius.lods[0], material_kind::leaf), 1920u);
    EXPECT_EQ(triangles_of(quaternius.lods[0], material_kind::bark), 4345u);
    const plant_model cesium = import_plant_model(trees / "cesium_tree.glb", 256);
    EXPECT_EQ(triangles_of(cesium.lods[0], material_kind::leaf), 892u);
    // 1,184 trunk triangles, 120 of them of zero area (dropped with a warning).
    EXPECT_EQ(triangles_of(cesium.lods[0], material_kind::bark), 1064u);
    for (const plant_model* p : {&quaternius, &cesium}) {
        // The leaf texture keeps its cut-out: some texels transparent, some opaque.
        std::size_t clear = 0, solid = 0;
        for (std::size_t i = 3; i < p->leaf_texture.texels.size(); i += 4)
            (p->leaf_texture.texels[i] < 128 ? clear : solid) += 1;
        EXPECT_GT(clear, 0u);
        EXPECT_GT(solid, 0u);
        // Standing on the ground, a few metres tall.
        glm::vec3 lo(1e9f), hi(-1e9f);
        for (const vertex& v : p->lods[0].vertices) lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
        EXPECT_NEAR(lo.y, 0.0f, 0.3f);
        EXPECT_GT(hi.y, 5.0f);
    }
}

}  // namespace
}  // namespace sylva
