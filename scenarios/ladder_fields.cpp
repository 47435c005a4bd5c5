#include "scenarios/ladder_fields.h"

namespace sylva {
namespace {

const field_table<ladder_step_settings>& step_fields() {
    using t = ladder_step_settings;
    static const auto table = field_table<t>()
                                  .choice("rung", &t::rung, k_rung_names)
                                  .required()
                                  .number("below_px", &t::below_px, {0.01, 1e6})
                                  .number("band", &t::band, {0.0, 0.9})
                                  .choice("shadow", &t::shadow, k_rung_names);
    static_assert(k_max_band == 0.9f, "the range above is lod/ladder.h's k_max_band");
    return table;
}

}  // namespace

ladder ladder_of(const std::vector<ladder_step_settings>& steps) {
    ladder l;
    l.count = std::uint8_t(std::min(steps.size(), k_max_rungs));
    for (std::size_t i = 0; i < l.count; ++i) {
        l.rungs[i] = rung_of_name(steps[i].rung).value_or(representation::none);
        l.below_px[i] = steps[i].below_px;
        l.band[i] = i == 0 ? 0.0f : steps[i].band;
        l.shadow[i] = steps[i].shadow.empty() ? representation::none
                                              : rung_of_name(steps[i].shadow).value_or(representation::none);
    }
    return l;
}

void read_ladder(const json_node& node, std::vector<ladder_step_settings>& out) {
    const std::size_t size = expect_array(node, 1, k_max_rungs);
    out.assign(size, {});
    for (std::size_t i = 0; i < size; ++i) {
        const json_node item = node.at(i);
        step_fields().read(item, out[i]);
        if (i == 0 && item.find("below_px"))
            item.find("below_px")->fail("the first rung is drawn at every size above the second's: it takes no below_px");
        if (i == 0 && item.find("band")) item.find("band")->fail("the first rung has no band: the second rung's band is the step between them");
        if (i > 0 && !item.find("below_px")) item.fail_missing("below_px");
        // A band left out is 0 where no fade is needed (lod/ladder.h seamless_step).
        if (i > 0 && !item.find("band") && rung_of_name(out[i - 1].rung) && rung_of_name(out[i].rung) &&
            seamless_step(*rung_of_name(out[i - 1].rung), *rung_of_name(out[i].rung)))
            out[i].band = 0.0f;
    }
    if (const auto problem = find_ladder_problem(ladder_of(out))) {
        // A band left at its default is not in the file: the rung's object stands for it.
        const json_node item = node.at(problem->rung);
        const auto field = item.find(problem->field);
        (field ? *field : item).fail(problem->what);
    }
}

void write_ladder(const std::vector<ladder_step_settings>& steps, nlohmann::json& parent) {
    if (steps.empty()) return;
    nlohmann::json items = nlohmann::json::array();
    for (std::size_t i = 0; i < steps.size(); ++i) {
        nlohmann::json step = {{"rung", steps[i].rung}};
        if (i > 0) {
            step["below_px"] = steps[i].below_px;
            step["band"] = steps[i].band;
        }
        if (!steps[i].shadow.empty()) step["shadow"] = steps[i].shadow;
        items.push_back(std::move(step));
    }
    parent["ladder"] = std::move(items);
}

}  // namespace sylva
