#include "systems/render/passes/lodf_draw.h"

#include "resources/draw_list.h"
#include "resources/sort_key.h"
#include "systems/render/lodf_commands.h"
#include "systems/render/renderer.h"

namespace sylva::render {

void lodf_draw::draw(pass_context& context, const draw_target& target) const {
    const frame_view& view = *context.view;
    if (!m_commands || !view.lodf || (target.kind != pass_kind::shadow && target.kind != pass_kind::view)) return;
    const bool shadow = target.kind == pass_kind::shadow;
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, m_commands->buffer());
    glBindTextureUnit(0, context.textures->leaf.id());
    if (!shadow) glBindBufferBase(GL_UNIFORM_BUFFER, 1, context.textures->species_block.id());
    glDisable(GL_CULL_FACE);  // leaves are seen from both sides
    for (std::uint32_t s = 0; s < view.lodf->slots.size(); ++s) {
        const lodf_slot& slot = view.lodf->slots[s];
        if (slot.plant == k_no_lodf_slot || m_commands->slot_commands(s) == 0) continue;
        const render_pass pass = shadow ? shadow_pass(target.cascade) : render_pass::opaque;
        if (s >= view.draws->lodf_pass_masks.size() || !(view.draws->lodf_pass_masks[s] & (1u << unsigned(pass))))
            continue;
        const lighting_variant lighting = view.library->species[slot.species].lighting;
        // A slot that is a transition's partner dissolves (its record's fade below 1).
        const bool faded = !shadow && view.draws->lodf_instances[s].fade < 1.0f;
        const surface_program& program = context.programs->surface(
            shadow ? pass_kind::shadow : faded ? pass_kind::view_faded : pass_kind::view, material_kind::leaf,
            primitive_kind::triangles, lighting);
        glUseProgram(program.id);
        if (shadow) glUniform1i(program.cascade, target.cascade);
        glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT,
                                    reinterpret_cast<const void*>(m_commands->slot_offset(s)),  // NOLINT: GL's offset
                                    GLsizei(m_commands->slot_commands(s)), 0);
        ++context.draw_calls;
    }
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, context.frame_indirect_buffer);
}

}  // namespace sylva::render
