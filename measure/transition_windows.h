#pragma once
// Transitions of plants between representations along a camera path, found from what each plant
// is drawn as frame by frame, and the lighting jump measured over each whole transition.
//
// A transition window is a maximal run of frames in which a plant's drawn mix changes from one
// frame to the next: a hard switch changes it in one frame; a fade or a dissolve changes its
// partner's share every frame of the band; Deussen's §5.3 blend changes the split between
// triangles and points every frame until every part has settled; a handover to or from an eco
// tile's aggregated set changes the group the plant is drawn in. The window runs from the last
// frame before the change started (`from`) to the first frame after which it stopped (`to`):
//
//   frame:    0    1    2    3    4    5    6
//   mix:      A    A    A+B  A+B' B    B    B        (A+B: A whole, B fading in)
//   changed:       -    x    x    x    -    -
//   window:             from=1 ........ to=4
//
// Only complete windows are measured: one whose change began before the first frame, or was
// still going on at the last frame, is not (the path did not show its ends), and neither is one
// that ends as it began (a band entered and left again: popping sees that, not this).
//
// The lighting jump of a window is |(C_to − C_from) − (R_to − R_from)|: the test's colour change
// of the plant over the whole transition less the reference's change over the same frames (the
// camera and sun move; the reference does not switch), Euclidean RGB in 8-bit units. Measuring
// at the frame where the primary representation flips instead would see nearly nothing of a
// fade, whose two representations are both drawn whole on either side of that frame.
//
// A plant drawn as part of an eco tile's set (Deussen 2002 §6.2) has no pixels of its own: its
// window is measured over the whole group's plants (drawn_mix::group_*), in the test and in the
// reference alike, and the plants of one group that hand over together count once.
//
// Pure CPU and deterministic: windows come out ordered by plant, then frame.
#include <cstdint>
#include <span>
#include <vector>

#include "measure/temporal_metrics.h"

namespace sylva {

// What one plant is drawn as in one frame, as codes this layer does not interpret (the bench
// fills them in, app/drawn_mix.h): two mixes are the same drawing exactly when they are equal.
struct drawn_mix {
    std::uint8_t primary = 0;       // what is drawn whole; k_not_drawn: nothing (culled)
    std::uint8_t partner = 0;       // what is drawn besides it during a transition; 0: nothing
    std::uint16_t detail = 0;       // a handover within the primary (e.g. lines drawn as splats)
    float share = 0.0f;             // how much of the partner, or of the primary's second form
    std::uint32_t group_first = 0;  // the plants whose pixels count as this plant's: itself, or
    std::uint32_t group_count = 1;  // the eco tile whose set draws it (dense plant indices)

    bool operator==(const drawn_mix&) const = default;
};

inline constexpr std::uint8_t k_not_drawn = 0;

struct transition_window {
    std::uint32_t first_plant = 0;  // the unit measured: one plant, or a whole eco tile group
    std::uint32_t plant_count = 1;
    std::uint32_t from_frame = 0;
    std::uint32_t to_frame = 0;
    drawn_mix from;  // the first plant's mix at from_frame and at to_frame
    drawn_mix to;
    bool partnered = false;  // some frame of the window drew a partner (a fade or dissolve)
    bool grouped = false;    // some frame of the window drew the plant in an eco tile's set
};

// Finds the windows of every plant, fed one frame at a time.
class transition_finder {
public:
    explicit transition_finder(std::size_t plants);

    // The mixes of frame `frames()`, one per plant. Throws std::invalid_argument on a count
    // other than the constructor's.
    void add_frame(std::span<const drawn_mix> mixes);
    std::uint32_t frames() const { return m_frames; }

    // The complete windows (see above), in plant order; windows of one group ending on the same
    // frame are merged into one, from the earliest start. Call after the last frame.
    std::vector<transition_window> complete_windows() const;
    // Windows the path cut off at either end; windows that ended as they began.
    std::uint64_t incomplete_windows() const { return m_incomplete + open_at_end(); }
    // Of a shard of the path (issue 25): a window belongs to the frames in which its end was
    // seen, the first unchanged frame after it (to_frame + 1), so shards [a, b) and [b, c) fed
    // every frame from 0 to their last split the whole path's windows between them exactly.
    // The windows cut off at the path's start whose end was seen in [first, end).
    std::uint64_t cut_off_at_start_ending_in(std::uint32_t first, std::uint32_t end) const;
    // Windows open now: counted as cut off by the shard that holds the path's last frame.
    std::uint64_t open_windows() const { return open_at_end(); }
    // The first frames (from_frame) of the windows open now that may still be measured, sorted,
    // once each: a shard starting at the next frame needs the colours of those frames.
    std::vector<std::uint32_t> open_from_frames() const;
    std::uint64_t returned_windows() const { return m_returned; }

private:
    struct open_window {
        bool open = false;
        bool seen_from_start = false;  // the frame before the change was seen, not frame 0's past
        bool hidden = false;           // some frame of it drew nothing (visibility, not a switch)
        bool partnered = false;
        bool grouped = false;
        std::uint32_t from_frame = 0;
        std::uint32_t group_first = 0;
        std::uint32_t group_end = 0;
        drawn_mix from;
    };
    std::uint64_t open_at_end() const;

    std::vector<drawn_mix> m_previous;
    std::vector<open_window> m_open;
    std::vector<transition_window> m_complete;
    std::uint32_t m_frames = 0;
    std::uint64_t m_incomplete = 0;
    std::vector<std::uint32_t> m_incomplete_seen;  // the frame each of them was seen to end
    std::uint64_t m_returned = 0;
};

// The mean colour of the plants [first, first + count) together, from a frame's per-plant colours
// keyed by plant ID (dense index + 1, as mean_plant_colors gives them).
plant_color group_color(const plant_colors& colors, std::uint32_t first, std::uint32_t count);

// The lighting jump of `w` (see above), or a negative value when the unit covers fewer than
// `min_pixels` pixels in any of the four colours (its colour is then mostly its edges').
// `test` and `reference` hold every frame's colours, indexed by frame.
double window_lighting_jump(const transition_window& w, std::span<const plant_colors> test,
                            std::span<const plant_colors> reference, std::uint32_t min_pixels);

}  // namespace sylva
