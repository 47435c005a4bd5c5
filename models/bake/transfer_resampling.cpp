#include "models/bake/transfer_resampling.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <nanoflann.hpp>
#include <stdexcept>
#include <vector>

#include "ecs/parallel.h"

namespace sylva {
namespace {

// nanoflann's dataset adaptor over a mesh's vertex positions.
struct vertex_cloud {
    const std::vector<vertex>* vertices;
    std::size_t kdtree_get_point_count() const { return vertices->size(); }
    float kdtree_get_pt(std::size_t i, std::size_t dim) const {
        return (*vertices)[i].position[int(dim)];
    }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};

using vertex_tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, vertex_cloud>,
                                        vertex_cloud, 3>;

// Fixed chunks: the result never depends on how many threads ran them.
constexpr std::size_t k_chunk = 1024;

}  // namespace

radiance_transfer resample_transfer(const mesh_data& full, const radiance_transfer& full_transfer,
                                    std::span<const vertex> receivers, std::uint32_t k) {
    const std::size_t n = std::size_t(full_transfer.bands) * full_transfer.bands;
    if (k == 0 || n == 0 || full_transfer.receiver_count() != full.vertices.size() ||
        full_transfer.back.size() != full_transfer.front.size())
        throw std::invalid_argument(
            "resample_transfer: the full transfer must have one receiver per vertex, k > 0");
    radiance_transfer out;
    out.bands = full_transfer.bands;
    out.front.assign(receivers.size() * n, 0.0f);
    out.back.assign(receivers.size() * n, 0.0f);
    if (full.vertices.empty() || receivers.empty()) return out;

    const vertex_cloud cloud{&full.vertices};
    vertex_tree tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(16));
    tree.buildIndex();
    const std::uint32_t count = std::min<std::uint32_t>(k, std::uint32_t(full.vertices.size()));
    const std::size_t chunks = (receivers.size() + k_chunk - 1) / k_chunk;
    ecs::parallel_for_each_index(chunks, [&](std::size_t chunk) {
        std::vector<std::uint32_t> nearest(count);
        std::vector<float> distances(count);
        const std::size_t end = std::min(receivers.size(), (chunk + 1) * k_chunk);
        for (std::size_t r = chunk * k_chunk; r < end; ++r) {
            const vertex& receiver = receivers[r];
            const std::size_t found =
                tree.knnSearch(&receiver.position.x, count, nearest.data(), distances.data());
            float* front = &out.front[r * n];
            float* back = &out.back[r * n];
            for (std::size_t j = 0; j < found; ++j) {
                const std::uint32_t v = nearest[j];
                const bool turned = glm::dot(full.vertices[v].normal, receiver.normal) < 0.0f;
                const float* f = &full_transfer.front[std::size_t(v) * n];
                const float* b = &full_transfer.back[std::size_t(v) * n];
                for (std::size_t i = 0; i < n; ++i) {
                    front[i] += turned ? b[i] : f[i];
                    back[i] += turned ? f[i] : b[i];
                }
            }
            for (std::size_t i = 0; i < n; ++i) {
                front[i] /= float(found);
                back[i] /= float(found);
            }
        }
    });
    return out;
}

}  // namespace sylva
