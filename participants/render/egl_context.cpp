#include "participants/render/egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>

#include <fmt/format.h>

#include <stdexcept>

namespace turf {

struct EglContext::Impl {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
};

namespace {

[[noreturn]] void Fail(const std::string& step) {
  throw std::runtime_error(fmt::format("EGL: {} failed (error {:#x}); offscreen", step, eglGetError()) +
                           " rendering needs libegl-mesa0 and libgl1-mesa-dri, or a GPU's EGL driver");
}

EGLDisplay SurfacelessDisplay() {
  auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (get_display == nullptr) Fail("eglGetProcAddress(eglGetPlatformDisplayEXT)");
  EGLDisplay display = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY) Fail("eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA)");
  return display;
}

}  // namespace

EglContext::EglContext() : impl_(std::make_unique<Impl>()) {
  impl_->display = SurfacelessDisplay();
  EGLint major = 0, minor = 0;
  if (eglInitialize(impl_->display, &major, &minor) != EGL_TRUE) Fail("eglInitialize");
  const EGLint attributes[] = {EGL_SURFACE_TYPE,
                               EGL_PBUFFER_BIT,
                               EGL_RENDERABLE_TYPE,
                               EGL_OPENGL_BIT,
                               EGL_RED_SIZE,
                               8,
                               EGL_GREEN_SIZE,
                               8,
                               EGL_BLUE_SIZE,
                               8,
                               EGL_DEPTH_SIZE,
                               24,
                               EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (eglChooseConfig(impl_->display, attributes, &config, 1, &count) != EGL_TRUE || count < 1) {
    eglTerminate(impl_->display);
    Fail("eglChooseConfig (8-bit RGB, 24-bit depth, OpenGL)");
  }
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
    eglTerminate(impl_->display);
    Fail("eglBindAPI(EGL_OPENGL_API)");
  }
  impl_->context = eglCreateContext(impl_->display, config, EGL_NO_CONTEXT, nullptr);
  if (impl_->context == EGL_NO_CONTEXT) {
    eglTerminate(impl_->display);
    Fail("eglCreateContext");
  }
  if (eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context) != EGL_TRUE) {
    eglDestroyContext(impl_->display, impl_->context);
    eglTerminate(impl_->display);
    Fail("eglMakeCurrent (surfaceless)");
  }
}

EglContext::~EglContext() {
  eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(impl_->display, impl_->context);
  eglTerminate(impl_->display);
}

std::string EglContext::Renderer() const {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(renderer != nullptr ? renderer : "?") + ", OpenGL " + (version != nullptr ? version : "?");
}

}  // namespace turf
