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
