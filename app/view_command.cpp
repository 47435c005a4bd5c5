// `sylva view`: a window onto a scenario. It plays the scenario's camera path; F switches to
// flying by hand (W/A/S/D, Q/E, drag with the left mouse button to look), Space pauses, N steps
// one frame, R tints every plant by the rung it is drawn with (app/rung_colours.h), Escape quits.
// An overlay shows the frame's measurements, in rung colours the key, and with the auto ladder a
// slider for its budget (or frame-time target, or error threshold). With implicit-lit species a
// second panel tunes Luft 2007's parameters (app/implicit_tuning.h): pick the species from the
// list or by right-clicking a plant, move the sliders, re-bake in the background (a progress bar
// shows it; the view keeps playing the old bake until the new one is swapped in), and write the
// values back to the scenario file.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>

#include "app/commands.h"
#include "app/implicit_tuning.h"
#include "app/rung_colours.h"
#include "app/scenario_options.h"
#include "app/scenario_player.h"
#include "scenarios/scenario_loader.h"
#include "components/camera.h"
#include "components/plant_instance.h"
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

// The implicit-lighting panel's state: the species tuned, its values as the sliders hold them,
// the background re-bake and the last message.
struct tuning_state {
    int species = -1;  // index into the scenario's species; -1: none implicit-lit
    implicit_lighting_settings values;
    std::unique_ptr<implicit_rebake> rebake;
    std::string message;
};

bool implicit_lit(const scene_assets& assets, std::size_t species) {
    return species < assets.densities.size() && !assets.densities[species].generators.empty();
}

// The values the bake used for `species` (derived ones filled in), in the model's own units as
// the scenario's fields are.
implicit_lighting_settings used_values(const scenario& s, const scene_assets& assets, std::size_t species) {
    implicit_lighting_settings v = s.species[species].implicit;
    const species_density& d = assets.densities[species];
    v.rho_m = d.used.rho_m / d.scale;
    v.tau = d.used.tau;
    v.d_min = d.used.d_min;
    v.ka_min = d.used.ka_min;
    v.exponent = d.used.exponent;
    v.blend = d.used.blend;
    return v;
}

void choose_species(tuning_state& t, const scenario& s, const scene_assets& assets, int species) {
    if (species < 0 || !implicit_lit(assets, std::size_t(species))) return;
    t.species = species;
    t.values = used_values(s, assets, std::size_t(species));
}

// Returns true when the user asked for a re-bake.
bool tuning_panel(tuning_state& t, const scenario& s, const scene_assets& assets) {
    if (t.species < 0) return false;
    ImGui::SetNextWindowPos(ImVec2(float(s.width) - 330.0f, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.7f);
    ImGui::Begin("Implicit lighting (Luft 2007)", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
    if (ImGui::BeginCombo("species", s.species[std::size_t(t.species)].name.c_str())) {
        for (std::size_t i = 0; i < s.species.size(); ++i)
            if (implicit_lit(assets, i) && ImGui::Selectable(s.species[i].name.c_str(), int(i) == t.species))
                choose_species(t, s, assets, int(i));
        ImGui::EndCombo();
    }
    ImGui::TextDisabled("right-click a plant to pick its species");
    implicit_lighting_settings& v = t.values;
    ImGui::SliderFloat("rho (m)", &v.rho_m, 0.01f, 20.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("tau", &v.tau, 0.01f, 500.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("ka,min", &v.ka_min, 0.0f, 1.0f, "%.2f");
    int source = v.ambient_from == "density" ? 1 : 0;
    if (ImGui::Combo("ambient from", &source, "depth below the surface\0density F (paper)\0"))
        v.ambient_from = std::string(k_ambient_sources[std::size_t(source)]);
    if (source == 1) {
        ImGui::SliderFloat("d_min", &v.d_min, 0.01f, 1000.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    } else {
        // 0 asks the bake for its default (twice the foliage's median depth), which only the bake
        // knows: it needs the iso-surface.
        ImGui::SliderFloat("depth d_min (m)", &v.depth_min_m, 0.0f, 20.0f,
                           v.depth_min_m > 0.0f ? "%.3f" : "derived", ImGuiSliderFlags_Logarithmic);
    }
    ImGui::SliderFloat("n", &v.exponent, 0.05f, 20.0f, "%.2f", ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("blend", &v.blend, 0.0f, 1.0f, "%.2f");
    bool rebake = false;
    if (t.rebake) {
        ImGui::ProgressBar(t.rebake->progress(), ImVec2(300.0f, 0.0f), t.rebake->step().c_str());
    } else {
        rebake = ImGui::Button("Re-bake");
        ImGui::SameLine();
        if (ImGui::Button("Write to scenario")) {
            try {
                std::filesystem::path file = s.source;
                if (s.source.rfind("embedded:", 0) == 0 || !std::filesystem::exists(file)) {
                    // A bundled scenario has no file of its own: write a copy beside the user.
                    file = s.name + ".json";
                    std::ofstream(file) << scenario_to_json_text(s) << '\n';
                }
                write_implicit_settings(file, std::size_t(t.species), v);
                t.message = "written to " + file.string();
            } catch (const std::exception& e) {
                t.message = e.what();
            }
        }
    }
    if (!t.message.empty()) ImGui::TextWrapped("%s", t.message.c_str());
    ImGui::End();
    return rebake;
}

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
// threshold or the plants' budget, whichever the run chose its rungs by, and the gain a ms must
// buy when the run gave one; the next frame solves for the new value. Nothing without measured
// rung tables.
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
    } else if (budget.plant_budget_us > 0.0) {
        float ms = float(budget.plant_budget_us / 1000.0);
        if (ImGui::SliderFloat("plant budget ms", &ms, 1.0f, 20000.0f, "%.0f", ImGuiSliderFlags_Logarithmic))
            budget.plant_budget_us = double(ms) * 1000.0;
    }
    if (budget.gain_per_us > 0.0) {
        float g = float(budget.gain_per_us * 1000.0);
        if (ImGui::SliderFloat("gain per ms", &g, 1.0f, 1000.0f, "%.0f",
                               ImGuiSliderFlags_Logarithmic))
            budget.gain_per_us = double(g) / 1000.0;
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
        auto player = std::make_unique<scenario_player>(s, o.scenario.threads, context.get(), &cache, player_settings);
        tuning_state tuning;
        for (std::size_t i = 0; i < s.species.size() && tuning.species < 0; ++i)
            choose_species(tuning, player->settings(), player->assets(), int(i));
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
            auto& track = player->world().resource<camera_track>();
            track.follow = !state.flying;
            if (state.flying) fly(window, state, player->world().single<camera>(), float(now - last_time));
            last_time = now;
            // The background re-bake done: a player on the tuned assets takes over at this frame.
            if (tuning.rebake && tuning.rebake->ready()) {
                try {
                    player_options options = player_settings;
                    options.assets = tuning.rebake->take();
                    const std::uint64_t at = player->frame();
                    const camera kept = player->world().single<camera>();
                    auto next = std::make_unique<scenario_player>(tuning.rebake->tuned(), o.scenario.threads,
                                                                  context.get(), &cache, options);
                    next->set_frame(at);
                    if (state.flying) next->world().single<camera>() = kept;
                    player = std::move(next);
                    tuning.message = "re-baked and swapped in";
                } catch (const std::exception& e) {
                    tuning.message = std::string("re-bake failed: ") + e.what();
                }
                tuning.rebake.reset();
            }
            // Right-click picks the species under the cursor for the tuning panel.
            if (glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse) {
                double cx = 0.0, cy = 0.0;
                glfwGetCursorPos(window, &cx, &cy);
                const std::vector<std::uint32_t> ids = player->capture_plant_ids();
                const auto x = std::size_t(cx * double(s.width) / double(std::max(context->width(), 1)));
                const auto y = std::size_t(cy * double(s.height) / double(std::max(context->height(), 1)));
                if (x < s.width && y < s.height && !ids.empty() && ids[y * s.width + x] != 0) {
                    const auto plant = ids[y * s.width + x] - 1;
                    choose_species(tuning, player->settings(), player->assets(),
                                   int(player->world().table<plant_instance>().data()[plant].species));
                }
            }
            const std::uint64_t frame = player->frame();
            frame_record record = player->step();
            if (state.paused && !state.step) player->set_frame(frame);
            state.step = false;
            if (state.rungs)
                render::draw_image_to_default(
                    tint_by_rung(player->capture(), player->capture_plant_ids(), player->world().table<lod_state>().values()),
                    context->width(), context->height());
            else
                player->present(context->width(), context->height());
            ++shown;
            if (!o.screenshot.empty() && o.exit_after && shown == o.exit_after)
                write_image(render::read_default_framebuffer(context->width(), context->height()),
                            o.screenshot);
            if (o.overlay) {
                ImGui_ImplOpenGL3_NewFrame();
                ImGui_ImplGlfw_NewFrame();
                ImGui::NewFrame();
                draw_overlay(record, state, player->info(), player->world().resource<rung_budget>());
                if (tuning_panel(tuning, player->settings(), player->assets()))
                    tuning.rebake = std::make_unique<implicit_rebake>(player->settings(), std::size_t(tuning.species), tuning.values,
                                                                      player_settings);
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
                 "crossed_billboard violet, facing_billboard orchid, lodf rose, eco_tile_points cyan");
    return [options] { return view(*options); };
}

}  // namespace sylva
