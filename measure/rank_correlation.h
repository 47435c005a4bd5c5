#pragma once
// Spearman's rank correlation (the Pearson correlation of the two series' ranks, ties given the
// mean of the ranks they span): how well one per-vertex quantity orders vertices as another does,
// whatever the scale of either (issue 22: Luft 2007's k_a against ray-cast occlusion).
#include <vector>

namespace sylva {

// In [-1, 1]; 0 when either series is constant or they are not equally long and non-empty.
double spearman_correlation(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace sylva
