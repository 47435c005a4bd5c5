// Writes the glTF seed corpus: every fixture of tests/models/gltf/gltf_fixtures.h (real-world shapes
// and broken files alike) into the folder given as the only argument.
#include <cstdio>
#include <exception>
#include <filesystem>

#include "tests/app/hostile_inputs.h"
#include "tests/models/gltf/gltf_fixtures.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: write_gltf_seeds FOLDER\n");
        return 2;
    }
    namespace t = sylva::test;
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    try {
        t::write_opaque_leaves(dir, true);
        t::write_opaque_leaves(dir, false);
        t::write_many_materials(dir);
        t::write_branch_hierarchy(dir);
        t::write_missing_texture(dir);
        t::write_centimetres_scaled(dir);
        t::write_centimetres_unscaled(dir);
        t::write_blend_leaves(dir);
        t::write_jpeg_bark_and_tiled_leaf_uvs(dir);
        t::write_truncated_glb(dir);
        t::write_missing_buffer(dir);
        t::write_lines_primitive(dir);
        t::write_nan_position(dir);
        t::write_infinite_position(dir, false);
        t::write_overflowing_scale(dir);
        t::write_bad_json(dir);
        t::write_zero_area_triangles(dir);
        t::write_only_zero_area_triangles(dir);
        t::write_draco_required(dir);
        t::write_no_meshes(dir);
        // Small seeds: one triangle as .glb, as .gltf with an external buffer and with a data:
        // URI, so short mutations reach every stage of the reader.
        t::write_file(dir / "triangle.glb", t::make_glb(t::triangle_json(), t::make_triangle_buffer().bytes));
        const auto bin = t::make_triangle_buffer().bytes;
        t::write_file(dir / "triangle.bin", std::string(bin.begin(), bin.end()));
        t::write_file(dir / "triangle.gltf", t::triangle_json("triangle.bin"));
        t::write_file(dir / "triangle_data_uri.gltf",
                      t::triangle_json("data:application/octet-stream;base64,AAAAAAEAAAACAAAAAAAAAAAAAAAAAAAAAACAPwAA"
                                       "AAAAAAAAAAAAAAAAgD8AAAAA"));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "write_gltf_seeds: %s\n", e.what());
        return 1;
    }
    return 0;
}
