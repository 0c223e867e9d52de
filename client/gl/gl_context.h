// GlContext: an OpenGL 3.3+ core-profile context, current on the calling thread, either headless
// (EGL on Mesa's surfaceless platform, or a pbuffer on the default EGL display; no default
// framebuffer to show, render into framebuffer objects) or a GLFW window (GL 3.3 core profile,
// the default framebuffer is the window's back buffer).
//
// Input (windows only): Esc or the window's close button sets shouldClose(); the cursor's travel
// while the left mouse button is held is collected between pollEvents() calls for takeLeftDragPx().
//
// Conventions: sizes in pixels; one context per thread; every GL object of the renderer is created
// and destroyed while its context lives. Failures (no display, no EGL, no GL 3.3) are values: one
// sentence saying what is missing and what to do.
#pragma once

#include <expected>
#include <memory>
#include <string>

#include <glm/vec2.hpp>

struct GLFWwindow;

namespace vem::gl {

class GlContext {
 public:
  [[nodiscard]] static std::expected<std::unique_ptr<GlContext>, std::string> headless(
      int widthPx, int heightPx);
  [[nodiscard]] static std::expected<std::unique_ptr<GlContext>, std::string> window(
      int widthPx, int heightPx, const std::string& title);
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  [[nodiscard]] bool isWindow() const { return window_ != nullptr; }
  void makeCurrent();
  void swapBuffers();                         // no-op when headless
  [[nodiscard]] bool shouldClose() const;     // false when headless
  void pollEvents();                          // no-op when headless
  [[nodiscard]] glm::ivec2 framebufferSizePx() const;
  void setTitle(const std::string& title);    // no-op when headless
  // The cursor's travel with the left button held since the last call, in window pixels (x to the
  // right, y down); zero when headless.
  [[nodiscard]] glm::dvec2 takeLeftDragPx();

  [[nodiscard]] int glMajor() const { return glMajor_; }
  [[nodiscard]] int glMinor() const { return glMinor_; }
  [[nodiscard]] const std::string& rendererName() const { return renderer_; }  // GL_RENDERER
  [[nodiscard]] const std::string& versionString() const { return version_; }  // GL_VERSION
  // True for Mesa's CPU rasterisers (llvmpipe, softpipe, swrast).
  [[nodiscard]] bool softwareRenderer() const;
  // A label for timing tables: "llvmpipe (software)", or the GPU's renderer string.
  [[nodiscard]] std::string timingLabel() const;

 private:
  GlContext() = default;
  void installInputCallbacks();
  static void onMouseButton(GLFWwindow* window, int button, int action, int mods);
  static void onCursorPos(GLFWwindow* window, double x, double y);
  static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);
  [[nodiscard]] std::string readGlInfo();  // fills the version fields; empty or the error

  void* eglDisplay_ = nullptr;  // EGLDisplay
  void* eglContext_ = nullptr;  // EGLContext
  void* eglSurface_ = nullptr;  // EGLSurface (pbuffer fallback only)
  bool ownsEglDisplay_ = false;
  GLFWwindow* window_ = nullptr;
  glm::ivec2 headlessSizePx_{0, 0};
  bool leftDown_ = false;
  glm::dvec2 lastCursorPx_{0.0, 0.0};
  glm::dvec2 dragPx_{0.0, 0.0};  // collected by the callbacks, taken by takeLeftDragPx
  int glMajor_ = 0;
  int glMinor_ = 0;
  std::string renderer_;
  std::string version_;
};

}  // namespace vem::gl
