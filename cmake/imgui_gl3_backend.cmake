# Debian's libimgui.a has an OpenGL3 backend whose built-in loader fails under OSMesa.
# We compile the backend source the package ships, with glad as its loader, instead: once per
# flavour (shadows_flavour), against that flavour's loader.
# Elsewhere (macOS) point both at an ImGui checkout's backends/.
set(IMGUI_GL3_BACKEND_SOURCE
    /usr/share/doc/libimgui-dev/examples/backends/imgui_impl_opengl3.cpp
    CACHE FILEPATH "Dear ImGui's imgui_impl_opengl3.cpp")
set(IMGUI_BACKENDS_DIR /usr/include/imgui/backends CACHE PATH "Dear ImGui's backend headers")
if(NOT EXISTS ${IMGUI_GL3_BACKEND_SOURCE})
  message(FATAL_ERROR "${IMGUI_GL3_BACKEND_SOURCE} missing: install libimgui-dev")
endif()
