#include "synth/map_sequences.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include <glm/geometric.hpp>

#include "core/color.h"
#include "util/contract.h"

namespace vem::synth {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

// The direction of the brightest pixel (luminance; NaN and negative read as 0).
glm::dvec3 brightestDirection(const EnvMap& map) {
  int bestX = 0;
  int bestY = 0;
  double best = -1.0;
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const double v = luminance(map.at(x, y));
      if (std::isfinite(v) && v > best) {
        best = v;
        bestX = x;
        bestY = y;
      }
    }
  }
  return pixelCentreDirection(map, bestX, bestY);
}

}  // namespace

glm::dmat3 turnAboutUp(double angleDeg) {
  // dir = (sin t cos p, cos t, sin t sin p): p -> p + a is x' = x cos a - z sin a,
  // z' = x sin a + z cos a (glm is column-major: columns are the images of X, Y, Z).
  const double c = std::cos(angleDeg * kDegToRad);
  const double s = std::sin(angleDeg * kDegToRad);
  return glm::dmat3(glm::dvec3(c, 0.0, s), glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(-s, 0.0, c));
}

EnvMap turnedMap(const EnvMap& map, double angleDeg) {
  // Pixel x of the turned map shows the source over [x - d, x + 1 - d] in columns, d the turn in
  // columns: 1 - f of source column x - k and f of column x - k - 1 (d = k + f).
  const double turns = angleDeg / 360.0;
  const double d = (turns - std::floor(turns)) * map.width;
  const int k = int(std::floor(d));
  const double f = d - k;
  EnvMap out = map;
  const auto wrap = [&](int x) { return ((x % map.width) + map.width) % map.width; };
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const glm::dvec3 a(map.at(wrap(x - k), y));
      const glm::dvec3 b(map.at(wrap(x - k - 1), y));
      out.set(x, y, glm::vec3((1.0 - f) * a + f * b));
    }
  }
  return out;
}

std::vector<SequenceFrame> noisySequence(const EnvMap& map, double sigma, int frames,
                                         std::uint64_t seed) {
  VEM_EXPECTS(sigma >= 0.0 && frames >= 1);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<SequenceFrame> out;
  out.reserve(std::size_t(frames));
  for (int k = 0; k < frames; ++k) {
    SequenceFrame frame{map, glm::dmat3(1.0)};
    for (float& v : frame.map.rgb) v = float(double(v) * std::max(0.0, 1.0 + sigma * normal(rng)));
    out.push_back(std::move(frame));
  }
  return out;
}

std::vector<SequenceFrame> turningSequence(const EnvMap& map, double degPerFrame, int frames) {
  VEM_EXPECTS(frames >= 1);
  std::vector<SequenceFrame> out;
  out.reserve(std::size_t(frames));
  for (int k = 0; k < frames; ++k) {
    out.push_back(
        {turnedMap(map, k * degPerFrame), k == 0 ? glm::dmat3(1.0) : turnAboutUp(degPerFrame)});
  }
  return out;
}

std::vector<SequenceFrame> switchOnSequence(const EnvMap& map, int frames) {
  VEM_EXPECTS(frames >= kSwitchOffFrames + kSwitchRampFrames + 1);
  const glm::dvec3 centre = brightestDirection(map);
  const double cosRadius = std::cos(kSwitchCapRadiusDeg * kDegToRad);
  std::vector<SequenceFrame> out;
  out.reserve(std::size_t(frames));
  for (int k = 0; k < frames; ++k) {
    const double scale = std::clamp(double(k - kSwitchOffFrames + 1) / kSwitchRampFrames, 0.0, 1.0);
    SequenceFrame frame{map, glm::dmat3(1.0)};
    for (int y = 0; y < map.height; ++y) {
      for (int x = 0; x < map.width; ++x) {
        if (glm::dot(pixelCentreDirection(map, x, y), centre) >= cosRadius)
          frame.map.set(x, y, glm::vec3(scale * glm::dvec3(map.at(x, y))));
      }
    }
    out.push_back(std::move(frame));
  }
  return out;
}

namespace {

// The solid-angle-weighted mean radiance over pixel (x, y), from n x n directions inside it.
glm::dvec3 pixelMean(const calib::RadianceFunction& radiance, MapLayout layout, int width,
                     int height, int x, int y, int n, double& minY, double& maxY) {
  glm::dvec3 sum(0.0);
  double weights = 0.0;
  minY = std::numeric_limits<double>::infinity();
  maxY = 0.0;
  for (int j = 0; j < n; ++j) {
    const double theta = thetaFromRowCoord(layout, height, y + (j + 0.5) / n);
    const double w = std::sin(theta);  // solid angle per unit theta and phi
    for (int i = 0; i < n; ++i) {
      const double phi = phiFromColumnCoord(layout, width, x + (i + 0.5) / n);
      const glm::dvec3 value = radiance(directionFromAngles(theta, phi));
      const double y709 = luminance(value);
      minY = std::min(minY, y709);
      maxY = std::max(maxY, y709);
      sum += w * value;
      weights += w;
    }
  }
  return weights > 0.0 ? sum / weights : glm::dvec3(0.0);
}

}  // namespace

std::vector<SequenceFrame> sceneSequence(const SyntheticScene& scene, MapLayout layout, int width,
                                         int height, double rateHz, int frames) {
  VEM_EXPECTS(width > 0 && height > 0 && rateHz > 0.0 && frames >= 1);
  std::vector<SequenceFrame> out;
  out.reserve(std::size_t(frames));
  for (int k = 0; k < frames; ++k) {
    const SceneState state = scene.at(k / rateHz);
    EnvMap map = EnvMap::filled(layout, width, height, glm::vec3(0.0F));
    // Coarse pass; a pixel with contrast inside it, and its 8 neighbours (an edge may cross a
    // neighbour between its samples), are refined.
    std::vector<char> refine(map.pixelCount(), 0);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        double minY = 0.0;
        double maxY = 0.0;
        map.set(x, y,
                glm::vec3(pixelMean(state.radiance, layout, width, height, x, y, kSceneSubsamples,
                                    minY, maxY)));
        if (!(maxY > kSceneRefineContrast * minY)) continue;
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dx = -1; dx <= 1; ++dx) {
            const int ny = y + dy;
            if (ny < 0 || ny >= height) continue;
            const int nx = ((x + dx) % width + width) % width;
            refine[std::size_t(ny) * std::size_t(width) + std::size_t(nx)] = 1;
          }
        }
      }
    }
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        if (!refine[std::size_t(y) * std::size_t(width) + std::size_t(x)]) continue;
        double minY = 0.0;
        double maxY = 0.0;
        map.set(x, y,
                glm::vec3(pixelMean(state.radiance, layout, width, height, x, y,
                                    kSceneRefinedSubsamples, minY, maxY)));
      }
    }
    out.push_back({std::move(map), glm::dmat3(1.0)});
  }
  return out;
}

}  // namespace vem::synth
