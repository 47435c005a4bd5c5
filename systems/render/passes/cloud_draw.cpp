#include "systems/render/passes/cloud_draw.h"

namespace sylva::render {

// One-sided: each side of a billboard shows only to its own viewer. In a cascade, both sides of
// a billboard share its plane and silhouette (the back image is the front's mirror): culling
// the side turned away from the sun leaves one quad per billboard and the same shadow, at half
// the alpha-tested fragments.
void cloud_draw::draw(pass_context& context, const draw_target& target) const {
    if (target.kind != pass_kind::shadow && target.kind != pass_kind::view) return;
    const bool shadow = target.kind == pass_kind::shadow;
    const pass_commands& groups = target.commands(context);
    const scene_textures& textures = *context.textures;
    for (const lighting_variant l : k_all_lightings) {
        const command_range& range =
            groups[group_of(material_kind::billboard_cloud, primitive_kind::triangles, l)];
        if (range.count == 0) continue;
        const surface_program& program = context.programs->surface(
            target.kind, material_kind::billboard_cloud, primitive_kind::triangles, l);
        glUseProgram(program.id);
        if (shadow) glUniform1i(program.cascade, target.cascade);
        // Pre-lit clouds read the page lit at bake time in the colour page's place (same layout
        // and alpha); SH clouds add their transfer pages.
        glBindTextureUnit(0, !shadow && l == lighting_variant::pre_lit
                                 ? textures.cloud_pre_lit.id()
                                 : textures.cloud_albedo.id());
        glBindTextureUnit(2, textures.cloud_normal.id());
        if (!shadow && uses_transfer(l))
            glBindTextureUnit(3, textures.cloud_transfer.id());
        context.draw_group(range, program.id, true);
    }
}

}  // namespace sylva::render
