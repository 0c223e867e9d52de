#include "client/vemview/plate_view.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

namespace vem::view {
namespace {

constexpr float kNearM = 0.05F;
constexpr float kFarM = 200.0F;

// OpenCV's camera frame (+Y down, +Z forward) into OpenGL's view frame (+Y up, looking down -Z).
glm::mat4 viewFromWorldOf(const calib::PlatePose& pose) {
  const glm::dmat3 glFromCv(glm::dvec3(1, 0, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, -1));
  const glm::dmat3 rotation = glFromCv * pose.cameraFromWorld;
  glm::dmat4 view(rotation);
  view[3] = glm::dvec4(-(rotation * pose.positionWorldM), 1.0);
  return glm::mat4(view);
}

}  // namespace

std::optional<glm::vec3> floorMoveOfDrag(const PlateView& view, glm::vec3 centreWorld,
                                         glm::vec2 dragPlatePx) {
  const glm::vec3 floorPoint(centreWorld.x, 0.0F, centreWorld.z);
  const int w = view.renderWidthPx;
  const int h = view.renderHeightPx;
  const scene::ViewCamera::Projection at = view.camera.project(floorPoint, w, h);
  if (at.behindEye) return std::nullopt;
  const glm::vec2 toPx = at.pixel + dragPlatePx * glm::vec2(float(w) / float(view.plateWidthPx),
                                                            float(h) / float(view.plateHeightPx));
  const scene::Ray ray = view.camera.primaryRay(toPx.x, toPx.y, w, h);
  if (!(ray.dirWorld.y < -1e-4F)) return std::nullopt;
  const float t = -ray.originWorld.y / ray.dirWorld.y;
  return ray.originWorld + t * ray.dirWorld - floorPoint;
}

int renderHeightFor(int plateWidthPx, int plateHeightPx, int renderWidthPx) {
  return std::max(
      1, int(std::lround(double(renderWidthPx) * double(plateHeightPx) / double(plateWidthPx))));
}

std::expected<PlateView, std::string> plateViewOf(const calib::PlateCamera& camera,
                                                  const std::string& file, int plateWidthPx,
                                                  int plateHeightPx, int renderWidthPx) {
  const calib::PlateIntrinsics& k = camera.intrinsics;
  if (k.widthPx != plateWidthPx || k.heightPx != plateHeightPx) {
    return std::unexpected(fmt::format(
        "{}: intrinsics: calibrated for {} x {} px, but the plate is {} x {} px: is the file "
        "another camera's, or was the camera switched to another mode?",
        file, k.widthPx, k.heightPx, plateWidthPx, plateHeightPx));
  }
  if (!camera.pose) {
    return std::unexpected(fmt::format(
        "{}: pose: missing; expected the camera's pose on the floor board (vemcalib plate pose)",
        file));
  }
  PlateView view;
  view.plateWidthPx = plateWidthPx;
  view.plateHeightPx = plateHeightPx;
  view.renderWidthPx = renderWidthPx;
  view.renderHeightPx = renderHeightFor(plateWidthPx, plateHeightPx, renderWidthPx);
  const glm::mat4 turn =
      glm::rotate(glm::mat4(1.0F), float(-camera.probeYawRad), glm::vec3(0.0F, 1.0F, 0.0F));
  view.probeWorldFromPlateWorld = turn;
  // A point seen at p_plate is at turn * p_plate in the probe's world: the view undoes the turn.
  view.camera =
      scene::pinholeViewCamera(viewFromWorldOf(*camera.pose) * glm::inverse(turn), k.fxPx, k.fyPx,
                               k.cxPx, k.cyPx, k.widthPx, k.heightPx, kNearM, kFarM);
  const bool distorted = std::ranges::any_of(k.distortion, [](double d) { return d != 0.0; });
  if (distorted) {
    std::vector<glm::dvec2> plate;
    plate.reserve(std::size_t(plateWidthPx) * std::size_t(plateHeightPx));
    for (int y = 0; y < plateHeightPx; ++y) {
      for (int x = 0; x < plateWidthPx; ++x) plate.emplace_back(double(x), double(y));
    }
    const std::vector<glm::dvec2> ideal = calib::idealFromDistortedPx(k, plate);
    view.renderPxOfPlatePx.reserve(ideal.size());
    const double sx = double(view.renderWidthPx) / double(plateWidthPx);
    const double sy = double(view.renderHeightPx) / double(plateHeightPx);
    for (const glm::dvec2& p : ideal) {
      view.renderPxOfPlatePx.emplace_back(float((p.x + 0.5) * sx), float((p.y + 0.5) * sy));
    }
  }
  if (camera.colour) {
    view.colour.gainRgb =
        glm::vec3(float(camera.colour->gainRgb[0]), float(camera.colour->gainRgb[1]),
                  float(camera.colour->gainRgb[2]));
  }
  view.description = fmt::format(
      "plate camera {} {} ({} x {} px, {}{}, probe yaw {:.2f} degrees{})", camera.camera.model,
      camera.camera.serial, k.widthPx, k.heightPx, calib::plateLensModelName(k.model),
      distorted ? "" : ", no distortion", camera.probeYawRad * 180.0 / 3.14159265358979,
      camera.colour ? ", colour matched" : ", no colour match: gain 1");
  return view;
}

PlateView simulatedPlateView(const scene::MixedRealityWorld& world, int renderWidthPx,
                             int renderHeightPx) {
  PlateView view;
  view.camera = scene::plateViewCamera(world);
  view.plateWidthPx = renderWidthPx;
  view.plateHeightPx = renderHeightPx;
  view.renderWidthPx = renderWidthPx;
  view.renderHeightPx = renderHeightPx;
  view.description = fmt::format(
      "the simulated world's plate camera ({} x {} px at {} x {}, no "
      "distortion, gain 1)",
      world.intrinsics.widthPx, world.intrinsics.heightPx, renderWidthPx, renderHeightPx);
  return view;
}

}  // namespace vem::view
