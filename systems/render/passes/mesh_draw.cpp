#include "systems/render/passes/mesh_draw.h"

namespace sylva::render {

void mesh_draw::draw(pass_context& context, const draw_target& target) const {
    if (target.kind == pass_kind::shadow) draw_casters(context, target);
    if (target.kind == pass_kind::view) draw_view(context, target);
}

// Depth only: every lighting variant's group is drawn with the one shadow program of its
// material (the table folds the lighting axis of depth-only passes).
void mesh_draw::draw_casters(pass_context& context, const draw_target& target) {
    const pass_commands& groups = target.commands(context);
    auto draw = [&](material_kind material, lighting_variant lighting, GLuint texture) {
        const command_range& range =
            groups[group_of(material, primitive_kind::triangles, lighting)];
        if (range.count == 0) return;
        const surface_program& program = context.programs->surface(
            pass_kind::shadow, material, primitive_kind::triangles, lighting);
        glUseProgram(program.id);
        glUniform1i(program.cascade, target.cascade);
        if (texture) glBindTextureUnit(0, texture);
        context.draw_group(range, program.id, false);
    };
    draw(material_kind::ground, lighting_variant::normal_mapped, 0);
    for (const lighting_variant l : k_all_lightings) {
        draw(material_kind::bark, l, 0);
        draw(material_kind::leaf, l, context.textures->leaf.id());
        draw(material_kind::billboard, l, context.textures->billboard_albedo.id());
        draw(material_kind::facing_billboard, l, context.textures->billboard_albedo.id());
    }
}

void mesh_draw::draw_view(pass_context& context, const draw_target& target) {
    const pass_commands& groups = target.commands(context);
    const scene_textures& textures = *context.textures;
    auto program = [&](material_kind material, lighting_variant lighting, bool faded = false) {
        return context.programs
            ->surface(faded ? pass_kind::view_faded : pass_kind::view, material, primitive_kind::triangles, lighting)
            .id;
    };
    // Terrain and bark are closed, one-sided surfaces: back faces culled. Leaf cards and
    // billboards are seen from both sides.
    const command_range& ground =
        groups[group_of(material_kind::ground, primitive_kind::triangles)];
    if (ground.count) {
        glBindTextureUnit(0, textures.ground.id());
        context.draw_group(ground, program(material_kind::ground, lighting_variant::normal_mapped),
                           true);
    }
    glBindBufferBase(GL_UNIFORM_BUFFER, 1, textures.species_block.id());
    // One group: skip it when empty, else bind its textures and draw. The plants drawn whole
    // first, then the partners of transitions with the programs that dissolve them.
    auto draw = [&](material_kind material, lighting_variant lighting, bool faded, bool cull_back_faces,
                    auto bind_textures) {
        const command_range& range =
            groups[group_of(material, primitive_kind::triangles, lighting, faded)];
        if (!range.count) return;
        bind_textures();
        context.draw_group(range, program(material, lighting, faded), cull_back_faces);
    };
    for (const bool faded : {false, true})
        for (const lighting_variant l : k_all_lightings) {
            draw(material_kind::bark, l, faded, true, [&] { glBindTextureUnit(0, textures.bark.id()); });
            draw(material_kind::leaf, l, faded, false, [&] { glBindTextureUnit(0, textures.leaf.id()); });
            for (const material_kind billboard : {material_kind::billboard, material_kind::facing_billboard})
                draw(billboard, l, faded, false, [&] {
                    glBindTextureUnit(0, textures.billboard_albedo.id());
                    glBindTextureUnit(2, textures.billboard_normal.id());
                    if (uses_transfer(l)) glBindTextureUnit(3, textures.billboard_transfer.id());
                });
        }
}

}  // namespace sylva::render
