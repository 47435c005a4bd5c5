#pragma once
// nanoflann's dataset adaptor over a list of points, and the 3-D k-d tree over it, shared by the
// bakes that look up neighbours (models/bake/implicit_illumination.cpp, setup/population_ambient.cpp).
// nanoflann keeps a reference to the adaptor: it must outlive the tree.
#include <cstddef>
#include <glm/vec3.hpp>
#include <nanoflann.hpp>
#include <vector>

namespace sylva {

struct nanoflann_points {
    const std::vector<glm::vec3>* points;
    std::size_t kdtree_get_point_count() const { return points->size(); }
    float kdtree_get_pt(std::size_t i, std::size_t dim) const { return (*points)[i][int(dim)]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;  // nanoflann computes the bounds itself
    }
};

using point_kd_tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, nanoflann_points>, nanoflann_points, 3>;

}  // namespace sylva
