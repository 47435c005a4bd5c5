#include "systems/render/shader_library.h"

#include <stdexcept>

#include "scenarios/embedded_files.h"

namespace sylva::render {
namespace {

std::string_view embedded_shader(std::string_view path) {
    auto text = embedded_file("shaders/" + std::string(path));
    if (!text) throw std::runtime_error("shader not found in the binary: shaders/" + std::string(path));
    return *text;
}

// Replaces each `#include "x"` line with the text of shaders/x (one level is all we use).
std::string resolve_includes(std::string_view text, std::string_view path) {
    std::string out;
    std::size_t line_start = 0;
    int line_number = 1;
    while (line_start < text.size()) {
        std::size_t line_end = text.find('\n', line_start);
        if (line_end == std::string_view::npos) line_end = text.size();
        std::string_view line = text.substr(line_start, line_end - line_start);
        if (line.starts_with("#include")) {
            auto open = line.find('"');
            auto close = line.rfind('"');
            if (open == std::string_view::npos || close <= open)
                throw std::runtime_error("shaders/" + std::string(path) + ":" +
                                         std::to_string(line_number) + ": malformed #include");
            std::string_view included = line.substr(open + 1, close - open - 1);
            out += embedded_shader(included);
            out += "\n";
        } else {
            out += line;
            out += '\n';
        }
        line_start = line_end + 1;
        ++line_number;
    }
    return out;
}

GLuint compile(GLenum stage, const std::string& text, std::string_view path) {
    GLuint shader = glCreateShader(stage);
    const char* source = text.c_str();
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(length > 0 ? length : 1), '\0');
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        throw std::runtime_error("shaders/" + std::string(path) + ": compile error:\n" + log);
    }
    return shader;
}

std::string key_of(const program_source& source) {
    std::string key = source.vertex + "|" + source.geometry + "|" + source.fragment + "|" + source.compute;
    for (const auto& d : source.defines) key += "|" + d;
    return key;
}

}  // namespace

std::string shader_library::expand(std::string_view path, const std::vector<std::string>& defines) {
    std::string text = "#version 450 core\n";
    for (const auto& d : defines) text += "#define " + d + "\n";
    text += "#line 1\n";
    text += resolve_includes(embedded_shader(path), path);
    return text;
}

GLuint shader_library::program(const program_source& source) {
    const std::string key = key_of(source);
    if (auto it = m_programs.find(key); it != m_programs.end()) return it->second.id();

    gl_program program(glCreateProgram());
    const bool compute = !source.compute.empty();
    const std::string& first = compute ? source.compute : source.vertex;
    GLuint vs = compile(compute ? GL_COMPUTE_SHADER : GL_VERTEX_SHADER, expand(first, source.defines), first);
    glAttachShader(program.id(), vs);
    GLuint gs = 0;
    if (!source.geometry.empty()) {
        gs = compile(GL_GEOMETRY_SHADER, expand(source.geometry, source.defines), source.geometry);
        glAttachShader(program.id(), gs);
    }
    GLuint fs = 0;
    if (!source.fragment.empty()) {
        fs = compile(GL_FRAGMENT_SHADER, expand(source.fragment, source.defines), source.fragment);
        glAttachShader(program.id(), fs);
    }
    glLinkProgram(program.id());
    glDeleteShader(vs);
    if (gs) glDeleteShader(gs);
    if (fs) glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(length > 0 ? length : 1), '\0');
        glGetProgramInfoLog(program.id(), length, nullptr, log.data());
        throw std::runtime_error("program " + key + ": link error:\n" + log);
    }
    GLuint id = program.id();
    m_programs.emplace(key, std::move(program));
    return id;
}

}  // namespace sylva::render
