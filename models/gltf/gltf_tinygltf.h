#pragma once
// The one way Sylva includes tinygltf. Images are decoded and encoded through OpenImageIO
// (models/gltf/gltf_image_codec.h), not tinygltf's bundled stb, so every translation unit must see
// the same configuration: TinyGLTF's inline constructor picks its default image callbacks from
// these macros.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>

namespace sylva {

// A loader with the OpenImageIO image callback installed (PNG and JPEG, embedded or external).
tinygltf::TinyGLTF make_gltf_loader();

}  // namespace sylva
