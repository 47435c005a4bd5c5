#pragma once
// What a Wang tile set of plants is made with (models/terrain/wang_tiles.h), and whether it can
// be: header-only so the scenario loader can check a scenario without linking the models.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace sylva {

inline constexpr std::uint32_t k_max_wang_colours = 4;  // 4⁴ = 256 tiles

struct wang_tile_rules {
    double tile_size_m = 32.0;  // T
    std::uint32_t colours = 2;  // C corner colours: C⁴ tiles
    float min_spacing_m = 3.0f;  // r
    // How far a plant reaches from its position (crown radius times its largest scale): the
    // edge strips are at least this wide, so only plants the tile's colours fix reach into it
    // (what its shell bakes, models/bake/shell_bake.h). 0: the spacing.
    float reach_m = 0.0f;
    double plants_per_m2 = 0.02;  // darts are thrown for this density, at most as many as fit
    float scale_min = 1.0f;
    float scale_max = 1.0f;
};

// The regions' sizes for a spacing r and a reach: strips of half-width w = max(r, reach) and
// corner squares of half-side m = w + r/√2 (rounded up by a part in a million against rounding).
struct wang_margins {
    double strip = 0.0;   // w
    double corner = 0.0;  // m
};
inline wang_margins wang_margins_for(double min_spacing_m, double reach_m = 0.0) {
    const double r = std::max(min_spacing_m, 0.0);
    const double w = std::max(r, reach_m) * (1.0 + 1e-6);
    return {w, w + r / std::sqrt(2.0) * (1.0 + 1e-6)};
}

// Why rules cannot make a tile set, or empty: 2 to k_max_wang_colours colours; the tile at least
// 2m + 2w = 5.41 r wide so there is an interior; a positive finite density and tile size.
inline std::string wang_rules_problem(const wang_tile_rules& rules) {
    if (rules.colours < 2 || rules.colours > k_max_wang_colours)
        return "corner colours must be 2 to " + std::to_string(k_max_wang_colours) + ", not " +
               std::to_string(rules.colours);
    if (!(rules.tile_size_m > 0.0) || !std::isfinite(rules.tile_size_m)) return "the tile size must be positive";
    if (!(rules.plants_per_m2 >= 0.0) || !std::isfinite(rules.plants_per_m2))
        return "the density must be finite and >= 0";
    if (!(rules.min_spacing_m >= 0.0f)) return "the spacing must be >= 0";
    if (!(rules.reach_m >= 0.0f)) return "the reach must be >= 0";
    const wang_margins g = wang_margins_for(rules.min_spacing_m, rules.reach_m);
    const double least = 2.0 * (g.corner + g.strip);
    if (rules.tile_size_m < least) {
        char text[320];
        if (rules.reach_m > rules.min_spacing_m)
            std::snprintf(text, sizeof text,
                          "a tile of %g m is too small for plants that reach %g m at a spacing of %g m: it needs "
                          "at least %.2f m (edge strips as wide as the reach, corner squares, and an interior)",
                          rules.tile_size_m, double(rules.reach_m), double(rules.min_spacing_m), least);
        else
            std::snprintf(text, sizeof text,
                          "a tile of %g m is too small for a spacing of %g m: it needs at least %.2f m (5.41 x the "
                          "spacing: corner squares and edge strips on both sides, and an interior)",
                          rules.tile_size_m, double(rules.min_spacing_m), least);
        return text;
    }
    return {};
}

}  // namespace sylva
