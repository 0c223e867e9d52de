// The Embree half of study_renderer.h.
#include <algorithm>
#include <chrono>

#include "bench/render/study_renderer.h"
#include "client/embree/light_renderer.h"

namespace vem::bench {
namespace {

class EmbreeStudyRenderer final : public StudyRenderer {
 public:
  EmbreeStudyRenderer(const embree::EmbreeScene& embreeScene, const StudyScene& scene,
                      const render::LightingGeometry& geometry, StudyImageSize size, int frames,
                      bool softShadows)
      : embreeScene_(embreeScene),
        scene_(scene),
        geometry_(geometry),
        size_(size),
        frames_(std::max(frames, 1)),
        softShadows_(softShadows) {}

  std::expected<TimedFrame, std::string> render(
      const StudyConfig& /*config*/, const StudyMap& map, const render::ShadingLights& lights,
      const render::EnvironmentLighting* environment) override {
    TimedFrame out;
    embree::LightRenderOptions options;
    options.environment = environment;
    options.softShadows = softShadows_;
    for (int frame = 0; frame < frames_; ++frame) {
      const auto start = std::chrono::steady_clock::now();
      out.image = embree::renderWithLights(embreeScene_, scene_.camera, size_.widthPx,
                                           size_.heightPx, lights, geometry_, &map.cube, options);
      out.framesMs.push_back(
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
              .count());
    }
    out.medianMs = medianOf(out.framesMs);
    return out;
  }

 private:
  const embree::EmbreeScene& embreeScene_;
  const StudyScene& scene_;
  const render::LightingGeometry& geometry_;
  StudyImageSize size_;
  int frames_;
  bool softShadows_;
};

}  // namespace

double medianOf(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::ranges::sort(values);
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

std::unique_ptr<StudyRenderer> makeEmbreeStudyRenderer(const embree::EmbreeScene& embreeScene,
                                                       const StudyScene& scene,
                                                       const render::LightingGeometry& geometry,
                                                       StudyImageSize size, int frames,
                                                       bool softShadows) {
  return std::make_unique<EmbreeStudyRenderer>(embreeScene, scene, geometry, size, frames,
                                               softShadows);
}

}  // namespace vem::bench
