#include "models/gltf/gltf_container.h"

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "io/confined_path.h"
#include "io/input_file.h"
#include "io/json_nesting.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t k_glb_magic = 0x46546C67;       // "glTF"
constexpr std::uint32_t k_glb_json_chunk = 0x4E4F534A;  // "JSON"
constexpr std::size_t k_glb_header_bytes = 12;
constexpr std::size_t k_glb_chunk_header_bytes = 8;

[[noreturn]] void fail(const gltf_source& source, const std::string& problem) {
    throw std::runtime_error(source.name + ": " + problem);
}

std::uint32_t little_endian_u32(std::string_view bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v |= std::uint32_t(std::uint8_t(bytes[at + i])) << (8 * i);
    return v;
}

// The JSON chunk of a .glb, after checking the header against the file's real size.
std::string_view glb_json(const gltf_source& source) {
    const std::string_view bytes = source.bytes;
    if (bytes.size() < k_glb_header_bytes + k_glb_chunk_header_bytes)
        fail(source, "too short to be a binary glTF (" + std::to_string(bytes.size()) + " bytes)");
    if (little_endian_u32(bytes, 0) != k_glb_magic) fail(source, "not a binary glTF (no 'glTF' magic)");
    if (const std::uint32_t version = little_endian_u32(bytes, 4); version != 2)
        fail(source, "binary glTF version " + std::to_string(version) + "; only 2 is read");
    const std::uint64_t length = little_endian_u32(bytes, 8);
    if (length > bytes.size())
        fail(source, "the header claims " + std::to_string(length) + " bytes but the file has " +
                         std::to_string(bytes.size()) + " (truncated?)");
    const std::uint64_t json_length = little_endian_u32(bytes, 12);
    if (little_endian_u32(bytes, 16) != k_glb_json_chunk)
        fail(source, "the first chunk is not JSON");
    if (json_length == 0 || k_glb_header_bytes + k_glb_chunk_header_bytes + json_length > length)
        fail(source, "the JSON chunk claims " + std::to_string(json_length) +
                         " bytes, past the end of the file");
    return bytes.substr(k_glb_header_bytes + k_glb_chunk_header_bytes, std::size_t(json_length));
}

// Every external buffer and image URI must name a file inside the model's folder; data: URIs
// and bufferView images are inside the file itself. Checked on our own parse of the JSON so the
// message names the URI; malformed JSON is left to tinygltf to report.
void check_external_uris(const gltf_source& source, std::string_view json) {
    const nlohmann::json document = nlohmann::json::parse(json, nullptr, false);
    if (document.is_discarded() || !document.is_object()) return;
    for (const char* kind : {"buffers", "images"}) {
        const auto list = document.find(kind);
        if (list == document.end() || !list->is_array()) continue;
        for (std::size_t i = 0; i < list->size(); ++i) {
            const nlohmann::json& item = (*list)[i];
            if (!item.is_object()) continue;
            const auto uri = item.find("uri");
            if (uri == item.end() || !uri->is_string()) continue;
            const std::string& text = uri->get_ref<const std::string&>();
            if (text.starts_with("data:")) continue;
            const std::string what = source.name + ": " + std::string(kind).substr(0, std::strlen(kind) - 1) +
                                     " " + std::to_string(i);
            resolve_inside(source.folder, text, what);
        }
    }
}

// tinygltf's file access, confined to the model's folder and bounded in size. `user_data` is
// the gltf_source.
bool confined_file_exists(const std::string& path, void* user_data) {
    const auto& source = *static_cast<const gltf_source*>(user_data);
    std::error_code ec;
    return is_inside(source.folder, path) && fs::is_regular_file(path, ec);
}

std::string unexpanded_path(const std::string& path, void*) {
    return path;  // never `~` or $VARIABLE expansion: a URI is a file name, nothing more
}

bool confined_read(std::vector<unsigned char>* out, std::string* error, const std::string& path,
                   void* user_data) {
    const auto& source = *static_cast<const gltf_source*>(user_data);
    if (!is_inside(source.folder, path)) {
        if (error) *error += "outside the model's folder";
        return false;
    }
    try {
        const std::string bytes = read_input_file(path, k_max_model_bytes);
        out->assign(bytes.begin(), bytes.end());
        return true;
    } catch (const std::exception& e) {
        if (error) *error += e.what();
        return false;
    }
}

bool refuse_write(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
    if (error) *error += "the importer writes no files";
    return false;
}

}  // namespace

gltf_source read_gltf_source(const fs::path& file) {
    gltf_source source;
    source.name = file.filename().string();
    const std::string extension = file.extension().string();
    if (extension == ".glb" || extension == ".GLB") {
        source.binary = true;
    } else if (extension != ".gltf" && extension != ".GLTF") {
        fail(source, "not a glTF file (expected .gltf or .glb)");
    }
    std::error_code ec;
    if (!fs::exists(file, ec)) fail(source, "no such file (" + file.string() + ")");
    source.folder = fs::absolute(file, ec).parent_path();
    source.bytes = read_input_file(file, k_max_model_bytes);
    return source;
}

void parse_gltf(const gltf_source& source, tinygltf::Model& model) {
    const std::string_view json = source.binary ? glb_json(source) : std::string_view(source.bytes);
    if (const auto offset = find_nesting_beyond(json, k_max_gltf_depth))
        fail(source, "its JSON nests deeper than " + std::to_string(k_max_gltf_depth) +
                         " levels (at byte " + std::to_string(*offset) + " of the JSON)");
    check_external_uris(source, json);
    tinygltf::TinyGLTF loader = make_gltf_loader();
    tinygltf::FsCallbacks callbacks{&confined_file_exists, &unexpanded_path, &confined_read,
                                    &refuse_write, const_cast<gltf_source*>(&source)};
    loader.SetFsCallbacks(callbacks);
    std::string error, warning;
    const std::string base_dir = source.folder.string();
    const bool ok =
        source.binary
            ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                          reinterpret_cast<const unsigned char*>(source.bytes.data()),
                                          static_cast<unsigned>(source.bytes.size()), base_dir)
            : loader.LoadASCIIFromString(&model, &error, &warning, source.bytes.data(),
                                         static_cast<unsigned>(source.bytes.size()), base_dir);
    if (!ok) {
        while (!error.empty() && error.back() == '\n') error.pop_back();
        fail(source, error.empty() ? "cannot be read as glTF" : error);
    }
}

}  // namespace sylva
