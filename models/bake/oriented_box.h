#pragma once
// Oriented bounding boxes of point sets, for the billboard clouds (models/bake/billboard_cloud.h):
// the principal-component (PCA) box, and the minimum-volume box that Behrendt 2005 §2.2 finds by
// rotating an initial box in one-degree steps. The paper reports that eigenvector boxes "often
// do not represent the cluster in a visually optimal way" and that the minimum-volume box does.
//
// Written by hand: the 3x3 symmetric eigen solver is twenty lines (Jacobi), and the rotation
// search is the paper's own procedure; no Debian library offers either for glm types.
#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <span>

namespace sylva {

// A box centred at `center` with orthonormal, right-handed `axes` (cross(axes[0], axes[1]) ==
// axes[2]) and half its side along each axis in `half_extent`. Degenerate point sets give a zero
// half extent along the flat directions, never NaN.
struct oriented_box {
    glm::vec3 center{0.0f};
    std::array<glm::vec3, 3> axes{glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};
    glm::vec3 half_extent{0.0f};

    float volume() const { return 8.0f * half_extent.x * half_extent.y * half_extent.z; }
};

// The tightest box around `points` whose axes are the given orthonormal frame.
oriented_box fit_box(std::span<const glm::vec3> points, const std::array<glm::vec3, 3>& axes);

// The tightest box whose axes are the eigenvectors of the points' covariance (largest variance
// first). Throws std::invalid_argument when `points` is empty or holds a non-finite coordinate.
oriented_box pca_box(std::span<const glm::vec3> points);

struct min_box_settings {
    float step_degrees = 1.0f;      // Behrendt 2005 §2.2: "rotating the box in one-degree steps"
    std::uint32_t max_rounds = 32;  // sweeps over the three axes; the search stops earlier when
                                    // a sweep finds no smaller box
};

// Behrendt 2005 §2.2: starting from `initial`'s axes, for each of the box's three axes in turn
// every rotation about it by a whole number of steps in (0°, 90°) is tried (a box is unchanged
// by a quarter turn, so that covers every orientation about that axis at the step's resolution),
// and the smallest box is kept; sweeps repeat until one improves nothing. The objective is the
// volume with every side padded by a millionth of the points' extent, so flat and collinear sets
// still prefer the smallest face (or cross-section) instead of tying at zero volume.
// Deterministic. Throws std::invalid_argument like pca_box, or for a step outside (0°, 45°].
oriented_box minimum_volume_box(std::span<const glm::vec3> points, const oriented_box& initial,
                                const min_box_settings& settings = {});

// minimum_volume_box from the PCA box, the paper's "given initial bounding box".
oriented_box minimum_volume_box(std::span<const glm::vec3> points, const min_box_settings& settings = {});

}  // namespace sylva
