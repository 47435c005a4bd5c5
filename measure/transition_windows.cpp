#include "measure/transition_windows.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

namespace sylva {

transition_finder::transition_finder(std::size_t plants) : m_previous(plants), m_open(plants) {}

void transition_finder::add_frame(std::span<const drawn_mix> mixes) {
    if (mixes.size() != m_previous.size())
        throw std::invalid_argument("transition_finder: " + std::to_string(mixes.size()) +
                                    " mixes for " + std::to_string(m_previous.size()) + " plants");
    const std::uint32_t t = m_frames++;
    if (t == 0) {
        std::copy(mixes.begin(), mixes.end(), m_previous.begin());
        return;
    }
    for (std::size_t k = 0; k < mixes.size(); ++k) {
        const drawn_mix& now = mixes[k];
        const drawn_mix& before = m_previous[k];
        open_window& w = m_open[k];
        if (now != before) {
            if (!w.open) {
                w = {};
                w.open = true;
                // The plant was settled at t - 1 only if the path showed the frame before it.
                w.seen_from_start = t >= 2;
                w.from_frame = t - 1;
                w.from = before;
                w.group_first = before.group_first;
                w.group_end = before.group_first + before.group_count;
                w.hidden = before.primary == k_not_drawn;
                w.partnered = before.partner != 0;
                w.grouped = before.group_count > 1;
            }
            w.hidden = w.hidden || now.primary == k_not_drawn;
            w.partnered = w.partnered || now.partner != 0;
            w.grouped = w.grouped || now.group_count > 1;
            w.group_first = std::min(w.group_first, now.group_first);
            w.group_end = std::max(w.group_end, now.group_first + now.group_count);
        } else if (w.open) {
            // Unchanged since t - 1: the change ended there.
            w.open = false;
            if (w.hidden) continue;  // entering or leaving the view is not a transition
            if (!w.seen_from_start) {
                ++m_incomplete;
                m_incomplete_seen.push_back(t);
                continue;
            }
            if (w.from == before) {
                ++m_returned;
                continue;
            }
            transition_window out;
            out.first_plant = w.grouped ? w.group_first : std::uint32_t(k);
            out.plant_count = w.grouped ? w.group_end - w.group_first : 1u;
            out.from_frame = w.from_frame;
            out.to_frame = t - 1;
            out.from = w.from;
            out.to = before;
            out.partnered = w.partnered;
            out.grouped = w.grouped;
            m_complete.push_back(out);
        }
    }
    std::copy(mixes.begin(), mixes.end(), m_previous.begin());
}

std::uint64_t transition_finder::open_at_end() const {
    return std::uint64_t(std::count_if(m_open.begin(), m_open.end(),
                                       [](const open_window& w) { return w.open && !w.hidden; }));
}

std::uint64_t transition_finder::cut_off_at_start_ending_in(std::uint32_t first, std::uint32_t end) const {
    return std::uint64_t(std::count_if(m_incomplete_seen.begin(), m_incomplete_seen.end(),
                                       [&](std::uint32_t t) { return t >= first && t < end; }));
}

std::vector<std::uint32_t> transition_finder::open_from_frames() const {
    std::vector<std::uint32_t> frames;
    for (const open_window& w : m_open)
        if (w.open && !w.hidden && w.seen_from_start) frames.push_back(w.from_frame);
    std::sort(frames.begin(), frames.end());
    frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
    return frames;
}

std::vector<transition_window> transition_finder::complete_windows() const {
    // The plants of one eco tile hand over together: one window per (group, last frame), from
    // the earliest start any of them saw.
    std::vector<transition_window> out;
    std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, std::size_t> group_windows;
    for (const transition_window& w : m_complete) {
        if (!w.grouped) {
            out.push_back(w);
            continue;
        }
        const auto key = std::make_tuple(w.first_plant, w.plant_count, w.to_frame);
        const auto [it, inserted] = group_windows.emplace(key, out.size());
        if (inserted) {
            out.push_back(w);
            continue;
        }
        transition_window& kept = out[it->second];
        if (w.from_frame < kept.from_frame) {
            kept.from_frame = w.from_frame;
            kept.from = w.from;
        }
        kept.partnered = kept.partnered || w.partnered;
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const transition_window& a, const transition_window& b) {
                         return std::tie(a.first_plant, a.from_frame, a.to_frame) <
                                std::tie(b.first_plant, b.from_frame, b.to_frame);
                     });
    return out;
}

plant_color group_color(const plant_colors& colors, std::uint32_t first, std::uint32_t count) {
    plant_color sum;
    for (std::uint32_t k = first; k < first + count; ++k) {
        const auto it = colors.find(k + 1);
        if (it == colors.end()) continue;
        const plant_color& c = it->second;
        sum.r += c.r * c.pixels;
        sum.g += c.g * c.pixels;
        sum.b += c.b * c.pixels;
        sum.pixels += c.pixels;
    }
    if (sum.pixels > 0) {
        sum.r /= sum.pixels;
        sum.g /= sum.pixels;
        sum.b /= sum.pixels;
    }
    return sum;
}

double window_lighting_jump(const transition_window& w, std::span<const plant_colors> test,
                            std::span<const plant_colors> reference, std::uint32_t min_pixels) {
    if (w.to_frame >= test.size() || w.to_frame >= reference.size())
        throw std::invalid_argument("window_lighting_jump: the window ends at frame " +
                                    std::to_string(w.to_frame) + " of " +
                                    std::to_string(test.size()));
    const plant_color test_from = group_color(test[w.from_frame], w.first_plant, w.plant_count);
    const plant_color test_to = group_color(test[w.to_frame], w.first_plant, w.plant_count);
    const plant_color reference_from =
        group_color(reference[w.from_frame], w.first_plant, w.plant_count);
    const plant_color reference_to =
        group_color(reference[w.to_frame], w.first_plant, w.plant_count);
    for (const plant_color* c : {&test_from, &test_to, &reference_from, &reference_to})
        if (c->pixels < min_pixels) return -1.0;
    return lighting_jump(test_from, test_to, reference_from, reference_to);
}

}  // namespace sylva
