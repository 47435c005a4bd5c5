// Headless GL through Mesa's OSMesa (llvmpipe on machines without a GPU). Sylva renders into
// its own framebuffer objects; the OSMesa surface only has to exist.
// glad's header first: it blocks the system gl.h that osmesa.h would otherwise pull in.
#include "systems/render/gl.h"
// clang-format off
#include <GL/osmesa.h>
// clang-format on

#include <stdexcept>
#include <vector>

#include "systems/render/gl_context.h"

namespace sylva::render {
namespace {

class osmesa_context final : public gl_context {
public:
    explicit osmesa_context(const context_options& options) {
        const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                                  OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                  OSMESA_CONTEXT_MAJOR_VERSION, 4,
                                  OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
        m_context = OSMesaCreateContextAttribs(attributes, nullptr);
        if (!m_context)
            throw std::runtime_error("OSMesa: cannot create a GL 4.5 core context (is libosmesa6 "
                                     "installed and is the driver llvmpipe?)");
        m_width = options.width;
        m_height = options.height;
        m_surface.resize(std::size_t(m_width) * std::size_t(m_height));
        make_current();
        if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress)))
            throw std::runtime_error("OSMesa: glad could not load the GL 4.5 entry points");
        read_strings();
    }
    ~osmesa_context() override { OSMesaDestroyContext(m_context); }
    osmesa_context(const osmesa_context&) = delete;
    osmesa_context& operator=(const osmesa_context&) = delete;

    void make_current() override {
        if (!OSMesaMakeCurrent(m_context, m_surface.data(), GL_UNSIGNED_BYTE, m_width, m_height))
            throw std::runtime_error("OSMesa: OSMesaMakeCurrent failed");
    }
    void swap_buffers() override {}
    bool poll_events() override { return true; }
    const char* backend_name() const override { return "osmesa"; }

private:
    OSMesaContext m_context = nullptr;
    std::vector<std::uint32_t> m_surface;
};

}  // namespace

std::unique_ptr<gl_context> create_osmesa_context(const context_options& options) {
    return std::make_unique<osmesa_context>(options);
}

}  // namespace sylva::render
