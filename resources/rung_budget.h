#pragma once
// The auto ladder (DESIGN §1.5, issue 21 item 3) as a world resource: each species' measured
// rung tables (app/rung_tables.h turned into error and cost by the device's costs), the budget
// the plants' predicted cost must hold, and what select_representation found this frame.
// Empty tables: the ladders switch by projected size alone (lod/ladder.h).
#include <cstdint>
#include <vector>

#include "lod/rung_solver.h"

namespace sylva {

struct rung_budget {
    std::vector<species_rung_tables> tables;  // by species, each in its ladder's order
    double plant_budget_us = 0.0;             // predicted cost of every plant drawn, per frame
    // Above 0, instead of a budget: each plant takes the cheapest rung whose mean colour error
    // per plant pixel (of 1, as the tables measure it) is at most this (lod/rung_solver.h
    // cheapest_within).
    double max_error = 0.0;
    // Above 0: the least error a microsecond of a plant's cost must put right (error as the
    // tables sum it over the plant's pixels), so λ never falls below it (lod/rung_solver.h): each
    // plant buys a dearer rung only where it is worth this much, in every frame alike; with a
    // budget too, the budget's λ where it is higher. Alone (no budget, no target) it spends what
    // each frame is worth: little where the plants are far, more where they are near.
    double gain_per_us = 0.0;
    // Above 0: plant_budget_us is adapted every frame so that the GPU frame takes this long
    // (systems/adapt_plant_budget_system.h; not deterministic).
    double target_frame_ms = 0.0;
    // The controller's last point (budget, GPU ms), for its secant.
    double controller_budget_us = 0.0;
    double controller_ms = 0.0;
    float hysteresis = 0.05f;                 // lod/rung_solver.h choose_at
    // A plant that changes rung keeps drawing the old one as its partner, dissolving over this
    // many frames (the new rung is whole at once, so the plant never thins).
    std::uint32_t fade_frames = 8;
    // The frame before was not shown: the first frame, a rehearsal of it (scenario_player::step)
    // or a jump (scenario_player::forget_shown_frame). Then no plant holds or dissolves from the
    // rung it had: each takes its choice whole, as nothing on screen can pop. select_representation
    // clears it once it has chosen.
    bool cut = true;

    // Written by select_representation each frame.
    double lambda = 0.0;
    double predicted_us = 0.0;  // the rungs chosen (view and shadow)
    // What a budget could change this frame: the predicted cost with every plant on its
    // least-error rung, and with every plant on its cheapest (the controller stays between).
    double most_useful_us = 0.0;
    double least_possible_us = 0.0;
    std::vector<lambda_histogram> histograms;  // per chunk, scratch kept warm
    std::vector<double> costs;                 // per chunk, scratch kept warm
    // Per chunk, the candidates of its plants the budget's first pass judged, in walk order, for
    // its second pass to choose from without judging them again; scratch kept warm.
    std::vector<std::vector<rung_candidates>> offers;

    bool active() const { return !tables.empty(); }
};

}  // namespace sylva
