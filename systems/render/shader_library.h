#pragma once
// GLSL programs compiled from the sources embedded in the binary (shaders/). A source may say
// `#include "common.glsl"`; the include is resolved against shaders/. Programs are built on
// first use only, so passes no entity needs never cost a compile.
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "systems/render/gl_objects.h"

namespace sylva::render {

struct program_source {
    std::string vertex;    // path under shaders/, e.g. "plant.vert"
    std::string fragment;  // may be empty (depth-only programs)
    std::vector<std::string> defines;  // "MATERIAL_LEAF", "SH_TRANSFER", ...
    std::string geometry;  // optional geometry shader (GL 3.2), e.g. "line.geom"
    // A compute program (GL 4.3) instead: this stage alone, `vertex` and `fragment` empty.
    std::string compute;
};

class shader_library {
public:
    // Returns the program for this source combination, compiling it the first time; throws
    // std::runtime_error with the file name and the driver's log on a compile or link error.
    GLuint program(const program_source& source);
    std::size_t compiled_count() const { return m_programs.size(); }

    // The source text with #version, the defines and #includes expanded (for tests).
    static std::string expand(std::string_view path, const std::vector<std::string>& defines);

private:
    std::map<std::string, gl_program> m_programs;
};

}  // namespace sylva::render
