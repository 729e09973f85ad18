// Compiles Dear ImGui's OpenGL3 backend (shipped by libimgui-dev as source) against this
// flavour's glad loader, because the copy inside libimgui.a brings a loader that fails under
// OSMesa (and speaks desktop GL only).
#include "gl/gl_api.hpp"

#include IMGUI_GL3_BACKEND_SOURCE
