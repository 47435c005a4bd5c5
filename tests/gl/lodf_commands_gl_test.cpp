// LoDF's indirect commands on the GPU (systems/render/lodf_commands.h, Rebollo 2006 §4): a
// change of detail uploads the commands of the changed clusters and nothing else, the buffer
// holds what the CPU thinks it holds, and drawing it rasterises exactly the foliage of that
// level, from the full mesh's own vertices.
#include "systems/render/lodf_commands.h"

#include <gtest/gtest.h>

#include <set>

#include "gl_test_support.h"
#include "lod/lodf.h"
#include "models/generate/plant_library.h"
#include "systems/render/gl.h"

namespace sylva {
namespace {

using render::lodf_commands;

// Triangles a multi-draw of the slot's commands generates (rasterisation discarded).
std::uint64_t primitives_drawn(const render::mesh_pool& pool, const lodf_commands& commands, std::uint32_t slot) {
    static const char* k_vertex = "#version 450 core\nlayout(location = 0) in vec3 p;\nvoid main() { gl_Position = vec4(p, 1.0); }\n";
    const GLuint shader = glCreateShader(GL_VERTEX_SHADER);
    glShaderSource(shader, 1, &k_vertex, nullptr);
    glCompileShader(shader);
    const GLuint program = glCreateProgram();
    glAttachShader(program, shader);
    glLinkProgram(program);
    GLuint query = 0;
    glGenQueries(1, &query);
    glUseProgram(program);
    glBindVertexArray(pool.vertex_array());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, commands.buffer());
    glEnable(GL_RASTERIZER_DISCARD);
    glBeginQuery(GL_PRIMITIVES_GENERATED, query);
    glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                reinterpret_cast<const void*>(commands.slot_offset(slot)),  // NOLINT: GL's offset
                                GLsizei(commands.slot_mirror(slot).size()), 0);
    glEndQuery(GL_PRIMITIVES_GENERATED);
    glDisable(GL_RASTERIZER_DISCARD);
    GLuint64 generated = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &generated);
    glDeleteQueries(1, &query);
    glDeleteProgram(program);
    glDeleteShader(shader);
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    return generated;
}

std::vector<lodf_commands::command> read_back(const lodf_commands& commands, std::uint32_t slot) {
    std::vector<lodf_commands::command> out(commands.slot_mirror(slot).size());
    glGetNamedBufferSubData(commands.buffer(), GLintptr(commands.slot_offset(slot)),
                            GLsizeiptr(out.size() * sizeof(lodf_commands::command)), out.data());
    return out;
}

TEST(lodf_commands_gl, a_change_uploads_only_the_changed_clusters_and_draws_that_level) {
    SYLVA_REQUIRE_GL();
    const plant_model plant = generate_plant_model("broadleaf", 3, 32);
    const lodf_model lodf = bake_lodf(plant.lods[0], plant.has_hierarchy);
    const lodf_structure& f = lodf.structure;
    const auto g = std::uint32_t(f.clusters.size());
    render::mesh_pool pool;
    const std::uint16_t full = pool.add(plant.lods[0]);
    const std::uint64_t vertex_bytes_before = pool.uploaded_bytes();
    mesh_data foliage_list;
    foliage_list.indices = lodf.indices;
    foliage_list.submeshes = {{0, std::uint32_t(lodf.indices.size()), material_kind::leaf}};
    const std::uint16_t foliage = pool.add_indices(full, foliage_list);
    EXPECT_EQ(pool.uploaded_bytes() - vertex_bytes_before, lodf.indices.size() * 4) << "indices only: Eq. 3, no vertices";
    lodf_commands commands(3, g + 2);
    std::vector<cluster_changes> clusters(g);
    reset_lodf_clusters(f, clusters);
    EXPECT_EQ(commands.assign(1, f, pool.get(foliage).submeshes[0], 7, clusters), (g + 2) * 20u);
    EXPECT_EQ(read_back(commands, 1), std::vector(commands.slot_mirror(1).begin(), commands.slot_mirror(1).end()));
    const auto foliage_triangles = [&](std::uint32_t leaves) {
        const mesh_data m = lodf_mesh(plant.lods[0], lodf, leaves);
        return std::uint64_t(m.submeshes.back().index_count / 3);
    };
    EXPECT_EQ(primitives_drawn(pool, commands, 1), foliage_triangles(f.leaf_count));
    // Nothing changed: nothing uploaded.
    EXPECT_EQ(commands.update(1, clusters), 0u);
    // One collapse touches one cluster: one 20-byte command.
    std::uint32_t position = 0;
    std::vector<std::uint32_t> changed;
    retarget_lodf(f, clusters, position, 1, changed);
    ASSERT_EQ(changed.size(), 1u);
    EXPECT_EQ(commands.update(1, clusters), 20u);
    // A larger step: exactly the changed clusters' commands (in runs of neighbours).
    retarget_lodf(f, clusters, position, f.collapse_count() / 3, changed);
    EXPECT_EQ(commands.update(1, clusters), 20u * changed.size());
    EXPECT_EQ(read_back(commands, 1), std::vector(commands.slot_mirror(1).begin(), commands.slot_mirror(1).end()));
    EXPECT_EQ(primitives_drawn(pool, commands, 1), foliage_triangles(f.leaves_after(position)));
    // Every live command draws the slot's instance once.
    for (std::uint32_t c = 0; c < g; ++c) {
        EXPECT_EQ(commands.slot_mirror(1)[c].base_instance, 7u);
        EXPECT_EQ(commands.slot_mirror(1)[c].instance_count, 1u);
    }
    // The other slots were never touched; a released slot draws nothing.
    EXPECT_EQ(primitives_drawn(pool, commands, 0), 0u);
    EXPECT_EQ(commands.release(1), (g + 2) * 20u);
    EXPECT_EQ(primitives_drawn(pool, commands, 1), 0u);
}

}  // namespace
}  // namespace sylva
