#include "client/vemview/composite_frame_renderer.h"

#include <chrono>
#include <optional>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include "client/embree/embree_scene.h"
#include "client/embree/surface_classes.h"
#include "client/gl/overlay_pass.h"
#include "client/gl/picture_pass.h"
#include "client/render/image_files.h"
#include "client/render/layer_resampling.h"
#include "client/vemview/embree_frame_renderer.h"
#include "client/vemview/frame_writer.h"
#include "client/vemview/gl_frame_renderer.h"

namespace vem::view {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

// What the render without the objects depends on: the lights and the cube map (the camera and
// the local scene are fixed for the run).
struct WithoutKey {
  std::uint64_t inputSeq = 0;
  std::uint64_t cubeVersion = 0;
  std::size_t lightCount = 0;
  bool operator==(const WithoutKey&) const = default;
};

struct Layers {
  std::unique_ptr<ViewerOptions> options;  // the renderers borrow it: the render size
  std::unique_ptr<FrameRenderer> withObjects;
  std::unique_ptr<FrameRenderer> withoutObjects;  // null with no differential pass
  std::optional<embree::EmbreeScene> classesScene;
  std::vector<bool> objectMeshes;
  std::shared_ptr<gl::GlContext> context;  // the window's, or OpenGL layers' headless one
};

// The window of a composite: the picture and the overlay drawn by OpenGL into its back buffer.
struct CompositeWindow {
  gl::PicturePass picture;
  gl::OverlayPass overlay;
};

std::expected<std::unique_ptr<FrameRenderer>, std::string> layerRenderer(
    const ViewerOptions& options, const RenderPlan& plan, const scene::Scene& scene,
    const render::LightingGeometry& geometry, const std::shared_ptr<gl::GlContext>& context) {
  if (options.renderer == RendererKind::Gl) {
    return makeGlFrameRenderer(options, plan, scene, geometry, context);
  }
  return makeEmbreeFrameRenderer(options, plan, scene, geometry);
}

// The layer with the objects and the classes' scene, for `composition` (built again when the
// objects are dragged).
std::expected<void, std::string> buildWithObjects(Layers& layers, const RenderPlan& plan,
                                                  const scene::LocalComposition& composition,
                                                  const render::LightingGeometry& geometry) {
  auto with =
      layerRenderer(*layers.options, plan, composition.withObjects, geometry, layers.context);
  if (!with) return std::unexpected(with.error());
  auto classes = embree::EmbreeScene::build(composition.withObjects);
  if (!classes) return std::unexpected(classes.error());
  layers.withObjects = std::move(*with);
  layers.classesScene.emplace(std::move(*classes));
  layers.objectMeshes = composition.objectMeshes;
  return {};
}

class CompositeFrameRenderer final : public FrameRenderer {
 public:
  CompositeFrameRenderer(const RenderPlan& plan, Layers layers, std::unique_ptr<PlateSource> plate,
                         PlateView view, scene::LocalComposition composition,
                         const render::LightingGeometry& geometry,
                         std::optional<CompositeWindow> window, std::string screenshot)
      : differential_(plan.composite && plan.composite->differential),
        plan_(plan),
        layers_(std::move(layers)),
        plate_(std::move(plate)),
        view_(std::move(view)),
        composition_(std::move(composition)),
        geometry_(geometry),
        window_(std::move(window)),
        screenshot_(std::move(screenshot)) {}

  ~CompositeFrameRenderer() override {
    if (!screenshot_.empty() && !shown_.empty()) {
      (void)render::saveSrgbPng(shown_, shownSizePx_.x, shownSizePx_.y, screenshot_);
    }
    if (layers_.context) layers_.context->makeCurrent();  // the GL objects go with their context
  }
  CompositeFrameRenderer(const CompositeFrameRenderer&) = delete;
  CompositeFrameRenderer& operator=(const CompositeFrameRenderer&) = delete;

  // The composite on the screen, the overlay over it; --screenshot keeps what is shown, before the
  // overlay, at the plate's size.
  void present(const render::ToneParams& tone, const std::string& overlay) override {
    if (!window_ || shownImage_.widthPx == 0) return;
    gl::GlContext& context = *layers_.context;
    context.makeCurrent();
    shown_ = frameSrgb8(shownImage_, shownDisplayReferred_, tone);
    shownSizePx_ = {shownImage_.widthPx, shownImage_.heightPx};
    const glm::ivec2 targetPx = context.framebufferSizePx();
    window_->picture.draw(0, targetPx, shown_, shownSizePx_.x, shownSizePx_.y);
    window_->overlay.draw(0, targetPx, overlay);
    context.setTitle(overlay.substr(0, overlay.find('\n')));
    context.swapBuffers();
    context.pollEvents();
  }

  bool open() override { return !window_ || !layers_.context->shouldClose(); }

  std::string name() const override {
    return fmt::format("composite (differential rendering into the plate) by {}",
                       layers_.withObjects->name());
  }

  std::uint64_t pollOwnInput() override {
    if (window_) {
      if (auto moved = dragObjects(); !moved) spdlog::warn("{}", moved.error());
    }
    const auto start = std::chrono::steady_clock::now();
    std::optional<PlateFrame> picture = plate_->next();
    decodeMs_ = msSince(start);
    if (picture && (!last_ || picture->seq != last_->seq)) {
      last_ = std::move(picture);
      state_ = "new";
      pictureArrived_ = start;
    } else if (!picture) {
      state_ = plate_->ended() ? (plate_->live() ? "stopped: keeping the last picture"
                                                 : "ended: keeping the last picture")
                               : "no new picture: keeping the last";
    } else {
      state_ = "still";
    }
    // A new picture or objects moved: redraw.
    return ((last_ ? last_->seq : 0) << 20U) ^ moves_;
  }

  bool ownInputEnded() const override { return plate_->ended() && !plate_->live(); }

  std::optional<double> ownInputCaptureUnixSec() const override {
    if (!last_ || !last_->captureOnSystemClock) return std::nullopt;
    return last_->captureTimeSec;
  }

  RenderedFrame render(const scene::ViewCamera& /*camera*/, const render::ShadingLights& lights,
                       const InputFrame& input) override {
    const auto start = std::chrono::steady_clock::now();
    RenderedFrame frame;
    frame.timing["plate_decode_ms"] = decodeMs_;
    frame.timing["plate_seq"] = last_ ? last_->seq : 0;
    frame.timing["plate_state"] = state_;
    if (state_ != "new" && state_ != "still") frame.plateState = state_;
    frame.timing["plate_capture_s"] = last_ ? last_->captureTimeSec : 0.0;
    // The lights' age at the picture: both on the system clock (a live camera, vemd's stream).
    if (last_ && last_->captureOnSystemClock && input.captureUnixSec) {
      frame.lightAgeSec = last_->captureTimeSec - *input.captureUnixSec;
      frame.timing["light_age_s"] = *frame.lightAgeSec;
    }
    if (!last_) {
      frame.image = render::LinearImage::black(view_.plateWidthPx, view_.plateHeightPx);
      frame.renderMs = msSince(start);
      return frame;
    }
    render::DifferentialLayers rendered;
    auto step = std::chrono::steady_clock::now();
    RenderedFrame with = layers_.withObjects->render(view_.camera, lights, input);
    rendered.withObjects = std::move(with.image);
    frame.timing["with_objects_ms"] = msSince(step);
    for (const auto& [key, value] : with.timing.items()) frame.timing["with_" + key] = value;
    frame.strataShadowMaps = with.strataShadowMaps;
    step = std::chrono::steady_clock::now();
    rendered.classes =
        embree::surfaceClasses(*layers_.classesScene, layers_.objectMeshes, view_.camera,
                               view_.renderWidthPx, view_.renderHeightPx, 0);
    frame.timing["classes_ms"] = msSince(step);
    const WithoutKey key{input.seq, input.cubeVersion, lights.diffuse.lights.size()};
    const bool reused = differential_ && withoutKey_ == key;
    if (differential_ && !reused) {
      step = std::chrono::steady_clock::now();
      without_ = layers_.withoutObjects->render(view_.camera, lights, input).image;
      withoutKey_ = key;
      frame.timing["without_objects_ms"] = msSince(step);
    }
    frame.timing["without_reused"] = reused;
    if (differential_) rendered.withoutObjects = without_;
    step = std::chrono::steady_clock::now();
    const render::DifferentialLayers layers = resampledLayers(
        rendered, last_->linear.widthPx, last_->linear.heightPx, view_.renderPxOfPlatePx);
    frame.timing["resample_ms"] = msSince(step);
    step = std::chrono::steady_clock::now();
    render::PlateColour colour = view_.colour;
    colour.saturation = last_->displayReferred ? 1.0F : 0.0F;  // 8-bit plates clip at white
    render::CompositeStats stats;
    if (differential_) {
      if (!reused || last_->seq != albedoPlateSeq_) {
        albedo_.update(last_->linear, layers.withoutObjects, colour);
        albedoPlateSeq_ = last_->seq;
      }
      frame.image = render::compositeDifferential(last_->linear, layers, albedo_, colour, &stats);
      frame.timing["albedo_frames"] = albedo_.frames();
      frame.timing["albedo_clamped_px"] = albedo_.clampedLastUpdate();
    } else {
      frame.image = render::compositePasted(last_->linear, layers, colour);
    }
    frame.timing["composite_ms"] = msSince(step);
    frame.timing["object_px"] = stats.objectPixels;
    frame.timing["local_px"] = stats.localPixels;
    if (stats.nonFinitePlatePixels > 0) {
      frame.timing["plate_non_finite_px"] = stats.nonFinitePlatePixels;
    }
    frame.displayReferred = last_->displayReferred;
    if (window_) {
      shownImage_ = frame.image;
      shownDisplayReferred_ = frame.displayReferred;
    }
    frame.renderMs = msSince(start);
    // From the picture's decode to its composite: the latency vemview adds to the plate.
    frame.timing["plate_to_composite_ms"] = msSince(pictureArrived_);
    return frame;
  }

 private:
  // A left-button drag in the window slides the objects on the floor: their floor point follows
  // the cursor (through the plate camera, onto y = 0). The layer with the objects is built again;
  // the one without them stays.
  std::expected<void, std::string> dragObjects() {
    const glm::dvec2 dragPx = layers_.context->takeLeftDragPx();
    if (dragPx == glm::dvec2(0.0) || !plan_.composite || !plan_.composite->objectBounds) {
      return {};
    }
    const glm::ivec2 targetPx = layers_.context->framebufferSizePx();
    const double shownScale = std::min(double(targetPx.x) / double(view_.plateWidthPx),
                                       double(targetPx.y) / double(view_.plateHeightPx));
    scene::Bounds& bounds = *plan_.composite->objectBounds;
    const std::optional<glm::vec3> found =
        floorMoveOfDrag(view_, bounds.centre(), glm::vec2(dragPx / shownScale));
    if (!found) return {};
    const glm::vec3 move = *found;
    for (std::size_t i = 0; i < composition_.withObjects.meshes.size(); ++i) {
      if (!composition_.objectMeshes[i]) continue;
      for (glm::vec3& p : composition_.withObjects.meshes[i].positions) p += move;
    }
    bounds.min += move;
    bounds.max += move;
    ++moves_;
    if (layers_.context) layers_.context->makeCurrent();
    return buildWithObjects(layers_, plan_, composition_, geometry_);
  }

  bool differential_;
  RenderPlan plan_;
  Layers layers_;
  std::unique_ptr<PlateSource> plate_;
  PlateView view_;
  std::optional<PlateFrame> last_;
  std::string state_ = "none";
  double decodeMs_ = 0.0;
  std::chrono::steady_clock::time_point pictureArrived_;
  std::optional<WithoutKey> withoutKey_;
  render::LinearImage without_;
  render::AlbedoEstimate albedo_;
  std::uint64_t albedoPlateSeq_ = 0;
  scene::LocalComposition composition_;  // in the light probe's world; the objects move with drags
  const render::LightingGeometry& geometry_;
  std::optional<CompositeWindow> window_;
  std::string screenshot_;
  std::uint64_t moves_ = 0;
  render::LinearImage shownImage_;
  bool shownDisplayReferred_ = false;
  std::vector<std::uint8_t> shown_;
  glm::ivec2 shownSizePx_{0, 0};
};

}  // namespace

std::expected<std::unique_ptr<FrameRenderer>, std::string> makeCompositeFrameRenderer(
    const ViewerOptions& options, const RenderPlan& plan,
    const scene::LocalComposition& composition, const render::LightingGeometry& geometry,
    std::unique_ptr<PlateSource> plate, PlateView view) {
  Layers layers;
  layers.options = std::make_unique<ViewerOptions>(options);
  layers.options->widthPx = view.renderWidthPx;
  layers.options->heightPx = view.renderHeightPx;
  layers.options->headless = true;
  std::optional<CompositeWindow> window;
  if (!options.headless) {
    // The window shows the plate's picture, at most 1280 px wide.
    const double scale = std::min(1.0, 1280.0 / double(view.plateWidthPx));
    auto made = gl::GlContext::window(int(double(view.plateWidthPx) * scale),
                                      int(double(view.plateHeightPx) * scale), "vemview");
    if (!made) return std::unexpected(made.error());
    layers.context = std::move(*made);
    auto picture = gl::PicturePass::create();
    if (!picture) return std::unexpected(picture.error());
    auto overlay = gl::OverlayPass::create();
    if (!overlay) return std::unexpected(overlay.error());
    window.emplace(CompositeWindow{std::move(*picture), std::move(*overlay)});
  } else if (options.renderer == RendererKind::Gl) {
    auto made = gl::GlContext::headless(view.renderWidthPx, view.renderHeightPx);
    if (!made) return std::unexpected(made.error());
    layers.context = std::move(*made);
  }
  if (auto built = buildWithObjects(layers, plan, composition, geometry); !built) {
    return std::unexpected(built.error());
  }
  if (plan.composite && plan.composite->differential) {
    auto without =
        layerRenderer(*layers.options, plan, composition.localOnly, geometry, layers.context);
    if (!without) return std::unexpected(without.error());
    layers.withoutObjects = std::move(*without);
  }
  return std::make_unique<CompositeFrameRenderer>(plan, std::move(layers), std::move(plate),
                                                  std::move(view), composition, geometry,
                                                  std::move(window), options.screenshot);
}

}  // namespace vem::view
