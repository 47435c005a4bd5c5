#include "models/gltf/gltf_accessors.h"

#include <algorithm>
#include <cstring>

namespace sylva::gltf_accessors {
namespace {

// An accessor with no buffer view is all zeros and costs no bytes in the file, so its count is
// bounded on its own: no plant has more vertices than this.
constexpr std::size_t k_max_zero_accessor_elements = 1u << 24;

const char* mode_name(int mode) {
    switch (mode) {
        case TINYGLTF_MODE_POINTS:
            return "POINTS";
        case TINYGLTF_MODE_LINE:
            return "LINES";
        case TINYGLTF_MODE_LINE_LOOP:
            return "LINE_LOOP";
        case TINYGLTF_MODE_LINE_STRIP:
            return "LINE_STRIP";
        default:
            return "unknown";
    }
}

// The accessor `accessor_index` checked against its buffer view and buffer before anything is
// allocated for it: a count is trusted only once the bytes it claims are there (a 2 KB file
// claiming 750 million elements fails here, not after a 3 GB allocation).
struct accessor_span {
    const tinygltf::Accessor* accessor = nullptr;
    const unsigned char* data = nullptr;  // first element; null: all zeros (no buffer view)
    std::size_t stride = 0;
    std::size_t component_size = 0;
};

accessor_span checked_accessor(const import_context& c, int accessor_index, int components,
                               const std::string& part) {
    const tinygltf::Model& m = *c.model;
    if (accessor_index < 0 || std::size_t(accessor_index) >= m.accessors.size())
        c.fail(part, "accessor " + std::to_string(accessor_index) + " does not exist");
    const tinygltf::Accessor& a = m.accessors[std::size_t(accessor_index)];
    if (a.sparse.isSparse) c.fail(part, "sparse accessors are not supported");
    if (tinygltf::GetNumComponentsInType(std::uint32_t(a.type)) != components)
        c.fail(part, "accessor " + std::to_string(accessor_index) + " has the wrong type");
    const int component_size = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
    if (component_size <= 0) c.fail(part, "unsupported component type");
    accessor_span span{&a, nullptr, 0, std::size_t(component_size)};
    const std::size_t element = span.component_size * std::size_t(components);
    if (a.bufferView < 0) {  // all zeros, as the spec says; the count still has to be plausible
        if (a.count > k_max_zero_accessor_elements)
            c.fail(part, "accessor " + std::to_string(accessor_index) + " claims " +
                             std::to_string(a.count) + " elements with no data");
        return span;
    }
    if (std::size_t(a.bufferView) >= m.bufferViews.size())
        c.fail(part, "buffer view " + std::to_string(a.bufferView) + " does not exist");
    const tinygltf::BufferView& view = m.bufferViews[std::size_t(a.bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= m.buffers.size())
        c.fail(part, "buffer " + std::to_string(view.buffer) + " does not exist");
    const std::vector<unsigned char>& data = m.buffers[std::size_t(view.buffer)].data;
    span.stride = view.byteStride ? view.byteStride : element;
    // Every size below comes from the file: compare in a way that cannot overflow.
    const auto past_end = [&](std::size_t start, std::size_t limit) {
        if (a.count == 0) return start > limit;
        if (start > limit || element > limit - start) return true;
        return (a.count - 1) > (limit - start - element) / span.stride;
    };
    if (span.stride < element || view.byteOffset > data.size() ||
        past_end(a.byteOffset, view.byteLength) ||
        past_end(view.byteOffset + a.byteOffset, data.size()) ||
        view.byteOffset + a.byteOffset < view.byteOffset)
        c.fail(part, "accessor " + std::to_string(accessor_index) + " (" + std::to_string(a.count) +
                         " elements) reads past the end of its buffer");
    span.data = data.data() + view.byteOffset + a.byteOffset;
    return span;
}

}  // namespace

// Reads `components` numbers per element of any glTF component type (normalized integers map
// to 0..1 or -1..1 as the spec says).
std::vector<float> read_floats(const import_context& c, int accessor_index, int components,
                               const std::string& part) {
    const accessor_span span = checked_accessor(c, accessor_index, components, part);
    const tinygltf::Accessor& a = *span.accessor;
    std::vector<float> out(a.count * std::size_t(components), 0.0f);
    if (!span.data) return out;
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* p = span.data + i * span.stride;
        for (int k = 0; k < components; ++k, p += span.component_size) {
            float v = 0;
            switch (a.componentType) {
                case TINYGLTF_COMPONENT_TYPE_FLOAT:
                    std::memcpy(&v, p, 4);
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    v = *p / (a.normalized ? 255.0f : 1.0f);
                    break;
                case TINYGLTF_COMPONENT_TYPE_BYTE:
                    v = float(std::int8_t(*p)) / (a.normalized ? 127.0f : 1.0f);
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    std::uint16_t s;
                    std::memcpy(&s, p, 2);
                    v = s / (a.normalized ? 65535.0f : 1.0f);
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_SHORT: {
                    std::int16_t s;
                    std::memcpy(&s, p, 2);
                    v = s / (a.normalized ? 32767.0f : 1.0f);
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
                    std::uint32_t s;
                    std::memcpy(&s, p, 4);
                    v = float(s);
                    break;
                }
                default:
                    c.fail(part, "unsupported component type");
            }
            out[i * std::size_t(components) + std::size_t(k)] =
                a.normalized ? std::max(v, -1.0f) : v;
        }
    }
    return out;
}

// Indices exactly as stored: the spec allows only unsigned byte, short and int, and a float has
// 24 bits of mantissa, so reading them as floats would turn 16,777,217 into 16,777,216 and
// 0xFFFFFFF0 into some other vertex.
std::vector<std::uint32_t> read_indices(const import_context& c, int accessor_index,
                                        const std::string& part) {
    const accessor_span span = checked_accessor(c, accessor_index, 1, part);
    const tinygltf::Accessor& a = *span.accessor;
    if (a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        c.fail(part, "indices must be unsigned bytes, shorts or ints");
    std::vector<std::uint32_t> out(a.count, 0);
    if (!span.data) return out;
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* p = span.data + i * span.stride;
        if (span.component_size == 1) {
            out[i] = *p;
        } else if (span.component_size == 2) {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            out[i] = v;
        } else {
            std::memcpy(&out[i], p, 4);
        }
    }
    return out;
}

// Triangle-list indices for TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN.
std::vector<std::uint32_t> read_triangles(const import_context& c, const tinygltf::Primitive& p,
                                          std::size_t vertex_count, const std::string& part) {
    std::vector<std::uint32_t> order;
    if (p.indices >= 0) {
        order = read_indices(c, p.indices, part + " indices");
    } else {
        for (std::size_t i = 0; i < vertex_count; ++i) order.push_back(std::uint32_t(i));
    }
    for (const std::uint32_t i : order)
        if (i >= vertex_count)
            c.fail(part, "index " + std::to_string(i) + " is past the last vertex");
    std::vector<std::uint32_t> triangles;
    if (p.mode == TINYGLTF_MODE_TRIANGLES || p.mode == -1) {
        triangles.assign(order.begin(), order.end() - std::ptrdiff_t(order.size() % 3));
    } else if (p.mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 2; i < order.size(); ++i) {
            const bool odd = i % 2;
            triangles.insert(triangles.end(),
                             {order[i - 2], order[odd ? i : i - 1], order[odd ? i - 1 : i]});
        }
    } else if (p.mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (std::size_t i = 2; i < order.size(); ++i)
            triangles.insert(triangles.end(), {order[0], order[i - 1], order[i]});
    } else {
        c.fail(part, std::string("mode ") + mode_name(p.mode) + " is not supported");
    }
    return triangles;
}

}  // namespace sylva::gltf_accessors
