#include "models/cache/lodf_io.h"

#include <stdexcept>
#include <string>

#include "models/cache/bake_cache.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_magic = 0x464c5953;  // "SYLF"
static_assert(sizeof(lodf_cluster) == 8 && sizeof(lodf_node) == 12 && sizeof(lodf_collapse) == 8);

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error("LoDF model: " + what); }

}  // namespace

void validate_lodf(const lodf_model& model) {
    const lodf_structure& f = model.structure;
    const std::uint64_t leaves = f.leaf_count, groups = f.clusters.size();
    if (leaves == 0) {
        if (groups || !f.nodes.empty() || !model.indices.empty()) fail("clusters without leaves");
        return;
    }
    if (groups == 0 || groups > leaves) fail(std::to_string(groups) + " clusters for " + std::to_string(leaves) + " leaves");
    const std::uint64_t total = 2 * leaves - groups;
    if (f.nodes.size() != total || f.cluster_of_leaf.size() != total || f.position_of_leaf.size() != total)
        fail("F^r holds " + std::to_string(f.nodes.size()) + " leaves, not 2L − G = " + std::to_string(total));
    if (f.changed_group.size() != leaves - groups || f.collapses.size() != leaves - groups)
        fail("Changed_group has " + std::to_string(f.changed_group.size()) + " collapses, not L − G");
    std::uint64_t next = 0;
    std::vector<std::uint32_t> named(groups, 0);
    for (const std::uint32_t g : f.changed_group) {
        if (g >= groups) fail("Changed_group names cluster " + std::to_string(g));
        ++named[g];
    }
    for (std::uint64_t c = 0; c < groups; ++c) {
        const lodf_cluster& k = f.clusters[c];
        if (k.first_node != next || k.original_leaves == 0) fail("cluster " + std::to_string(c) + " is not where the previous ended");
        if (named[c] != k.original_leaves - 1) fail("cluster " + std::to_string(c) + " is named by the wrong number of collapses");
        next += k.node_count();
        if (next > total) fail("cluster " + std::to_string(c) + " runs past F^r");
        for (std::uint32_t p = 0; p < k.node_count(); ++p) {
            const lodf_node& n = f.nodes[k.first_node + p];
            if (n.leaf >= total || f.cluster_of_leaf[n.leaf] != c || f.position_of_leaf[n.leaf] != p)
                fail("cluster " + std::to_string(c) + " position " + std::to_string(p) + " holds a leaf placed elsewhere");
            if (std::uint64_t(n.first_index) + n.index_count > model.indices.size() || n.index_count % 3 != 0 || n.index_count == 0)
                fail("leaf " + std::to_string(n.leaf) + " has a bad index range");
            if (p > 0) {
                const lodf_node& before = f.nodes[k.first_node + p - 1];
                if (n.first_index != before.first_index + before.index_count)
                    fail("cluster " + std::to_string(c) + " is not one run of indices");
            }
        }
    }
    if (next != total) fail("clusters do not cover F^r");
    for (std::uint64_t k = 0; k < f.collapses.size(); ++k) {
        const lodf_collapse& c = f.collapses[k];
        if (c.old1 >= leaves + k || c.old2 >= leaves + k || c.old1 == c.old2)
            fail("collapse " + std::to_string(k) + " joins leaves it has not made");
    }
    if (model.crown_vertices > model.vertex_count) fail("more crown vertices than vertices");
    for (const std::uint32_t i : model.indices)
        if (i >= model.vertex_count) fail("index " + std::to_string(i) + " past the mesh's " + std::to_string(model.vertex_count) + " vertices");
}

std::vector<std::byte> serialize_lodf_model(const lodf_model& model) {
    binary_writer out;
    out.pod(k_magic);
    out.pod(k_lodf_format);
    const lodf_structure& f = model.structure;
    out.pod(f.leaf_count);
    out.pod(model.vertex_count);
    out.pod(model.crown_vertices);
    out.pod(model.mean_area_ratio);
    out.array(f.clusters);
    out.array(f.nodes);
    out.array(f.changed_group);
    out.array(f.collapses);
    out.array(f.cluster_of_leaf);
    out.array(f.position_of_leaf);
    out.array(model.indices);
    return std::move(out.bytes());
}

lodf_model deserialize_lodf_model(std::span<const std::byte> bytes) {
    binary_reader in(bytes);
    if (in.pod<std::uint32_t>() != k_magic) fail("magic number missing");
    if (const auto version = in.pod<std::uint32_t>(); version != k_lodf_format)
        fail("format " + std::to_string(version) + ", this build reads " + std::to_string(k_lodf_format));
    lodf_model model;
    lodf_structure& f = model.structure;
    f.leaf_count = in.pod<std::uint32_t>();
    model.vertex_count = in.pod<std::uint32_t>();
    model.crown_vertices = in.pod<std::uint32_t>();
    model.mean_area_ratio = in.pod<float>();
    f.clusters = in.array<lodf_cluster>();
    f.nodes = in.array<lodf_node>();
    f.changed_group = in.array<std::uint32_t>();
    f.collapses = in.array<lodf_collapse>();
    f.cluster_of_leaf = in.array<std::uint32_t>();
    f.position_of_leaf = in.array<std::uint32_t>();
    model.indices = in.array<std::uint32_t>();
    if (!in.at_end()) fail("trailing bytes");
    validate_lodf(model);
    return model;
}

}  // namespace sylva
