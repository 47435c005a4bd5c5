// `sylva view`: a window onto a scenario. It plays the scenario's camera path; F switches to
// flying by hand (W/A/S/D, Q/E, drag with the left mouse button to look), Space pauses, N steps
// one frame, R tints every plant by the rung it is drawn with (app/rung_colours.h), Escape quits.
// An overlay shows the frame's measurements, in rung colours the key, and with the auto ladder a
// slider for its budget (or frame-time target, or error threshold).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "app/commands.h"
#include "app/rung_colours.h"
#include "app/scenario_options.h"
#include "app/scenario_player.h"
#include "scenarios/scenario_loader.h"
#include "components/camera.h"
#include "models/generate/textures.h"
#include "scenarios/scenario_loader.h"
#include "resources/playback.h"
#include "systems/render/render_target.h"

namespace sylva {
namespace {

struct view_options {
    scenario_options scenario;
    std::uint32_t exit_after = 0;  // frames; 0 = run until closed
    std::string screenshot;
    bool hidden = false;
    bool overlay = true;
    bool rungs = false;  // start with the rung colours on
};

struct walk_state {
    bool paused = false;
    bool step = false;
    bool flying = false;
    double last_x = 0.0, last_y = 0.0;
    bool dragging = false;
    float yaw = 0.0f, pitch = 0.0f;
    bool rungs = false;
};

void key_callback(GLFWwindow* window, int key, int, int action, int) {
    auto* state = static_cast<walk_state*>(glfwGetWindowUserPointer(window));
    if (action != GLFW_PRESS) return;
    if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
    if (key == GLFW_KEY_SPACE) state->paused = !state->paused;
    if (key == GLFW_KEY_N) state->step = true;
    if (key == GLFW_KEY_F) state->flying = !state->flying;
    if (key == GLFW_KEY_R) state->rungs = !state->rungs;
}

// Moves the camera by hand: yaw/pitch from mouse drags, position from keys (metres/second).
void fly(GLFWwindow* window, walk_state& state, camera& cam, float dt) {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    const bool down = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS &&
                      !ImGui::GetIO().WantCaptureMouse;
    if (down && state.dragging) {
        state.yaw -= float(x - state.last_x) * 0.004f;
        state.pitch = std::clamp(state.pitch - float(y - state.last_y) * 0.004f, -1.5f, 1.5f);
    }
    state.dragging = down;
    state.last_x = x;
    state.last_y = y;
    cam.forward = {std::cos(state.pitch) * std::sin(state.yaw), std::sin(state.pitch),
                   -std::cos(state.pitch) * std::cos(state.yaw)};
    const glm::vec3 right = glm::normalize(glm::cross(cam.forward, glm::vec3(0, 1, 0)));
    const float speed = (glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ? 60.0f : 12.0f) * dt;
    glm::vec3 move{0.0f};
    if (glfwGetKey(window, GLFW_KEY_W) == GLFW_PRESS) move += cam.forward;
    if (glfwGetKey(window, GLFW_KEY_S) == GLFW_PRESS) move -= cam.forward;
    if (glfwGetKey(window, GLFW_KEY_D) == GLFW_PRESS) move += right;
    if (glfwGetKey(window, GLFW_KEY_A) == GLFW_PRESS) move -= right;
    if (glfwGetKey(window, GLFW_KEY_E) == GLFW_PRESS) move.y += 1.0f;
    if (glfwGetKey(window, GLFW_KEY_Q) == GLFW_PRESS) move.y -= 1.0f;
    cam.position += glm::dvec3(move * speed);
}

// The auto ladder's aim as a slider (issue 21 item 6): the frame-time target, the error
// threshold or the plants' budget, whichever the run chose its rungs by; the next frame solves
// for the new value. Nothing without measured rung tables.
void budget_slider(rung_budget& budget) {
    if (!budget.active()) return;
    if (budget.max_error > 0.0) {
        float e = float(budget.max_error);
        if (ImGui::SliderFloat("max error", &e, 0.001f, 0.5f, "%.3f", ImGuiSliderFlags_Logarithmic))
            budget.max_error = double(e);
    } else if (budget.target_frame_ms > 0.0) {
        float t = float(budget.target_frame_ms);
        if (ImGui::SliderFloat("target frame ms", &t, 5.0f, 2000.0f, "%.0f", ImGuiSliderFlags_Logarithmic))
            budget.target_frame_ms = double(t);
        ImGui::Text("plant budget %.1f ms (adapted)", budget.plant_budget_us / 1000.0);
    } else {
        float ms = float(budget.plant_budget_us / 1000.0);
        if (ImGui::SliderFloat("plant budget ms", &ms, 1.0f, 20000.0f, "%.0f", ImGuiSliderFlags_Logarithmic))
            budget.plant_budget_us = double(ms) * 1000.0;
    }
    ImGui::Text("predicted plants %.1f ms  lambda %.3g", budget.predicted_us / 1000.0, budget.lambda);
}

void draw_overlay(const frame_record& r, const walk_state& state, const run_info& info, rung_budget& budget) {
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.55f);
    ImGui::Begin("Sylva", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::Text("%s  frame %llu  t=%.2f s%s%s", info.scenario.c_str(),
                static_cast<unsigned long long>(r.frame), r.time_s, state.paused ? "  [paused]" : "",
                state.flying ? "  [flying]" : "");
    ImGui::Text("frame %.1f ms  cpu %.1f ms  gpu %.1f ms", r.frame_ms, r.cpu_ms, r.gpu_ms);
    for (const auto& [name, ms] : r.systems) ImGui::Text("  %-22s %6.2f ms", name.c_str(), ms);
    for (const auto& [name, ms] : r.passes) ImGui::Text("  gpu %-18s %6.2f ms", name.c_str(), ms);
    ImGui::Text("triangles %llu (+%llu shadow)  draws %u", static_cast<unsigned long long>(r.triangles),
                static_cast<unsigned long long>(r.shadow_triangles), r.draw_calls);
    ImGui::Text("instances per rung%s:", state.rungs ? " (the colours in the view)" : "");
    for (const rung_colour& c : k_rung_colours)
        ImGui::TextColored(state.rungs ? ImVec4(c.rgb[0] / 255.0f, c.rgb[1] / 255.0f, c.rgb[2] / 255.0f, 1.0f)
                                       : ImGui::GetStyleColorVec4(ImGuiCol_Text),
                           "  %-18s %u", c.name.data(), r.instances[std::size_t(c.rung)]);
    budget_slider(budget);
    ImGui::Text("%zu plants  %s", info.plants, info.gl_renderer.c_str());
    ImGui::TextDisabled("F fly  WASDQE move  drag look  R rung colours  Space pause  N step  Esc quit");
    ImGui::End();
}

int view(const view_options& o) {
    const std::optional<scenario> loaded = load_or_report(o.scenario);
    if (!loaded) return k_exit_bad_input;
    const scenario& s = *loaded;
    try {
        render::context_options context_options;
        context_options.width = int(s.width);
        context_options.height = int(s.height);
        context_options.headless = false;
        context_options.visible = !o.hidden;
        context_options.title = "Sylva — " + s.name;
        auto context = render::create_context(context_options);
        bake_cache cache;
        // The ID buffer tells each pixel's plant, for the rung colours.
        player_options player_settings;
        player_settings.id_buffer = true;
        scenario_player player(s, o.scenario.threads, context.get(), &cache, player_settings);
        walk_state state;
        state.rungs = o.rungs;
        GLFWwindow* window = context->window();
        glfwSetWindowUserPointer(window, &state);
        glfwSetKeyCallback(window, key_callback);
        ImGui::CreateContext();
        ImGui::GetIO().IniFilename = nullptr;
        ImGui_ImplGlfw_InitForOpenGL(window, true);
        ImGui_ImplOpenGL3_Init("#version 450");

        std::uint32_t shown = 0;
        double last_time = glfwGetTime();
        while (context->poll_events()) {
            const double now = glfwGetTime();
            auto& track = player.world().resource<camera_track>();
            track.follow = !state.flying;
            if (state.flying) fly(window, state, player.world().single<camera>(), float(now - last_time));
            last_time = now;
            const std::uint64_t frame = player.frame();
            frame_record record = player.step();
            if (state.paused && !state.step) player.set_frame(frame);
            state.step = false;
            if (state.rungs)
                render::draw_image_to_default(
                    tint_by_rung(player.capture(), player.capture_plant_ids(), player.world().table<lod_state>().values()),
                    context->width(), context->height());
            else
                player.present(context->width(), context->height());
            ++shown;
            if (!o.screenshot.empty() && o.exit_after && shown == o.exit_after)
                write_image(render::read_default_framebuffer(context->width(), context->height()),
                            o.screenshot);
            if (o.overlay) {
                ImGui_ImplOpenGL3_NewFrame();
                ImGui_ImplGlfw_NewFrame();
                ImGui::NewFrame();
                draw_overlay(record, state, player.info(), player.world().resource<rung_budget>());
                ImGui::Render();
                ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
            }
            context->swap_buffers();
            if (o.exit_after && shown >= o.exit_after) break;
        }
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
        ImGui::DestroyContext();
    } catch (const scenario_error& e) {  // a file the scenario names cannot be used
        spdlog::error("{}", e.what());
        return k_exit_bad_input;
    } catch (const std::exception& e) {
        spdlog::error("{}", e.what());
        return k_exit_failure;
    }
    return k_exit_ok;
}

}  // namespace

command_runner add_view_command(CLI::App& app) {
    auto options = std::make_shared<view_options>();
    add_scenario_options(app, options->scenario);
    app.add_option("--exit-after", options->exit_after,
                   "Close after this many frames (0: when the window is closed)");
    app.add_option("--screenshot", options->screenshot,
                   "With --exit-after: save the last frame (without the overlay) to this PNG");
    app.add_flag("--hidden", options->hidden, "Keep the window hidden (automated tests)");
    app.add_flag("!--no-overlay", options->overlay, "Hide the statistics overlay");
    app.add_flag("--rungs", options->rungs,
                 "Start with every plant tinted by the rung it is drawn with (R toggles): mesh_full red, "
                 "mesh_reduced orange, mesh_far yellow, billboard_cloud green, points_lines blue, "
                 "crossed_billboard violet");
    return [options] { return view(*options); };
}

}  // namespace sylva
