#include "app/rung_table_report.h"

#include <cstdio>

#include "lod/ladder.h"

namespace sylva {
namespace {

template <typename... Args>
void append(std::string& out, const char* format, Args... args) {
    char line[64];
    std::snprintf(line, sizeof line, format, args...);
    out += line;
}

}  // namespace

std::string rung_table_report(const std::string& scenario_name,
                              std::span<const std::string> species, const rung_budget& budget) {
    if (!budget.active())
        return "'" + scenario_name + "' switches its rungs by projected size: no rung tables\n";
    std::string out;
    for (std::size_t i = 0; i < budget.tables.size(); ++i) {
        const species_rung_tables& tables = budget.tables[i];
        const std::string name = i < species.size() ? species[i] : "species " + std::to_string(i);
        out += "\n" + name +
               ": error per plant pixel (of 1), view and shadow cost (us), by projected size\n";
        append(out, "%-18s %-6s", "rung", "");
        for (const float size : k_rung_table_sizes_px) append(out, " %9.0fpx", double(size));
        append(out, "\n%-18s %-6s", "plant pixels", "");
        for (const float pixels : tables.plant_pixels) append(out, " %11.0f", double(pixels));
        out += "\n";
        for (const rung_table& t : tables.rungs) {
            append(out, "%-18s %-6s", std::string(rung_name(t.rung)).c_str(), "error");
            for (std::size_t k = 0; k < k_rung_table_size_count; ++k)
                // A size where the plant covers no pixel has no error per pixel.
                if (tables.plant_pixels[k] > 0.0f)
                    append(out, " %11.4f", double(t.error[k] / tables.plant_pixels[k]));
                else
                    append(out, " %11s", "n/a");
            append(out, "\n%-18s %-6s", "", "view");
            for (const float us : t.cost_us) append(out, " %11.1f", double(us));
            append(out, "\n%-18s %-6s", "", "shadow");
            for (const float us : t.shadow_cost_us) append(out, " %11.1f", double(us));
            out += "\n";
        }
    }
    return out;
}

}  // namespace sylva
