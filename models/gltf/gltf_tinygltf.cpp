// tinygltf's implementation, compiled once, with OpenImageIO as its image decoder.
#define TINYGLTF_IMPLEMENTATION
#include "models/gltf/gltf_tinygltf.h"

#include <exception>

#include "models/gltf/gltf_image_codec.h"

namespace sylva {
namespace {

bool load_image_with_oiio(tinygltf::Image* image, const int image_index, std::string* error,
                          std::string*, int, int, const unsigned char* bytes, int size, void*) {
    try {
        const image_rgba8 decoded =
            decode_image({bytes, std::size_t(size)},
                         "image " + std::to_string(image_index) + " '" + image->name + "'");
        image->width = int(decoded.width);
        image->height = int(decoded.height);
        image->component = 4;
        image->bits = 8;
        image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
        image->image = decoded.texels;
        return true;
    } catch (const std::exception& e) {
        if (error) *error += e.what();
        return false;
    }
}

}  // namespace

tinygltf::TinyGLTF make_gltf_loader() {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&load_image_with_oiio, nullptr);
    return loader;
}

}  // namespace sylva
