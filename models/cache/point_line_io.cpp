#include "models/cache/point_line_io.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "models/cache/bake_cache.h"
#include "models/cache/mesh_io.h"

namespace sylva {
namespace {

constexpr std::uint32_t k_magic = 0x4c505953;  // "SYPL"

[[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("bake cache entry: point/line model " + what);
}

[[noreturn]] void fail_part(std::size_t part, const std::string& what) {
    fail("part " + std::to_string(part) + ": " + what);
}

void write_part(binary_writer& out, const lod_part& p) {
    out.pod(std::uint8_t(p.primitive));
    out.pod(std::uint8_t(p.material));
    out.pod(std::uint8_t(p.kind));
    out.pod(std::uint8_t(p.stratified ? 1 : 0));
    out.pod(p.importance);
    out.pod(p.area_m2);
    out.pod(p.center);
    out.pod(p.first_index);
    out.pod(p.triangle_count);
    out.pod(p.first_point);
    out.pod(p.point_count);
    out.pod(p.first_after);
    out.pod(p.first_line);
    out.pod(p.line_count);
    out.pod(p.line_length_m);
    out.pod(p.line_error_m);
}

lod_part read_part(binary_reader& in, std::size_t index) {
    lod_part p;
    const auto primitive = in.pod<std::uint8_t>();
    const auto material = in.pod<std::uint8_t>();
    const auto kind = in.pod<std::uint8_t>();
    const auto stratified = in.pod<std::uint8_t>();
    if (primitive > std::uint8_t(lod_primitive::lines)) fail_part(index, "unknown primitive");
    if (material > std::uint8_t(material_kind::billboard)) fail_part(index, "unknown material");
    if (kind > std::uint8_t(part_kind::frond)) fail_part(index, "unknown part kind");
    if (stratified > 1) fail_part(index, "stratified flag is not 0 or 1");
    p.primitive = lod_primitive(primitive);
    p.material = material_kind(material);
    p.kind = part_kind(kind);
    p.stratified = stratified == 1;
    p.importance = in.pod<float>();
    p.area_m2 = in.pod<float>();
    p.center = in.pod<glm::vec3>();
    p.first_index = in.pod<std::uint32_t>();
    p.triangle_count = in.pod<std::uint32_t>();
    p.first_point = in.pod<std::uint32_t>();
    p.point_count = in.pod<std::uint32_t>();
    p.first_after = in.pod<std::uint32_t>();
    p.first_line = in.pod<std::uint32_t>();
    p.line_count = in.pod<std::uint32_t>();
    p.line_length_m = in.pod<float>();
    p.line_error_m = in.pod<float>();
    return p;
}

void write_cell(binary_writer& out, const lod_cell& c) {
    out.pod(c.bounds_min);
    out.pod(c.bounds_max);
    out.pod(c.first_part);
    out.pod(c.part_count);
}

lod_cell read_cell(binary_reader& in) {
    lod_cell c;
    c.bounds_min = in.pod<glm::vec3>();
    c.bounds_max = in.pod<glm::vec3>();
    c.first_part = in.pod<std::uint32_t>();
    c.part_count = in.pod<std::uint32_t>();
    return c;
}

bool finite_non_negative(float value) {
    return std::isfinite(value) && value >= 0.0f;
}

// [first, first + count) within size, without overflow.
bool within(std::uint64_t first, std::uint64_t count, std::uint64_t size) {
    return first <= size && count <= size - first;
}

void validate_points(const point_line_model& m, std::size_t i, const lod_part& p) {
    if (!within(p.first_point, p.point_count, m.points.size()))
        fail_part(i, "points outside the point array");
    if (!within(p.first_after, std::uint64_t(p.triangle_count) + 1, m.points_after.size()))
        fail_part(i, "points_after outside its array");
    const std::uint32_t* after = &m.points_after[p.first_after];
    if (after[0] != p.point_count || after[p.triangle_count] != 0)
        fail_part(i, "points_after does not run from the point count to 0");
    for (std::uint32_t t = 0; t < p.triangle_count; ++t) {
        if (after[t] < after[t + 1]) fail_part(i, "points_after increases");
        if (p.stratified && after[t] - after[t + 1] != 2)
            fail_part(i, "stratified part without two points per triangle");
    }
    if (p.line_count != 0) fail_part(i, "a point part with lines");
}

void validate_part(const point_line_model& m, std::size_t i) {
    const lod_part& p = m.parts[i];
    if (!finite_non_negative(p.importance) || !finite_non_negative(p.area_m2) ||
        !finite_non_negative(p.line_length_m) || !finite_non_negative(p.line_error_m))
        fail_part(i, "negative or non-finite importance, area, length or error");
    if (p.first_index % 3 != 0 ||
        !within(p.first_index, 3 * std::uint64_t(p.triangle_count), m.triangles.indices.size()))
        fail_part(i, "triangles outside the index array");
    const submesh& s = m.triangles.submeshes[i];
    if (s.first_index != p.first_index ||
        std::uint64_t(s.index_count) != 3 * std::uint64_t(p.triangle_count) ||
        s.material != p.material)
        fail_part(i, "submesh does not match the part");
    if (p.primitive == lod_primitive::points) {
        validate_points(m, i, p);
    } else {
        if (!within(2 * std::uint64_t(p.first_line), 2 * std::uint64_t(p.line_count),
                    m.lines.size()))
            fail_part(i, "lines outside the line array");
        if (p.point_count != 0) fail_part(i, "a line part with points");
    }
}

void validate(const point_line_model& m) {
    if (m.triangles.indices.size() % 3 != 0) fail("index count is not a multiple of 3");
    if (m.triangles.submeshes.size() != m.parts.size())
        fail("submesh count differs from the part count");
    if (!m.triangles.parts.empty() && m.triangles.parts.size() != m.triangles.triangle_count())
        fail("triangle records do not match the triangles");
    if (m.lines.size() % 2 != 0) fail("odd number of line vertices");
    for (std::size_t i = 0; i < m.parts.size(); ++i) validate_part(m, i);
    std::uint64_t next = 0;
    for (std::size_t c = 0; c < m.cells.size(); ++c) {
        const lod_cell& cell = m.cells[c];
        if (cell.first_part != next || cell.part_count == 0 || cell.part_count > k_max_cell_parts)
            fail("cell " + std::to_string(c) + ": parts not the next 1.." +
                 std::to_string(k_max_cell_parts));
        next += cell.part_count;
    }
    if (next != m.parts.size()) fail("cells do not cover every part");
}

}  // namespace

std::vector<std::byte> serialize_point_line_model(const point_line_model& model) {
    binary_writer out;
    out.pod(k_magic);
    out.pod(k_point_line_format);
    write_mesh(out, model.triangles);
    out.array(model.points);
    out.array(model.lines);
    out.array(model.points_after);
    out.pod(std::uint64_t(model.parts.size()));
    for (const lod_part& p : model.parts) write_part(out, p);
    out.pod(std::uint64_t(model.cells.size()));
    for (const lod_cell& c : model.cells) write_cell(out, c);
    return std::move(out.bytes());
}

point_line_model deserialize_point_line_model(std::span<const std::byte> bytes) {
    // Each serialised part and cell is at least this many bytes: a corrupted count is caught
    // before it allocates.
    constexpr std::size_t k_part_bytes = 4 + 4 * 4 + 12 + 7 * 4 + 2 * 4;
    constexpr std::size_t k_cell_bytes = 2 * 12 + 2 * 4;
    binary_reader in(bytes);
    if (in.pod<std::uint32_t>() != k_magic) fail("magic number missing");
    if (const auto version = in.pod<std::uint32_t>(); version != k_point_line_format)
        fail("format " + std::to_string(version) + ", this build reads " +
             std::to_string(k_point_line_format));
    point_line_model model;
    model.triangles = read_mesh(in);
    model.points = in.array<vertex>();
    model.lines = in.array<vertex>();
    model.points_after = in.array<std::uint32_t>();
    const auto part_count = in.pod<std::uint64_t>();
    if (part_count > bytes.size() / k_part_bytes) fail("part count larger than the entry");
    for (std::uint64_t i = 0; i < part_count; ++i) model.parts.push_back(read_part(in, i));
    const auto cell_count = in.pod<std::uint64_t>();
    if (cell_count > bytes.size() / k_cell_bytes) fail("cell count larger than the entry");
    for (std::uint64_t i = 0; i < cell_count; ++i) model.cells.push_back(read_cell(in));
    if (!in.at_end()) fail("trailing bytes");
    validate(model);
    return model;
}

}  // namespace sylva
