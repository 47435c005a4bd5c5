# Dear ImGui from libimgui-dev: the core is a static library; Debian ships the GLFW and
# OpenGL 3 backends only as source, so we compile those two files here.
find_library(IMGUI_LIBRARY imgui REQUIRED)
set(IMGUI_BACKENDS /usr/share/doc/libimgui-dev/examples/backends)
add_library(sylva_imgui STATIC ${IMGUI_BACKENDS}/imgui_impl_glfw.cpp
                               ${IMGUI_BACKENDS}/imgui_impl_opengl3.cpp)
target_include_directories(sylva_imgui SYSTEM PUBLIC /usr/include/imgui /usr/include/imgui/backends)
target_link_libraries(sylva_imgui PUBLIC ${IMGUI_LIBRARY} glfw ${CMAKE_DL_LIBS})
