#include "app/device_costs.h"

#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdlib>

#include "app/metrics.h"
#include "io/once_per_process.h"

namespace sylva {
namespace {

// Entry layout (little-endian): u8 status (0 model, 1 refused), then the model's lines or the
// reason.
constexpr std::uint8_t k_model = 0;
constexpr std::uint8_t k_refused = 1;
const float calibration_settings_splat_factor = render::calibration_settings{}.splat_factor;

std::vector<std::byte> encode(const device_calibration& c) {
    binary_writer out;
    if (c.model) {
        out.pod(k_model);
        out.pod(c.model->paths);
    } else {
        out.pod(k_refused);
        out.text(c.refusal);
    }
    return out.bytes();
}

// A damaged entry must not skew every later play: exactly a status and what it carries, and a
// model's lines finite and non-negative (fit_cost_model never stores anything else).
device_calibration decode(const std::vector<std::byte>& bytes) {
    binary_reader in(bytes);
    device_calibration c;
    const auto status = in.pod<std::uint8_t>();
    if (status == k_model) {
        c.model.emplace();
        c.model->paths = in.pod<decltype(primitive_cost_model::paths)>();
        for (const cost_line& line : c.model->paths)
            if (!(std::isfinite(line.a_us) && std::isfinite(line.b_us_per_px) && line.a_us >= 0.0 &&
                  line.b_us_per_px >= 0.0))
                throw std::runtime_error("primitive cost model holds a cost line of " + std::to_string(line.a_us) +
                                         " + " + std::to_string(line.b_us_per_px) + " x pixels");
    } else if (status == k_refused) {
        c.refusal = in.text();
    } else {
        throw std::runtime_error("primitive cost model: unknown status " + std::to_string(status));
    }
    if (!in.at_end()) throw std::runtime_error("primitive cost model entry has trailing bytes");
    return c;
}

// A refusal is said once per process and device, not once per player.
void warn_once(const std::string& device, const std::string& why) {
    if (!first_time_in_process("primitive cost refusal", device)) return;
    spdlog::warn(
        "the device calibration of primitive costs was refused ({}); points and lines select "
        "with the paper's costs (a triangle as three points). `sylva calibrate --force` "
        "measures again",
        why);
}

std::vector<std::byte> encode_work(const device_work_calibration& c) {
    binary_writer out;
    if (c.costs) {
        out.pod(k_model);
        out.pod(c.costs->vertex_us);
        out.pod(c.costs->fragment_us);
        out.pod(c.costs->shadow_fragment_us);
    } else {
        out.pod(k_refused);
        out.text(c.refusal);
    }
    return out.bytes();
}

device_work_calibration decode_work(const std::vector<std::byte>& bytes) {
    binary_reader in(bytes);
    device_work_calibration c;
    const auto status = in.pod<std::uint8_t>();
    if (status == k_model) {
        shader_work_costs w;
        w.vertex_us = in.pod<double>();
        w.fragment_us = in.pod<double>();
        w.shadow_fragment_us = in.pod<double>();
        for (const double v : {w.vertex_us, w.fragment_us, w.shadow_fragment_us})
            if (!(std::isfinite(v) && v > 0.0))
                throw std::runtime_error("shader work costs hold a cost of " + std::to_string(v));
        c.costs = w;
    } else if (status == k_refused) {
        c.refusal = in.text();
    } else {
        throw std::runtime_error("shader work costs: unknown status " + std::to_string(status));
    }
    if (!in.at_end()) throw std::runtime_error("shader work costs entry has trailing bytes");
    return c;
}

}  // namespace

std::string describe_cost_device(const render::gl_context& context, const render::renderer& r,
                                 float splat_factor) {
    const char* rasteriser_threads = std::getenv("LP_NUM_THREADS");
    return describe_machine() + "; LP_NUM_THREADS " +
           (rasteriser_threads ? rasteriser_threads : "unset") + "; " + context.renderer() + "; " +
           context.version() + "; " + std::to_string(r.settings().width) + "x" +
           std::to_string(r.settings().height) + "; c_p " + std::to_string(splat_factor);
}

primitive_costs device_calibration::costs_for(const point_line_quality& q) const {
    return model ? model->costs_for(q) : primitive_costs{};
}

device_calibration device_cost_model(render::renderer& r, const render::gl_context& context,
                                     bake_cache& cache, float splat_factor, bool force,
                                     const render::calibration_settings& settings) {
    const std::string device = describe_cost_device(context, r, splat_factor);
    // /2: since 2172a1d the view's programs never carry the screen-door dissolve; a model
    // calibrated before by a player with it (ladders, billboard clouds) costed every triangle
    // and fragment with a hash and a discard, and is measured again.
    const std::uint64_t key = hash_string(device, hash_string("primitive_cost_model/2"));
    if (!force)
        if (const auto bytes = cache.load("primitive_cost_model", key)) {
            try {
                device_calibration c = decode(*bytes);
                if (!c.model) warn_once(device, c.refusal);
                return c;
            } catch (const std::runtime_error& e) {
                cache.discard("primitive_cost_model", key, e.what());  // reported once; calibrated again
            }
        }
    device_calibration c;
    c.measured_now = true;
    render::calibration_settings s = settings;
    s.splat_factor = splat_factor;
    if (!s.timer) s.timer = render::device_frame_timer(context.renderer());
    c.measurement = render::calibrate_primitive_costs(r, s);
    c.model = c.measurement->model;
    c.refusal = c.measurement->refusal;
    if (!c.model) warn_once(device, c.refusal);
    cache.store_or_warn("primitive_cost_model", key, encode(c));
    return c;
}

device_work_calibration device_work_costs(render::renderer& r, const render::gl_context& context, bake_cache& cache,
                                          bool force, const render::calibration_settings& settings) {
    // The splat factor does not change what shader work costs: the key takes the default one.
    const std::string device = describe_cost_device(context, r, calibration_settings_splat_factor);
    // /3: measured again since the view's programs lost the dissolve (primitive_cost_model/2).
    const std::uint64_t key = hash_string(device, hash_string("shader_work_costs/3"));
    if (!force)
        if (const auto bytes = cache.load("shader_work_costs", key)) {
            try {
                return decode_work(*bytes);
            } catch (const std::runtime_error& e) {
                cache.discard("shader_work_costs", key, e.what());
            }
        }
    device_work_calibration c;
    if (!r.settings().shadows) {
        // Not the device's answer, this renderer's: nothing is measured and nothing cached, so
        // a scenario with shadows on this device still calibrates.
        c.refusal = "the renderer draws no shadow map to time the shadow shape in";
        return c;
    }
    c.measured_now = true;
    render::calibration_settings s = settings;
    if (!s.timer) s.timer = render::device_frame_timer(context.renderer());
    c.measurement = render::calibrate_shader_work(r, s);
    c.costs = c.measurement->costs;
    c.refusal = c.measurement->refusal;
    if (!c.costs)
        spdlog::warn("the device calibration of shader work was refused ({}); the auto ladder costs its rungs by "
                     "their triangles. `sylva calibrate --force` measures again",
                     c.refusal);
    cache.store_or_warn("shader_work_costs", key, encode_work(c));
    return c;
}

}  // namespace sylva
