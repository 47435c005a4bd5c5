// GL behaviour of the device pieces on an OSMesa context (llvmpipe).
#include <gtest/gtest.h>

#include <cstring>

#include "gl_test_support.h"
#include "systems/render/frame_ring.h"
#include "systems/render/gl.h"
#include "systems/render/mesh_pool.h"
#include "systems/render/render_target.h"
#include "systems/render/shader_library.h"

namespace sylva {
namespace {
using render::frame_ring;
using render::mesh_pool;

mesh_data quad(float z) {
    mesh_data m;
    m.vertices = {{{-1, -1, z}, {0, 0, 1}, {0, 0}}, {{1, -1, z}, {0, 0, 1}, {1, 0}},
                  {{1, 1, z}, {0, 0, 1}, {1, 1}}, {{-1, 1, z}, {0, 0, 1}, {0, 1}}};
    m.indices = {0, 1, 2, 0, 2, 3};
    m.submeshes = {{0, 6, material_kind::bark}};
    return m;
}

TEST(gl_context, osmesa_gives_a_gl_4_5_core_context) {
    SYLVA_REQUIRE_GL();
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_GE(major * 10 + minor, 45);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    EXPECT_FALSE(testing::shared_gl_context()->renderer().empty());
}

TEST(mesh_pool, meshes_share_one_buffer_with_offsets_and_survive_growth) {
    SYLVA_REQUIRE_GL();
    mesh_pool pool;
    const auto a = pool.add(quad(0.0f));
    // Enough meshes to force the vertex and index buffers to grow (copying what was there).
    mesh_data big;
    big.vertices.resize(70000);
    big.indices.resize(300000, 0);
    big.submeshes = {{0, 300000, material_kind::leaf}};
    const auto b = pool.add(big);
    const auto c = pool.add(quad(1.0f));
    EXPECT_EQ(a, 0);
    EXPECT_EQ(b, 1);
    EXPECT_EQ(c, 2);
    EXPECT_EQ(pool.get(c).submeshes[0].base_vertex, 4 + 70000);
    EXPECT_EQ(pool.get(c).submeshes[0].first_index, 6u + 300000u);
    EXPECT_EQ(pool.get(a).triangle_count, 2u);
    // The first mesh's indices are still in the grown buffer.
    GLint element_buffer = 0;
    glGetVertexArrayiv(pool.vertex_array(), GL_ELEMENT_ARRAY_BUFFER_BINDING, &element_buffer);
    std::uint32_t first[6] = {};
    glGetNamedBufferSubData(GLuint(element_buffer), 0, sizeof(first), first);
    EXPECT_EQ(first[2], 2u);
    EXPECT_EQ(first[5], 3u);
}

TEST(frame_ring, allocations_are_aligned_inside_the_frame_region_and_visible_to_gl) {
    SYLVA_REQUIRE_GL();
    frame_ring ring(4096, 3);
    for (int frame = 0; frame < 5; ++frame) {
        ring.begin_frame(1024);
        auto a = ring.allocate(100, 256);
        auto b = ring.allocate(100, 256);
        EXPECT_EQ(a.offset % 256, 0);
        EXPECT_EQ(b.offset - a.offset, 256);
        std::memset(a.data, frame + 1, 100);
        ring.end_frame();
        glFinish();
        unsigned char readback = 0;
        glGetNamedBufferSubData(ring.buffer(), a.offset + 50, 1, &readback);
        EXPECT_EQ(readback, frame + 1);  // coherent persistent mapping: no flush needed
    }
    ring.begin_frame(1024);
    EXPECT_THROW(ring.allocate(8192), std::runtime_error);
    ring.end_frame();
}

TEST(frame_ring, grows_when_a_frame_needs_more_than_a_region) {
    SYLVA_REQUIRE_GL();
    frame_ring ring(1024, 2);
    ring.begin_frame(10000);
    EXPECT_GE(ring.bytes_per_frame(), 10000u);
    EXPECT_NO_THROW(ring.allocate(10000, 16));
    ring.end_frame();
}

TEST(shader_library, every_surface_variant_compiles_and_links_once) {
    SYLVA_REQUIRE_GL();
    render::shader_library shaders;
    struct variant {
        std::string vertex;
        std::string fragment;
        std::vector<std::string> defines;
    };
    const std::vector<variant> variants = {
        {"surface.vert", "mesh.frag", {}},
        {"surface.vert", "mesh.frag", {"MATERIAL_LEAF"}},
        {"surface.vert", "mesh.frag", {"MATERIAL_GROUND"}},
        {"surface.vert", "cloud.frag", {"MATERIAL_BILLBOARD_CLOUD"}},
        {"surface_shadow.vert", "", {}},
        {"surface_shadow.vert", "surface_shadow.frag", {"MATERIAL_LEAF"}}};
    for (const variant& v : variants) {
        const GLuint p = shaders.program({v.vertex, v.fragment, v.defines, {}});
        EXPECT_NE(p, 0u);
        EXPECT_EQ(shaders.program({v.vertex, v.fragment, v.defines, {}}), p);
    }
    EXPECT_NE(shaders.program({"sky.vert", "sky.frag", {}, {}}), 0u);
    EXPECT_EQ(shaders.compiled_count(), variants.size() + 1);
}

TEST(shader_library, point_and_line_variants_compile_and_link_with_the_line_geometry_shader) {
    SYLVA_REQUIRE_GL();
    render::shader_library shaders;
    // Leaf samples, and bark samples (bark has no material define).
    for (const std::vector<std::string>& material : {std::vector<std::string>{"MATERIAL_LEAF"}, std::vector<std::string>{}}) {
        auto with = [&](std::initializer_list<std::string> more) {
            std::vector<std::string> d = material;
            d.insert(d.end(), more);
            return d;
        };
        EXPECT_NE(shaders.program({"point.vert", "point.frag", with({"PRIMITIVE_POINTS"}), {}}), 0u);
        EXPECT_NE(shaders.program({"point.vert", "point.frag", with({"PRIMITIVE_POINTS", "WRITE_ID"}), {}}), 0u);
        EXPECT_NE(shaders.program({"surface_shadow.vert", "", with({"PRIMITIVE_POINTS"}), {}}), 0u);
        EXPECT_NE(shaders.program({"surface.vert", "line.frag", with({"PRIMITIVE_LINES", "LINE_QUADS"}), "line.geom"}),
                  0u);
        EXPECT_NE(shaders.program({"surface.vert", "line.frag",
                                   with({"PRIMITIVE_LINES", "LINE_QUADS", "WRITE_ID"}), "line.geom"}),
                  0u);
        EXPECT_NE(shaders.program({"surface.vert", "line.frag", with({"PRIMITIVE_LINES", "WRITE_ID"}), {}}), 0u);
        EXPECT_NE(shaders.program({"surface_shadow.vert", "", with({"PRIMITIVE_LINES"}), {}}), 0u);
    }
    EXPECT_EQ(shaders.compiled_count(), 14u);
}

TEST(shader_library, includes_are_expanded_and_missing_files_are_named) {
    const std::string text = render::shader_library::expand("surface_shadow.vert", {"PRIMITIVE_POINTS"});
    EXPECT_NE(text.find("#define PRIMITIVE_POINTS"), std::string::npos);
    EXPECT_NE(text.find("uniform frame_block"), std::string::npos);  // from common.glsl
    EXPECT_EQ(text.find("#include"), std::string::npos);
    try {
        render::shader_library::expand("missing.vert", {});
        FAIL() << "expected an error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("shaders/missing.vert"), std::string::npos);
    }
}

TEST(render_target, reads_back_top_row_first) {
    SYLVA_REQUIRE_GL();
    render::render_target target(8, 4);
    target.bind();
    glEnable(GL_SCISSOR_TEST);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(0, 3, 8, 1);  // GL's top row (y = 3)
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    const image_rgba8 image = target.read_color();
    EXPECT_EQ(image.at(0, 0)[2], 255);  // blue on the image's first row
    EXPECT_EQ(image.at(0, 3)[0], 255);  // red at the bottom
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace
}  // namespace sylva
