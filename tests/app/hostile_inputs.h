#pragma once
// Builders for the hostile corpus (hostile_corpus_test.cpp): a minimal valid glTF (one
// triangle) that each case then breaks in one way, written as .gltf text or .glb bytes.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace sylva::test {

// Three vertices (float VEC3) after three indices, in one buffer:
//   bytes 0..11  indices (u32 x 3)   bytes 12..47  positions (f32 x 9)
struct triangle_buffer {
    std::vector<unsigned char> bytes;
};

inline triangle_buffer make_triangle_buffer(std::uint32_t i0 = 0, std::uint32_t i1 = 1, std::uint32_t i2 = 2) {
    triangle_buffer b;
    const std::uint32_t indices[3] = {i0, i1, i2};
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    b.bytes.resize(48);
    std::memcpy(b.bytes.data(), indices, 12);
    std::memcpy(b.bytes.data() + 12, positions, 36);
    return b;
}

// The JSON of the triangle model; `buffer_uri` empty: the GLB's own BIN chunk. `index_count`
// and `extra` (appended as more top-level members) let a case lie about its data.
inline std::string triangle_json(const std::string& buffer_uri = "", std::uint64_t index_count = 3,
                                 const std::string& extra = "") {
    std::string buffer = R"({"byteLength":48)";
    if (!buffer_uri.empty()) buffer += R"(,"uri":")" + buffer_uri + "\"";
    buffer += "}";
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
           R"("meshes":[{"primitives":[{"attributes":{"POSITION":1},"indices":0}]}],"buffers":[)" +
           buffer +
           R"(],"bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":12},)"
           R"({"buffer":0,"byteOffset":12,"byteLength":36}],"accessors":[)"
           R"({"bufferView":0,"componentType":5125,"count":)" +
           std::to_string(index_count) +
           R"(,"type":"SCALAR"},{"bufferView":1,"componentType":5126,"count":3,"type":"VEC3",)"
           R"("min":[0,0,0],"max":[1,1,0]}])" +
           extra + "}";
}

inline void append_u32(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xFF);
}

// A .glb: header, JSON chunk (space-padded), BIN chunk (zero-padded) when `bin` is not empty.
inline std::string make_glb(std::string json, const std::vector<unsigned char>& bin) {
    while (json.size() % 4) json += ' ';
    std::string bin_chunk(bin.begin(), bin.end());
    while (bin_chunk.size() % 4) bin_chunk += '\0';
    const std::size_t total = 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin_chunk.size());
    std::string out = "glTF";
    append_u32(out, 2);
    append_u32(out, std::uint32_t(total));
    append_u32(out, std::uint32_t(json.size()));
    append_u32(out, 0x4E4F534A);
    out += json;
    if (!bin.empty()) {
        append_u32(out, std::uint32_t(bin_chunk.size()));
        append_u32(out, 0x004E4942);
        out += bin_chunk;
    }
    return out;
}

inline void write_file(const std::filesystem::path& path, const std::string& bytes) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
}

// CRC-32 (ISO 3309, as PNG chunks use), bit by bit: a test helper, speed does not matter.
inline std::uint32_t crc32(std::string_view bytes) {
    std::uint32_t crc = 0xFFFFFFFFu;
    for (const char c : bytes) {
        crc ^= std::uint8_t(c);
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

// A PNG signature and IHDR claiming width x height pixels, and nothing after it: a decoder that
// trusts the header allocates width * height * 4 bytes before it finds the data missing.
inline std::string png_header_claiming(std::uint32_t width, std::uint32_t height) {
    std::string png = "\x89PNG\r\n\x1a\n";
    auto big_endian = [&](std::uint32_t v) {
        for (int i = 3; i >= 0; --i) png += char((v >> (8 * i)) & 0xFF);
    };
    big_endian(13);
    const std::size_t chunk = png.size();
    png += "IHDR";
    big_endian(width);
    big_endian(height);
    png += std::string("\x08\x06\x00\x00\x00", 5);  // 8-bit RGBA
    big_endian(crc32(std::string_view(png).substr(chunk)));  // a correct CRC: the header is believed
    for (const char* type : {"IDAT", "IEND"}) {                // empty: libpng reads the header
        big_endian(0);
        png += type;
        big_endian(crc32(type));
    }
    return png;
}

}  // namespace sylva::test
