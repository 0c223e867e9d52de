#include "client/gl/gl_context.h"

#include <array>
#include <string_view>
#include <utility>

#include <epoxy/egl.h>
#include <epoxy/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace vem::gl {
namespace {

constexpr int kMinMajor = 3;
constexpr int kMinMinor = 3;

std::string& glfwLastError() {
  static std::string message;
  return message;
}

void onGlfwError(int /*code*/, const char* description) { glfwLastError() = description; }

std::string eglErrorName(EGLint code) {
  switch (code) {
    case EGL_NOT_INITIALIZED: return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ALLOC: return "EGL_BAD_ALLOC";
    case EGL_BAD_CONFIG: return "EGL_BAD_CONFIG";
    case EGL_BAD_MATCH: return "EGL_BAD_MATCH";
    case EGL_BAD_ATTRIBUTE: return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_DISPLAY: return "EGL_BAD_DISPLAY";
    default: return "EGL error " + std::to_string(code);
  }
}

// The surfaceless platform (Mesa) when the client extensions offer it, else the default display.
EGLDisplay openEglDisplay(bool& surfaceless) {
  surfaceless = false;
  if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless") &&
      epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_base")) {
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr) == EGL_TRUE) {
      surfaceless = true;
      return display;
    }
  }
  EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr) == EGL_TRUE) {
    return display;
  }
  return EGL_NO_DISPLAY;
}

}  // namespace

std::expected<std::unique_ptr<GlContext>, std::string> GlContext::headless(int widthPx,
                                                                          int heightPx) {
  std::unique_ptr<GlContext> context(new GlContext());
  context->headlessSizePx_ = {widthPx, heightPx};
  bool surfaceless = false;
  EGLDisplay display = openEglDisplay(surfaceless);
  if (display == EGL_NO_DISPLAY) {
    return std::unexpected("no EGL display: neither Mesa's surfaceless platform nor the default "
                           "display initialised (install Mesa's EGL, libegl-mesa0)");
  }
  context->eglDisplay_ = display;
  context->ownsEglDisplay_ = true;
  const std::array<EGLint, 13> configAttribs = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                                EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                                EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8,
                                                EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configCount = 0;
  if (eglChooseConfig(display, configAttribs.data(), &config, 1, &configCount) != EGL_TRUE ||
      configCount < 1) {
    return std::unexpected("no EGL config for desktop OpenGL with a pbuffer (" +
                           eglErrorName(eglGetError()) + ")");
  }
  if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
    return std::unexpected(std::string("EGL cannot bind the desktop OpenGL API"));
  }
  const std::array<EGLint, 7> contextAttribs = {
      EGL_CONTEXT_MAJOR_VERSION, kMinMajor, EGL_CONTEXT_MINOR_VERSION, kMinMinor,
      EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EGLContext eglContext = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttribs.data());
  if (eglContext == EGL_NO_CONTEXT) {
    return std::unexpected("no OpenGL 3.3 core context from EGL (" +
                           eglErrorName(eglGetError()) + ")");
  }
  context->eglContext_ = eglContext;
  if (!surfaceless || !epoxy_has_egl_extension(display, "EGL_KHR_surfaceless_context")) {
    const std::array<EGLint, 5> pbufferAttribs = {EGL_WIDTH, widthPx, EGL_HEIGHT, heightPx,
                                                  EGL_NONE};
    EGLSurface surface = eglCreatePbufferSurface(display, config, pbufferAttribs.data());
    if (surface == EGL_NO_SURFACE) {
      return std::unexpected("no EGL pbuffer of " + std::to_string(widthPx) + "x" +
                             std::to_string(heightPx) + " (" + eglErrorName(eglGetError()) + ")");
    }
    context->eglSurface_ = surface;
  }
  context->makeCurrent();
  if (std::string error = context->readGlInfo(); !error.empty()) return std::unexpected(error);
  return context;
}

std::expected<std::unique_ptr<GlContext>, std::string> GlContext::window(
    int widthPx, int heightPx, const std::string& title) {
  glfwSetErrorCallback(onGlfwError);
  if (glfwInit() != GLFW_TRUE) {
    return std::unexpected("no display: set DISPLAY or use --headless (GLFW: " + glfwLastError() +
                           ")");
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, kMinMajor);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, kMinMinor);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  GLFWwindow* window = glfwCreateWindow(widthPx, heightPx, title.c_str(), nullptr, nullptr);
  if (window == nullptr) {
    glfwTerminate();
    return std::unexpected("no OpenGL 3.3 core window of " + std::to_string(widthPx) + "x" +
                           std::to_string(heightPx) + " (GLFW: " + glfwLastError() + ")");
  }
  std::unique_ptr<GlContext> context(new GlContext());
  context->window_ = window;
  context->installInputCallbacks();
  context->makeCurrent();
  glfwSwapInterval(0);
  if (std::string error = context->readGlInfo(); !error.empty()) return std::unexpected(error);
  return context;
}

GlContext::~GlContext() {
  if (window_ != nullptr) {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  if (eglDisplay_ != nullptr) {
    eglMakeCurrent(eglDisplay_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (eglSurface_ != nullptr) eglDestroySurface(eglDisplay_, eglSurface_);
    if (eglContext_ != nullptr) eglDestroyContext(eglDisplay_, eglContext_);
    if (ownsEglDisplay_) eglTerminate(eglDisplay_);
  }
}

void GlContext::makeCurrent() {
  if (window_ != nullptr) {
    glfwMakeContextCurrent(window_);
    return;
  }
  EGLSurface surface = eglSurface_ != nullptr ? eglSurface_ : EGL_NO_SURFACE;
  eglMakeCurrent(eglDisplay_, surface, surface, eglContext_);
}

void GlContext::swapBuffers() {
  if (window_ != nullptr) glfwSwapBuffers(window_);
}

bool GlContext::shouldClose() const {
  return window_ != nullptr && glfwWindowShouldClose(window_) == GLFW_TRUE;
}

void GlContext::pollEvents() {
  if (window_ != nullptr) glfwPollEvents();
}

void GlContext::setTitle(const std::string& title) {
  if (window_ != nullptr) glfwSetWindowTitle(window_, title.c_str());
}

glm::dvec2 GlContext::takeLeftDragPx() { return std::exchange(dragPx_, glm::dvec2(0.0)); }

void GlContext::installInputCallbacks() {
  glfwSetWindowUserPointer(window_, this);
  glfwSetMouseButtonCallback(window_, &GlContext::onMouseButton);
  glfwSetCursorPosCallback(window_, &GlContext::onCursorPos);
  glfwSetKeyCallback(window_, &GlContext::onKey);
}

void GlContext::onMouseButton(GLFWwindow* window, int button, int action, int /*mods*/) {
  if (button != GLFW_MOUSE_BUTTON_LEFT) return;
  auto* self = static_cast<GlContext*>(glfwGetWindowUserPointer(window));
  self->leftDown_ = action == GLFW_PRESS;
  glfwGetCursorPos(window, &self->lastCursorPx_.x, &self->lastCursorPx_.y);
}

void GlContext::onCursorPos(GLFWwindow* window, double x, double y) {
  auto* self = static_cast<GlContext*>(glfwGetWindowUserPointer(window));
  const glm::dvec2 cursorPx{x, y};
  if (self->leftDown_) self->dragPx_ += cursorPx - self->lastCursorPx_;
  self->lastCursorPx_ = cursorPx;
}

void GlContext::onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
  if (key == GLFW_KEY_ESCAPE && action == GLFW_PRESS) glfwSetWindowShouldClose(window, GLFW_TRUE);
}

glm::ivec2 GlContext::framebufferSizePx() const {
  if (window_ == nullptr) return headlessSizePx_;
  glm::ivec2 size{0, 0};
  glfwGetFramebufferSize(window_, &size.x, &size.y);
  return size;
}

std::string GlContext::readGlInfo() {
  const auto* renderer = glGetString(GL_RENDERER);
  const auto* version = glGetString(GL_VERSION);
  if (renderer == nullptr || version == nullptr) {
    return "the OpenGL context is not current (glGetString failed)";
  }
  renderer_ = reinterpret_cast<const char*>(renderer);
  version_ = reinterpret_cast<const char*>(version);
  glGetIntegerv(GL_MAJOR_VERSION, &glMajor_);
  glGetIntegerv(GL_MINOR_VERSION, &glMinor_);
  if (glMajor_ < kMinMajor || (glMajor_ == kMinMajor && glMinor_ < kMinMinor)) {
    return "OpenGL " + version_ + " is too old: vemview needs 3.3 core";
  }
  return {};
}

bool GlContext::softwareRenderer() const {
  for (std::string_view name : {"llvmpipe", "softpipe", "swrast", "SWR"}) {
    if (renderer_.find(name) != std::string::npos) return true;
  }
  return false;
}

std::string GlContext::timingLabel() const {
  if (!softwareRenderer()) return renderer_;
  const std::size_t space = renderer_.find(' ');
  return renderer_.substr(0, space) + " (software)";
}

}  // namespace vem::gl
