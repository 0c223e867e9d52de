// The headless EGL context: a desktop GL 3.3+ core context with no display at all.
#include <gtest/gtest.h>

#include <epoxy/gl.h>

#include "gl_test_support.h"

namespace vem::gl::test {
namespace {

TEST(GlContext, HeadlessContextCreatesWithoutADisplayAndReportsGl33OrNewer) {
  GlContext* context = headlessContext();
  ASSERT_NE(context, nullptr);
  EXPECT_GE(context->glMajor() * 10 + context->glMinor(), 33) << context->versionString();
  EXPECT_FALSE(context->rendererName().empty());
  EXPECT_FALSE(context->isWindow());
  EXPECT_EQ(context->framebufferSizePx(), glm::ivec2(64, 64));
  GLint profile = 0;
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_NE(profile & GL_CONTEXT_CORE_PROFILE_BIT, 0);
  if (context->rendererName().find("llvmpipe") != std::string::npos) {
    EXPECT_EQ(context->timingLabel(), "llvmpipe (software)");
  }
}

TEST(GlContext, WindowWithoutADisplaySaysSoInOneSentence) {
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((display != nullptr && *display != '\0') || (wayland != nullptr && *wayland != '\0')) {
    GTEST_SKIP() << "a display is set";
  }
  auto window = GlContext::window(64, 64, "test");
  ASSERT_FALSE(window.has_value());
  EXPECT_NE(window.error().find("no display: set DISPLAY or use --headless"), std::string::npos)
      << window.error();
  headlessContext()->makeCurrent();
}

}  // namespace
}  // namespace vem::gl::test
