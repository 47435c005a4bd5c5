#include "systems/render/textures.h"

#include <algorithm>
#include <bit>
#include <stdexcept>

namespace sylva::render {

gl_texture make_texture_array(std::span<const image_rgba8> layers, bool repeat) {
    if (layers.empty()) throw std::invalid_argument("make_texture_array: no layers");
    const auto w = layers[0].width;
    const auto h = layers[0].height;
    for (const auto& layer : layers)
        if (layer.width != w || layer.height != h)
            throw std::invalid_argument("make_texture_array: layers differ in size");
    gl_texture texture = make_texture(GL_TEXTURE_2D_ARRAY);
    const int levels = std::bit_width(std::max(w, h));
    glTextureStorage3D(texture.id(), levels, GL_RGBA8, GLsizei(w), GLsizei(h), GLsizei(layers.size()));
    for (std::size_t i = 0; i < layers.size(); ++i)
        glTextureSubImage3D(texture.id(), 0, 0, 0, GLint(i), GLsizei(w), GLsizei(h), 1, GL_RGBA,
                            GL_UNSIGNED_BYTE, layers[i].texels.data());
    glGenerateTextureMipmap(texture.id());
    const GLint wrap = repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, wrap);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, wrap);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameterf(texture.id(), GL_TEXTURE_MAX_ANISOTROPY, 4.0f);
    return texture;
}

gl_texture make_float_texture(int width, int height, const float* rgb) {
    gl_texture texture = make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, GL_RGB16F, width, height);
    glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, GL_RGB, GL_FLOAT, rgb);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return texture;
}

}  // namespace sylva::render
