// The composite frame renderer (client/vemview/composite_frame_renderer.h) with an in-process
// plate source that behaves as a live camera does (OpenCV's V4L2 capture): pictures while it
// streams, then nothing, ended() once it stopped, live() throughout. There is no V4L2 device on
// this machine; the fake follows what CapturePlate reports for one.
#include "client/vemview/composite_frame_renderer.h"

#include <gtest/gtest.h>

#include "client/render/shading_lights.h"
#include "client/scene/local_scene.h"
#include "client/scene/mixed_reality_world.h"
#include "client/vemview/light_input.h"

namespace vem::view {
namespace {

class StoppingCamera final : public PlateSource {
 public:
  StoppingCamera(int pictures, int widthPx, int heightPx)
      : pictures_(pictures), widthPx_(widthPx), heightPx_(heightPx) {}
  std::string description() const override { return "live camera (fake)"; }
  bool live() const override { return true; }
  int widthPx() const override { return widthPx_; }
  int heightPx() const override { return heightPx_; }
  bool ended() const override { return sent_ >= pictures_; }
  std::optional<PlateFrame> next() override {
    if (ended()) return std::nullopt;  // the camera stopped: no picture, and it says so
    ++sent_;
    PlateFrame frame;
    frame.linear = render::LinearImage::black(widthPx_, heightPx_);
    for (float& v : frame.linear.rgb) v = 0.2F * float(sent_);
    std::ranges::fill(frame.linear.covered, std::uint8_t{1});
    frame.seq = std::uint64_t(sent_);
    frame.captureOnSystemClock = true;
    return frame;
  }

 private:
  int pictures_;
  int widthPx_;
  int heightPx_;
  int sent_ = 0;
};

// "A live source that stops: the window keeps the last frame and says so."
TEST(CompositeFrameRenderer, LiveCameraThatStopsKeepsItsLastPictureAndSaysSo) {
  const scene::MixedRealityWorld world = scene::mixedRealityWorld();
  const scene::LocalComposition composition =
      scene::composeWithLocal(world.objects, scene::floorOnly());
  auto input = openMapInput(std::string(VEM_SHARED_DATA_DIR) + "/hdri/sky.exr",
                            MapInputOptions{64, true, 32});
  ASSERT_TRUE(input.has_value()) << input.error();
  const std::optional<InputFrame> lights = (*input)->next(std::chrono::milliseconds(0));
  ASSERT_TRUE(lights.has_value());
  ViewerOptions options;
  options.headless = true;
  options.renderer = RendererKind::Embree;
  options.shading = ShadingKind::Ratio;
  PlanRequest request;
  request.lightCount = 16;
  request.shadingByRatio = true;
  request.inputLayout = MapLayout::Sphere;
  RenderPlan plan = planFor(composition.withObjects, request);
  plan.composite = compositePlanFor(world.objects, 0);
  const render::LightingGeometry geometry = render::makeLightingGeometry();
  render::LightingOptions lighting = plan.lighting;
  lighting.lightCount = 16;
  const render::ShadingLights shading =
      render::buildShadingLights(*lights->lights, geometry, lighting);
  auto renderer = makeCompositeFrameRenderer(options, plan, composition, geometry,
                                             std::make_unique<StoppingCamera>(2, 32, 24),
                                             simulatedPlateView(world, 32, 24));
  ASSERT_TRUE(renderer.has_value()) << renderer.error();
  FrameRenderer& r = **renderer;
  const std::uint64_t first = r.pollOwnInput();
  (void)r.render(scene::ViewCamera{}, shading, *lights);
  const std::uint64_t second = r.pollOwnInput();
  const RenderedFrame live = r.render(scene::ViewCamera{}, shading, *lights);
  EXPECT_NE(first, second);
  EXPECT_TRUE(live.plateState.empty());
  const std::uint64_t afterStop = r.pollOwnInput();
  const RenderedFrame stopped = r.render(scene::ViewCamera{}, shading, *lights);
  EXPECT_EQ(afterStop, second);     // no new picture: nothing to redraw
  EXPECT_FALSE(r.ownInputEnded());  // a live camera does not end the run
  EXPECT_EQ(stopped.plateState, "stopped: keeping the last picture");
  EXPECT_EQ(stopped.timing["plate_seq"].get<int>(), 2);  // the last picture, still composited
  EXPECT_EQ(stopped.image.widthPx, 32);
  EXPECT_EQ(stopped.image.rgb, live.image.rgb);
}

}  // namespace
}  // namespace vem::view
