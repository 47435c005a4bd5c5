#include "lod/leaf_shrink.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "models/bake/lodf_leaves.h"
#include "models/random.h"

namespace sylva {

mesh_data leaf_shrink_mesh(const mesh_data& full, std::uint32_t leaves, std::uint64_t seed) {
    mesh_data out = non_foliage_part(full);
    const std::vector<foliage_leaf> all = find_foliage_leaves(full);
    const auto total = std::uint32_t(all.size());
    if (total == 0) return out;
    if (leaves == 0 || leaves > total) leaves = total;
    std::vector<std::uint32_t> order(total);
    std::iota(order.begin(), order.end(), 0u);
    rng random(seed);
    shuffle_groups(order, 1, random);
    const float grow = std::sqrt(float(total) / float(leaves));
    const auto first = std::uint32_t(out.indices.size());
    std::vector<char> moved(out.vertices.size(), 0);
    for (std::uint32_t k = 0; k < leaves; ++k) {
        const foliage_leaf& leaf = all[order[k]];
        for (const std::uint32_t t : leaf.triangles)
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t v = full.indices[3 * std::size_t(t) + std::size_t(c)];
                out.indices.push_back(v);
                if (moved[v]) continue;
                moved[v] = 1;
                out.vertices[v].position = leaf.centre + (full.vertices[v].position - leaf.centre) * grow;
            }
    }
    out.submeshes.push_back({first, std::uint32_t(out.indices.size()) - first, material_kind::leaf});
    return out;
}

}  // namespace sylva
