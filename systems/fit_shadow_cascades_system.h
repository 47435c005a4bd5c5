#pragma once
// Fits the sun's shadow cascades to the camera's view frustum every frame (practical split
// scheme, texel-snapped sphere fits: lighting/shadow_cascades.h). The cascades are a
// resource that build_draw_list reads to pick each cascade's casters and the renderer draws;
// fitted with culling (they depend on the camera and the sun alone), so that the auto ladder's
// solver can cost each plant's shadow at the cascade it falls in (select_representation).
// A cascade whose slice of the view holds no receiver (resources/shadow_receivers.h; when the
// world has receiver_heights) is marked, and nothing is drawn into it.
#include "components/camera.h"
#include "components/sun.h"
#include "ecs/system.h"
#include "scenarios/scenario.h"
#include "lighting/shadow_cascades.h"
#include "resources/shadow_receivers.h"

namespace sylva {

struct fit_shadow_cascades_system {
    static constexpr std::string_view k_name = "fit_shadow_cascades";
    static constexpr ecs::phase k_phase = ecs::phase::cull;
    using reads = ecs::reads<camera, sun, shadow_settings, receiver_heights>;
    using writes = ecs::writes<cascade_set>;
    static void run(ecs::system_context<fit_shadow_cascades_system>& ctx);
};

}  // namespace sylva
