#pragma once
// LoDF foliage (Rebollo 2006 §4): each plant slot's clusters, one glMultiDrawElementsIndirect
// over the slot's persistent commands (systems/render/lodf_commands.h), drawn like leaf cards
// (alpha-tested, two-sided) into the shadow cascades and the view. The slots' instance records
// lead the frame's (resources/draw_list.h lodf_instances), so a slot's commands name its record
// by the slot's index and never change for it. The trunk is a mesh (mesh_draw).
#include "systems/render/passes/pass_context.h"

namespace sylva::render {

class lodf_commands;

class lodf_draw final : public surface_draw {
public:
    void set_commands(const lodf_commands* commands) { m_commands = commands; }
    void draw(pass_context& context, const draw_target& target) const override;

private:
    const lodf_commands* m_commands = nullptr;
};

}  // namespace sylva::render
