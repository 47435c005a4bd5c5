#include "app/rung_table_report.h"

#include <spdlog/fmt/fmt.h>

#include <iterator>

#include "lod/ladder.h"

namespace sylva {

std::string rung_table_report(const std::string& scenario_name,
                              std::span<const std::string> species, const rung_budget& budget) {
    if (!budget.active())
        return "'" + scenario_name + "' switches its rungs by projected size: no rung tables\n";
    std::string out;
    const auto to = std::back_inserter(out);
    for (std::size_t i = 0; i < budget.tables.size(); ++i) {
        const species_rung_tables& tables = budget.tables[i];
        const std::string name = i < species.size() ? species[i] : "species " + std::to_string(i);
        fmt::format_to(
            to,
            "\n{}: error per plant pixel (of 1), view and shadow cost (us), by projected size\n",
            name);
        fmt::format_to(to, "{:<18} {:<6}", "rung", "");
        for (const float size : k_rung_table_sizes_px) fmt::format_to(to, " {:9.0f}px", size);
        fmt::format_to(to, "\n{:<18} {:<6}", "plant pixels", "");
        for (const float pixels : tables.plant_pixels) fmt::format_to(to, " {:11.0f}", pixels);
        out += "\n";
        for (const rung_table& t : tables.rungs) {
            fmt::format_to(to, "{:<18} {:<6}", rung_name(t.rung), "error");
            for (std::size_t k = 0; k < k_rung_table_size_count; ++k)
                // A size where the plant covers no pixel has no error per pixel.
                if (tables.plant_pixels[k] > 0.0f)
                    fmt::format_to(to, " {:11.4f}", double(t.error[k] / tables.plant_pixels[k]));
                else
                    fmt::format_to(to, " {:>11}", "n/a");
            fmt::format_to(to, "\n{:<18} {:<6}", "", "view");
            for (const float us : t.cost_us) fmt::format_to(to, " {:11.1f}", double(us));
            fmt::format_to(to, "\n{:<18} {:<6}", "", "shadow");
            for (const float us : t.shadow_cost_us) fmt::format_to(to, " {:11.1f}", double(us));
            out += "\n";
        }
    }
    return out;
}

}  // namespace sylva
