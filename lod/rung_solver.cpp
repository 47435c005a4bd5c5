#include "lod/rung_solver.h"

#include <algorithm>
#include <cmath>

namespace sylva {
namespace {

const double k_log_lambda_min = std::log(k_lambda_min);
const double k_log_lambda_step = (std::log(k_lambda_max) - std::log(k_lambda_min)) / double(k_lambda_buckets);

// The bucket whose range (edge(b - 1), edge(b)] holds λ; k_lambda_buckets beyond the last edge.
std::size_t bucket_of(double lambda) {
    if (!(lambda > k_lambda_min)) return 0;
    const double b = std::ceil((std::log(lambda) - k_log_lambda_min) / k_log_lambda_step) - 1.0;
    return std::size_t(std::clamp(b, 0.0, double(k_lambda_buckets)));
}

// Where a size falls among the table sizes: between entry i - 1 and i at t (log-linear), or held
// at an end (t = 0 at i = 0, or at the last entry).
struct table_position {
    std::size_t i = 0;
    float t = 0.0f;
};

table_position position_of(float size_px) {
    const auto& sizes = k_rung_table_sizes_px;
    if (!(size_px > sizes.front())) return {0, 0.0f};
    if (size_px >= sizes.back()) return {k_rung_table_size_count - 1, 0.0f};
    std::size_t i = 1;
    while (sizes[i] < size_px) ++i;
    return {i, std::log(size_px / sizes[i - 1]) / std::log(sizes[i] / sizes[i - 1])};
}

float at(const std::array<float, k_rung_table_size_count>& table, table_position p) {
    if (p.t == 0.0f) return table[p.i];
    return table[p.i - 1] + p.t * (table[p.i] - table[p.i - 1]);
}

}  // namespace

float interpolate_table(const std::array<float, k_rung_table_size_count>& table, float size_px) {
    return at(table, position_of(size_px));
}

rung_candidates candidates_at(const species_rung_tables& tables, float size_px, bool seen, bool casts,
                              shown_last_frame shown, float caster_texel_m) {
    rung_candidates c;
    c.count = std::uint8_t(std::min(tables.rungs.size(), k_max_rungs));
    const table_position p = position_of(size_px);  // once for every rung
    float seen_share = 1.0f;
    if (shown.pixels >= 0.0f && shown.rung < c.count) {
        const float alone = at(tables.rungs[shown.rung].drawn_pixels, p);
        if (alone >= 1.0f) seen_share = std::min(1.0f, shown.pixels / alone);
    }
    for (std::size_t r = 0; r < c.count; ++r) {
        const rung_table& t = tables.rungs[r];
        c.error[r] = seen ? seen_share * at(t.error, p) : 0.0f;
        float shadow = 0.0f;
        if (casts) {
            shadow = at(t.shadow_cost_us, p);
            const float table_texel = at(t.shadow_texel_m, p);
            if (caster_texel_m > 0.0f && table_texel > 0.0f) {
                const float area = (table_texel / caster_texel_m) * (table_texel / caster_texel_m);
                shadow += (area - 1.0f) * at(t.shadow_fragment_cost_us, p);
            }
        }
        c.cost_us[r] = (seen ? at(t.cost_us, p) : 0.0f) + shadow;
    }
    c.plant_pixels = at(tables.plant_pixels, p);
    // A dearer rung whose error is not lower than a cheaper one's by at least
    // k_error_resolution_per_pixel over the plant's pixels is no better: it takes the cheaper
    // one's error, so no λ ever prefers it (choose_at breaks ties toward the cheaper).
    const float resolution = seen ? seen_share * c.plant_pixels * k_error_resolution_per_pixel : 0.0f;
    std::array<float, k_max_rungs> raised = c.error;
    for (std::size_t r = 0; r < c.count; ++r)
        for (std::size_t s = 0; s < c.count; ++s)
            if (c.cost_us[s] < c.cost_us[r] && c.error[s] <= c.error[r] + resolution)
                raised[r] = std::max(raised[r], c.error[s]);
    c.error = raised;
    return c;
}

std::uint8_t cheapest_within(const rung_candidates& c, double max_error, std::uint8_t previous, float hysteresis) {
    std::uint8_t best = k_max_rungs;
    for (std::uint8_t r = 0; r < c.count; ++r) {
        if (!(double(c.error[r]) <= max_error)) continue;
        if (best == k_max_rungs || c.cost_us[r] < c.cost_us[best] ||
            (c.cost_us[r] == c.cost_us[best] && c.error[r] < c.error[best]))
            best = r;
    }
    if (best == k_max_rungs) return choose_at(c, 0.0, previous, hysteresis);  // none is good enough
    if (previous < c.count && previous != best &&
        double(c.error[previous]) <= (1.0 + double(hysteresis)) * max_error &&
        double(c.cost_us[previous]) <= (1.0 + double(hysteresis)) * double(c.cost_us[best]))
        return previous;
    return best;
}

std::uint8_t choose_at(const rung_candidates& c, double lambda, std::uint8_t previous, float hysteresis) {
    std::uint8_t best = 0;
    double best_value = INFINITY;
    for (std::uint8_t r = 0; r < c.count; ++r) {
        const double value = double(c.error[r]) + lambda * double(c.cost_us[r]);
        if (value < best_value || (value == best_value && c.cost_us[r] < c.cost_us[best])) {
            best = r;
            best_value = value;
        }
    }
    if (previous < c.count && previous != best) {
        const double kept = double(c.error[previous]) + lambda * double(c.cost_us[previous]);
        const double cost_gap = std::abs(double(c.cost_us[previous]) - double(c.cost_us[best]));
        if (kept - best_value <= double(hysteresis) * lambda * cost_gap) return previous;
    }
    return best;
}

double lambda_bucket_edge(std::size_t bucket) {
    return std::exp(k_log_lambda_min + double(bucket + 1) * k_log_lambda_step);
}

void lambda_histogram::add(const rung_candidates& c) {
    if (c.count == 0) return;
    // The lower convex hull from the least-error rung towards the cheapest: from the current
    // vertex, the next is the cheaper rung reached at the least λ (Δerror / Δcost), ties to the
    // cheaper. Each step saves its cost difference from that λ on.
    std::uint8_t at = choose_at(c, 0.0, k_max_rungs, 0.0f);
    cost_at_zero_us += double(c.cost_us[at]);
    double lambda = 0.0;
    for (;;) {
        std::uint8_t next = at;
        double next_lambda = INFINITY;
        for (std::uint8_t r = 0; r < c.count; ++r) {
            if (!(c.cost_us[r] < c.cost_us[at])) continue;
            const double l = std::max(lambda, double(c.error[r] - c.error[at]) / double(c.cost_us[at] - c.cost_us[r]));
            if (l < next_lambda || (l == next_lambda && c.cost_us[r] < c.cost_us[next])) {
                next = r;
                next_lambda = l;
            }
        }
        if (next == at) return;
        saving_us[bucket_of(next_lambda)] += double(c.cost_us[at] - c.cost_us[next]);
        at = next;
        lambda = next_lambda;
    }
}

void lambda_histogram::merge(const lambda_histogram& other) {
    cost_at_zero_us += other.cost_at_zero_us;
    for (std::size_t b = 0; b < saving_us.size(); ++b) saving_us[b] += other.saving_us[b];
}

double lambda_histogram::cheapest_cost_us() const {
    double cost = cost_at_zero_us;
    for (const double saving : saving_us) cost -= saving;
    return cost;
}

lambda_choice solve_lambda(const lambda_histogram& h, double budget_us) {
    double cost = h.cost_at_zero_us;
    if (cost <= budget_us) return {};
    for (std::size_t b = 0; b < k_lambda_buckets; ++b) {
        const double before = cost;
        cost -= h.saving_us[b];
        if (cost <= budget_us)
            return {b == 0 ? 0.0 : lambda_bucket_edge(b - 1), lambda_bucket_edge(b),
                    std::clamp((before - budget_us) / h.saving_us[b], 0.0, 1.0)};
    }
    return {k_lambda_max, k_lambda_max, 1.0};
}

}  // namespace sylva
