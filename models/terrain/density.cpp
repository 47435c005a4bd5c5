#include "models/terrain/density.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "io/input_file.h"
#include "models/noise.h"

namespace sylva {
namespace {

// Half-width of the soft threshold band, in noise units (fbm_value spans about 0.2 .. 0.8).
constexpr float k_soft_band = 0.04f;

float smoothstep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

float density_map::at(double u, double v) const {
    if (width == 0 || height == 0) return 1.0f;
    // Texel centres sit at (i + 0.5) / width.
    const double gx = std::clamp(u * width - 0.5, 0.0, double(width - 1));
    const double gy = std::clamp(v * height - 0.5, 0.0, double(height - 1));
    const auto c0 = static_cast<std::uint32_t>(gx);
    const auto r0 = static_cast<std::uint32_t>(gy);
    const std::uint32_t c1 = std::min(c0 + 1, width - 1);
    const std::uint32_t r1 = std::min(r0 + 1, height - 1);
    const double fx = gx - c0;
    const double fy = gy - r0;
    const auto texel = [&](std::uint32_t c, std::uint32_t r) {
        return double(values[std::size_t(r) * width + c]);
    };
    const double top = texel(c0, r0) + (texel(c1, r0) - texel(c0, r0)) * fx;
    const double bottom = texel(c0, r1) + (texel(c1, r1) - texel(c0, r1)) * fx;
    return static_cast<float>(top + (bottom - top) * fy);
}

density_map load_density_map(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw std::runtime_error("load_density_map: " + name + ": no such file");
    check_input_file(path, k_max_image_bytes);  // a directory or device is refused here
    auto in = OIIO::ImageInput::open(name);
    if (!in)
        throw std::runtime_error("load_density_map: cannot read " + name + ": " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    check_image_dimensions("load_density_map: " + name, spec.width, spec.height);
    if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
        throw std::runtime_error("load_density_map: " + name + ": empty image");
    density_map map;
    map.width = static_cast<std::uint32_t>(spec.width);
    map.height = static_cast<std::uint32_t>(spec.height);
    map.values.resize(std::size_t(map.width) * map.height);
    if (!in->read_image(0, 0, 0, 1, OIIO::TypeDesc::FLOAT, map.values.data()))
        throw std::runtime_error("load_density_map: cannot read " + name + ": " + in->geterror());
    in->close();
    for (float& d : map.values) d = std::clamp(d, 0.0f, 1.0f);
    return map;
}

density_map procedural_density(std::uint64_t seed, float frequency, float coverage,
                               std::uint32_t resolution) {
    if (resolution == 0)
        resolution =
            static_cast<std::uint32_t>(std::clamp(std::ceil(64.0 * frequency), 64.0, 1024.0));
    density_map map;
    map.width = resolution;
    map.height = resolution;
    map.values.resize(std::size_t(resolution) * resolution);
    if (coverage <= 0.0f || coverage >= 1.0f) {
        std::fill(map.values.begin(), map.values.end(), coverage <= 0.0f ? 0.0f : 1.0f);
        return map;
    }
    const fbm_settings settings{4, 2.0, 0.5f, 0};
    for (std::uint32_t row = 0; row < resolution; ++row)
        for (std::uint32_t column = 0; column < resolution; ++column)
            map.values[std::size_t(row) * resolution + column] =
                fbm_value((column + 0.5) / resolution * frequency,
                          (row + 0.5) / resolution * frequency, seed, settings);
    // The (1 - coverage) quantile, so the covered fraction is what was asked for at any seed.
    std::vector<float> sorted = map.values;
    const auto k = static_cast<std::size_t>(double(1.0f - coverage) * double(sorted.size() - 1));
    std::nth_element(sorted.begin(), sorted.begin() + std::ptrdiff_t(k), sorted.end());
    const float threshold = sorted[k];
    for (float& d : map.values) d = smoothstep(threshold - k_soft_band, threshold + k_soft_band, d);
    return map;
}

}  // namespace sylva
