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
    float hysteresis = 0.05f;                 // lod/rung_solver.h choose_at
    // A plant that changes rung keeps drawing the old one as its partner, dissolving over this
    // many frames (the new rung is whole at once, so the plant never thins).
    std::uint32_t fade_frames = 8;

    // Written by select_representation each frame.
    double lambda = 0.0;
    double predicted_us = 0.0;
    std::vector<lambda_histogram> histograms;  // per chunk, scratch kept warm
    std::vector<double> costs;                 // per chunk, scratch kept warm

    bool active() const { return !tables.empty(); }
};

}  // namespace sylva
