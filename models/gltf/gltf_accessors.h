#pragma once
// Reading a glTF accessor's elements out of tinygltf's model, each accessor checked against its
// buffer view and buffer before anything is allocated for it: numbers of any component type,
// indices exactly as stored, and the triangle list of a primitive of any triangle mode. Every
// failure names the file and the part being read (gltf_import.cpp walks the nodes).
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/gltf/gltf_tinygltf.h"

namespace sylva::gltf_accessors {

// What a failure names: the file, and the part of it being read.
struct import_context {
    std::string file;  // file name for messages
    const tinygltf::Model* model = nullptr;
    [[noreturn]] void fail(const std::string& part, const std::string& what) const {
        throw std::runtime_error(file + ": " + part + ": " + what);
    }
};

// Reads `components` numbers per element of any glTF component type (normalized integers map
// to 0..1 or -1..1 as the spec says); an accessor with no buffer view is all zeros.
std::vector<float> read_floats(const import_context& c, int accessor_index, int components,
                               const std::string& part);

// Indices exactly as stored (unsigned byte, short or int only).
std::vector<std::uint32_t> read_indices(const import_context& c, int accessor_index,
                                        const std::string& part);

// Triangle-list indices of a TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN primitive of
// `vertex_count` vertices (every index checked against it); other modes fail.
std::vector<std::uint32_t> read_triangles(const import_context& c, const tinygltf::Primitive& p,
                                          std::size_t vertex_count, const std::string& part);

}  // namespace sylva::gltf_accessors
