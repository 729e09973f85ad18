# A build flavour: the GL API the lessons are compiled against. gl45 (desktop GL 4.5 core, the
# default), gl41 (4.1 core: macOS) or gles30 (OpenGL ES 3.0: a browser's WebGL 2). Each has its
# own glad loader, ImGui backend and GL half of common/; one source for all, the differences
# asked of Caps at run time (common/gl/caps.hpp).
include(${CMAKE_CURRENT_LIST_DIR}/glad.cmake)
include(${CMAKE_CURRENT_LIST_DIR}/imgui_gl3_backend.cmake)

# shadows_flavour(FLAVOUR SUFFIX): glad${SUFFIX}, imgui_gl3${SUFFIX}, shadows_common${SUFFIX}
# and shadows_main${SUFFIX} for FLAVOUR.
function(shadows_flavour flavour suffix)
  string(TOUPPER ${flavour} upper)
  shadows_glad(${flavour} glad${suffix})

  add_library(imgui_gl3${suffix} STATIC ${CMAKE_SOURCE_DIR}/common/gl/imgui_gl3_backend.cpp)
  target_compile_definitions(imgui_gl3${suffix} PRIVATE IMGUI_IMPL_OPENGL_LOADER_CUSTOM
    SHADOWS_GL_${upper} IMGUI_GL3_BACKEND_SOURCE="${IMGUI_GL3_BACKEND_SOURCE}"
    $<$<STREQUAL:${flavour},gles30>:IMGUI_IMPL_OPENGL_ES3>)
  target_include_directories(imgui_gl3${suffix} PRIVATE ${IMGUI_BACKENDS_DIR}
                             ${CMAKE_SOURCE_DIR}/common)
  target_link_libraries(imgui_gl3${suffix} PUBLIC glad${suffix} PkgConfig::IMGUI)

  add_library(shadows_common${suffix} STATIC ${SHADOWS_GL_SOURCES})
  target_include_directories(shadows_common${suffix} SYSTEM PRIVATE ${IMGUI_BACKENDS_DIR})
  target_compile_definitions(shadows_common${suffix} PUBLIC SHADOWS_GL_${upper}
    SHADOWS_COMMON_SHADER_DIR="${CMAKE_SOURCE_DIR}/common/shaders"
    SHADOWS_HAVE_OSMESA=$<BOOL:${OSMESA_FOUND}> SHADOWS_HAVE_EGL=$<BOOL:${EGL_FOUND}>)
  target_compile_options(shadows_common${suffix} PRIVATE ${SHADOWS_WARNINGS})
  target_link_libraries(shadows_common${suffix} PUBLIC shadows_core glad${suffix}
    imgui_gl3${suffix} PkgConfig::GLFW)
  if(OSMESA_FOUND)
    # Its header only: libOSMesa (and the LLVM it links) is dlopen()ed when asked for
    # (common/gl/context.cpp), so a binary runs where only a GPU's GL is installed.
    target_include_directories(shadows_common${suffix} SYSTEM PRIVATE ${OSMESA_INCLUDE_DIRS})
    target_link_libraries(shadows_common${suffix} PUBLIC ${CMAKE_DL_LIBS})
  endif()
  if(EGL_FOUND)
    target_link_libraries(shadows_common${suffix} PUBLIC PkgConfig::EGL)
  endif()

  add_library(shadows_main${suffix} STATIC ${CMAKE_SOURCE_DIR}/common/run/main.cpp)
  target_link_libraries(shadows_main${suffix} PRIVATE shadows_common${suffix})
endfunction()
