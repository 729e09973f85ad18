# Debian's libimgui.a has an OpenGL3 backend whose built-in loader fails under OSMesa.
# We compile the backend source the package ships, with glad as its loader, instead.
set(IMGUI_GL3_BACKEND_SOURCE
    /usr/share/doc/libimgui-dev/examples/backends/imgui_impl_opengl3.cpp)
if(NOT EXISTS ${IMGUI_GL3_BACKEND_SOURCE})
  message(FATAL_ERROR "${IMGUI_GL3_BACKEND_SOURCE} missing: install libimgui-dev")
endif()
add_library(imgui_gl3 STATIC ${CMAKE_SOURCE_DIR}/common/imgui_gl3_backend.cpp)
target_compile_definitions(imgui_gl3 PRIVATE IMGUI_IMPL_OPENGL_LOADER_CUSTOM
                           IMGUI_GL3_BACKEND_SOURCE="${IMGUI_GL3_BACKEND_SOURCE}")
target_include_directories(imgui_gl3 PRIVATE /usr/include/imgui/backends)
target_link_libraries(imgui_gl3 PUBLIC glad PkgConfig::IMGUI)
