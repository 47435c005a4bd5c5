# Dear ImGui from libimgui-dev: the core is a static library that needs libstb (stb_truetype,
# stb_rect_pack); Debian ships the GLFW and OpenGL 3 backends only as source, so we compile
# those two files here.
pkg_check_modules(IMGUI REQUIRED IMPORTED_TARGET imgui)
find_library(STB_LIBRARY stb REQUIRED)
set(IMGUI_BACKENDS /usr/share/doc/libimgui-dev/examples/backends)
add_library(sylva_imgui STATIC ${IMGUI_BACKENDS}/imgui_impl_glfw.cpp
                               ${IMGUI_BACKENDS}/imgui_impl_opengl3.cpp)
target_include_directories(sylva_imgui SYSTEM PUBLIC /usr/include/imgui /usr/include/imgui/backends)
target_link_libraries(sylva_imgui PUBLIC PkgConfig::IMGUI ${STB_LIBRARY} glfw ${CMAKE_DL_LIBS})
# imgui 1.86's bundled GL loader (imgui_impl_opengl3_loader.h) lists 54 functions for a 53-slot
# table and writes one pointer past it (ASan and UBSan stop on it): the backend uses Sylva's glad
# loader instead, which every context has loaded before ImGui starts (systems/render/*_context.cpp).
target_compile_definitions(sylva_imgui PRIVATE IMGUI_IMPL_OPENGL_LOADER_CUSTOM)
target_compile_options(sylva_imgui PRIVATE -include glad/gl.h)
target_link_libraries(sylva_imgui PUBLIC sylva_glad)
