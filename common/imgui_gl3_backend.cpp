// Compiles Dear ImGui's OpenGL3 backend (shipped by libimgui-dev as source) against glad,
// because the copy inside libimgui.a brings a loader that fails under OSMesa.
#include <glad/gl.h>

#include IMGUI_GL3_BACKEND_SOURCE
