#include "systems/render/render_target.h"

#include <cstring>
#include <stdexcept>

namespace sylva::render {
namespace {

// GL's first row is the bottom one; images are stored top row first.
image_rgba8 image_from_bottom_up(int width, int height, const std::vector<std::uint8_t>& bottom_up) {
    image_rgba8 image;
    image.width = std::uint32_t(width);
    image.height = std::uint32_t(height);
    const std::size_t row = std::size_t(width) * 4;
    image.texels.resize(bottom_up.size());
    for (int y = 0; y < height; ++y)
        std::memcpy(&image.texels[std::size_t(y) * row], &bottom_up[std::size_t(height - 1 - y) * row], row);
    return image;
}

}  // namespace

render_target::render_target(int width, int height, bool id_buffer, bool normal_buffer)
    : m_width(width), m_height(height), m_color(make_texture(GL_TEXTURE_2D)),
      m_depth(make_texture(GL_TEXTURE_2D)), m_framebuffer(make_framebuffer()) {
    glTextureStorage2D(m_color.id(), 1, GL_RGBA8, width, height);
    glTextureStorage2D(m_depth.id(), 1, GL_DEPTH_COMPONENT24, width, height);
    glNamedFramebufferTexture(m_framebuffer.id(), GL_COLOR_ATTACHMENT0, m_color.id(), 0);
    glNamedFramebufferTexture(m_framebuffer.id(), GL_DEPTH_ATTACHMENT, m_depth.id(), 0);
    if (id_buffer) {
        m_ids = make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(m_ids.id(), 1, GL_R32UI, width, height);
        glNamedFramebufferTexture(m_framebuffer.id(), GL_COLOR_ATTACHMENT1, m_ids.id(), 0);
    }
    if (normal_buffer) {
        m_normals = make_texture(GL_TEXTURE_2D);
        glTextureStorage2D(m_normals.id(), 1, GL_RGBA8, width, height);
        glNamedFramebufferTexture(m_framebuffer.id(), GL_COLOR_ATTACHMENT2, m_normals.id(), 0);
    }
    draw_ids(false);
    if (glCheckNamedFramebufferStatus(m_framebuffer.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("render_target: framebuffer incomplete");
}

void render_target::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, m_framebuffer.id());
    glViewport(0, 0, m_width, m_height);
}

void render_target::draw_ids(bool enabled) const {
    const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GLenum(enabled && has_id_buffer() ? GL_COLOR_ATTACHMENT1 : GL_NONE),
                               GL_NONE};
    glNamedFramebufferDrawBuffers(m_framebuffer.id(), 3, buffers);
}

void render_target::draw_surfaces() const {
    const GLenum buffers[3] = {GL_COLOR_ATTACHMENT0, GLenum(has_id_buffer() ? GL_COLOR_ATTACHMENT1 : GL_NONE),
                               GLenum(has_normal_buffer() ? GL_COLOR_ATTACHMENT2 : GL_NONE)};
    glNamedFramebufferDrawBuffers(m_framebuffer.id(), 3, buffers);
}

std::vector<std::uint32_t> render_target::read_ids() const {
    if (!has_id_buffer()) return {};
    const std::size_t row = std::size_t(m_width);
    std::vector<std::uint32_t> bottom_up(row * std::size_t(m_height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(m_ids.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT,
                      GLsizei(bottom_up.size() * sizeof(std::uint32_t)), bottom_up.data());
    std::vector<std::uint32_t> ids(bottom_up.size());
    for (int y = 0; y < m_height; ++y)
        std::memcpy(&ids[std::size_t(y) * row], &bottom_up[std::size_t(m_height - 1 - y) * row],
                    row * sizeof(std::uint32_t));
    return ids;
}

void render_target::read_ids_bottom_up(std::vector<std::uint32_t>& out) const {
    out.resize(has_id_buffer() ? std::size_t(m_width) * std::size_t(m_height) : 0);
    if (out.empty()) return;
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTextureImage(m_ids.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(out.size() * sizeof(std::uint32_t)),
                      out.data());
}

image_rgba8 render_target::read_color() const {
    std::vector<std::uint8_t> bottom_up(std::size_t(m_width) * std::size_t(m_height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(m_color.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(bottom_up.size()),
                      bottom_up.data());
    return image_from_bottom_up(m_width, m_height, bottom_up);
}

void render_target::blit_to_default(int window_width, int window_height) const {
    glBlitNamedFramebuffer(m_framebuffer.id(), 0, 0, 0, m_width, m_height, 0, 0, window_width,
                           window_height, GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

image_rgba8 read_default_framebuffer(int width, int height) {
    std::vector<std::uint8_t> bottom_up(std::size_t(width) * std::size_t(height) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
    return image_from_bottom_up(width, height, bottom_up);
}

void draw_image_to_default(const image_rgba8& image, int window_width, int window_height) {
    const GLsizei w = GLsizei(image.width), h = GLsizei(image.height);
    const gl_texture texture = make_texture(GL_TEXTURE_2D);
    glTextureStorage2D(texture.id(), 1, GL_RGBA8, w, h);
    // Rows bottom-up, as GL counts them.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (GLsizei y = 0; y < h; ++y)
        glTextureSubImage2D(texture.id(), 0, 0, h - 1 - y, w, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                            image.texels.data() + std::size_t(y) * std::size_t(w) * 4);
    const gl_framebuffer source = make_framebuffer();
    glNamedFramebufferTexture(source.id(), GL_COLOR_ATTACHMENT0, texture.id(), 0);
    glBlitNamedFramebuffer(source.id(), 0, 0, 0, w, h, 0, 0, window_width, window_height, GL_COLOR_BUFFER_BIT,
                           GL_LINEAR);
}

}  // namespace sylva::render
