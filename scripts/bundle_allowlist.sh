# What a bundle (scripts/bundle.sh) leaves to the machine it runs on: glibc, and the GL/EGL
# stack (glvnd's loaders and the driver behind them, never ours to ship). Sourced by
# bundle.sh and tests/bundle_test.sh; `allowed NAME` for a library's soname.
allowed() {
  case $1 in
    linux-vdso.so.*|ld-linux*.so.*|libc.so.*|libm.so.*|libdl.so.*|libpthread.so.*|librt.so.*|\
    libresolv.so.*|libutil.so.*) return 0 ;;
    libEGL.so.*|libGL.so.*|libGLX.so.*|libOpenGL.so.*|libGLESv2.so.*|libGLdispatch.so.*|\
    libEGL_*.so.*|libGLX_*.so.*|libnvidia-*.so.*|libglapi.so.*|libgbm.so.*) return 0 ;;
  esac
  return 1
}
