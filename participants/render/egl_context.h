// An OpenGL context with no window and no display: EGL on Mesa's surfaceless platform (software rendering with
// llvmpipe where there is no GPU; a GPU's EGL driver takes the same path). Recipe: ../shared/DEPENDENCY-NOTES.md.
// RAII: the context is current on the creating thread while the object lives; one per thread.
#pragma once

#include <memory>
#include <string>

namespace turf {

class EglContext {
 public:
  // Throws std::runtime_error naming the EGL step that failed (no EGL, no surfaceless platform, no config, ...).
  EglContext();
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  // "Mesa ... llvmpipe ..." (GL_RENDERER), for the start-up log.
  std::string Renderer() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace turf
