#pragma once
// The verdict of a bench, per lighting family: does each representation family's sweep beat the
// engine baseline's sweep (full mesh near, one crossed billboard beyond 0, 25, 50 or 100 m)?
// A baseline point is beaten when some configuration of the sweep is at least as fast (time
// ratio <= 1, from the timing rounds when there were several) with SSIM at least the baseline
// point's and FLIP at most its. Only configurations measured against the same reference are
// compared (bench_report.h: lighting families).
#include <string>
#include <vector>

#include "app/bench_report.h"

namespace sylva {

struct baseline_point_verdict {
    std::string baseline;     // the baseline point's configuration
    std::string beaten_by;    // the fastest configuration of the sweep that beats it; empty: none
    double time_ratio = 0.0;  // beaten_by's frame time over the baseline point's
    std::string why_not;      // when none beats it: the closest miss, in words
};

struct family_verdict {
    std::string lighting;  // the lighting family
    std::string family;    // the representation family whose sweep is judged
    std::vector<std::string> configurations;
    std::vector<baseline_point_verdict> points;  // one per baseline point, by switch distance

    bool beats_every_point() const;
    // "yes", or "no: not <baseline point>, <baseline point>".
    std::string summary() const;
};

// Every representation family (not the reference, brute force or the baseline itself) of every
// lighting family that has baseline points, in report order.
std::vector<family_verdict> baseline_verdicts(const bench_report& report);

}  // namespace sylva
