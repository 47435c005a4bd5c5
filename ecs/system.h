#pragma once
// Everything a system file needs: phases, reads<>/writes<> declarations, system_context and the
// parallel helpers. A system is a struct:
//
//   struct cull_system {
//       static constexpr std::string_view k_name = "cull";
//       static constexpr ecs::phase k_phase = ecs::phase::cull;
//       static constexpr bool k_main_thread = false;  // optional; true = GL thread
//       using reads = ecs::reads<world_transform, bounds, camera>;
//       using writes = ecs::writes<lod_state>;
//       static void run(ecs::system_context<cull_system>& ctx);
//   };
#include "ecs/access.h"
#include "ecs/command_buffer.h"
#include "ecs/parallel.h"
#include "ecs/system_context.h"
#include "ecs/world.h"
