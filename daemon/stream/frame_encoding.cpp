#include "stream/frame_encoding.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/color.h"
#include "core/cube_map_lookup.h"
#include "frames/published_lights.h"
#include "proto/stream_protocol.h"
#include "proto/texel_packing.h"
#include "util/contract.h"

namespace vem::stream {
namespace {

constexpr double kReinhardKey = 0.18;      // as preview_image.cpp
constexpr double kLogAverageDelta = 1e-6;  // as preview_image.cpp
constexpr int kMaxPreviewWidthPx = 1024;

void addVec3(google::protobuf::RepeatedField<float>& out, glm::vec3 v) {
  out.Add(v.x);
  out.Add(v.y);
  out.Add(v.z);
}

void fillClusters(Clusters& out, const Clustering& clustering) {
  out.set_radius_rad(clustering.radiusRad);
  const std::vector<Light>& clusters = clustering.clusters.lights;
  out.mutable_dirs()->Reserve(int(3 * clusters.size()));
  out.mutable_rgb()->Reserve(int(3 * clusters.size()));
  for (const Light& cluster : clusters) {
    addVec3(*out.mutable_dirs(), cluster.dir);
    addVec3(*out.mutable_rgb(), cluster.rgb);
  }
  out.mutable_member_of()->Add(clustering.clusterOfLight.begin(), clustering.clusterOfLight.end());
}

float cleanChannel(float c) { return std::isfinite(c) && c > 0.0F ? c : 0.0F; }

std::uint8_t srgbByte(double linear) {
  const double c = std::clamp(linear, 0.0, 1.0);
  const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return std::uint8_t(std::lround(255.0 * encoded));
}

// The preview's pixels, row-major, linear RGB with non-finite and negative channels as 0; pixels
// outside the disc hold kOutsideDisc.
constexpr glm::vec3 kOutsideDisc{-1.0F};

std::vector<glm::vec3> sampleDisc(const EnvMap& polar, int widthPx) {
  const std::size_t width = std::size_t(widthPx);
  std::vector<glm::vec3> disc(width * width, kOutsideDisc);
  const double thetaMax = thetaMaxRad(polar.layout);
  for (std::size_t py = 0; py < width; ++py) {
    for (std::size_t px = 0; px < width; ++px) {
      const double a = 2.0 * (double(px) + 0.5) / double(width) - 1.0;
      const double b = 2.0 * (double(py) + 0.5) / double(width) - 1.0;
      const double r = std::hypot(a, b);
      if (r > 1.0) continue;
      const glm::vec3 v =
          sampleEnvMapBilinear(polar, directionFromAngles(r * thetaMax, std::atan2(b, a)));
      disc[py * width + px] = glm::vec3(cleanChannel(v.x), cleanChannel(v.y), cleanChannel(v.z));
    }
  }
  return disc;
}

// Reinhard's global operator over the disc's pixels (preview_image.h), then sRGB bytes.
void toneMapInto(const std::vector<glm::vec3>& disc, std::string& bytes) {
  double logSum = 0.0;
  std::size_t inside = 0;
  for (const glm::vec3 v : disc) {
    if (v.x < 0.0F) continue;
    logSum += std::log(kLogAverageDelta + luminance(v));
    ++inside;
  }
  const double exposure = kReinhardKey / (inside > 0 ? std::exp(logSum / double(inside)) : 1.0);
  bytes.assign(3 * disc.size(), '\0');
  for (std::size_t i = 0; i < disc.size(); ++i) {
    const double lw = disc[i].x < 0.0F ? 0.0 : luminance(disc[i]);
    if (lw <= 0.0) continue;
    const double l = exposure * lw;
    const double scale = l / (1.0 + l) / lw;
    for (int c = 0; c < 3; ++c)
      bytes[3 * i + std::size_t(c)] = char(srgbByte(scale * double(disc[i][c])));
  }
}

}  // namespace

ServerMessage lightFrameMessage(const ProcessedFrame& frame, const LightFrameStamp& stamp) {
  VEM_EXPECTS(frame.captured != nullptr);
  const PublishedLights published = publishedLights(frame);
  const std::vector<Light>& lights = published.lights->lights;
  ServerMessage message;
  LightFrame& out = *message.mutable_lights();
  out.set_seq(frame.captured->seq);
  out.set_lights_seq(published.lightsSeq);
  out.set_capture_ts_ns(frame.captured->captureTsNs);
  out.set_capture_unix_ns(stamp.captureUnixNs);
  out.set_publish_unix_ns(stamp.publishUnixNs);
  out.set_status(stamp.status);
  out.set_filtered(published.filtered);
  out.set_filter_delay_frames(stamp.filterDelayFrames);
  out.set_total_luminance_sr(published.lights->luminanceSr);
  out.set_black(published.lights->black);
  out.mutable_ids()->Reserve(int(lights.size()));
  out.mutable_dirs()->Reserve(int(3 * lights.size()));
  out.mutable_rgb()->Reserve(int(3 * lights.size()));
  for (const Light& light : lights) {
    out.add_ids(light.id);
    addVec3(*out.mutable_dirs(), light.dir);
    addVec3(*out.mutable_rgb(), light.rgb);
  }
  if (published.clustering != nullptr) {
    fillClusters(*out.mutable_clusters(), *published.clustering);
  }
  return message;
}

ServerMessage environmentFrameMessage(const CubeMap& cube, std::uint64_t seq,
                                      std::int64_t captureTsNs, std::int64_t publishUnixNs,
                                      int zstdLevel, std::size_t* clampedCount) {
  VEM_EXPECTS(!cube.levels.empty());
  std::size_t floats = 0;
  for (const CubeMapLevel& level : cube.levels) {
    for (const std::vector<float>& face : level.faces) floats += face.size();
  }
  std::vector<float> texels;
  texels.reserve(floats);
  for (const CubeMapLevel& level : cube.levels) {
    for (const std::vector<float>& face : level.faces) {
      VEM_EXPECTS(face.size() == 3 * std::size_t(level.facePx) * std::size_t(level.facePx));
      texels.insert(texels.end(), face.begin(), face.end());
    }
  }
  // The power of two that brings the brightest finite texel into the half range (exact division).
  float maxTexel = 0.0F;
  for (const float t : texels) {
    if (std::isfinite(t)) maxTexel = std::max(maxTexel, std::abs(t));
  }
  float scale = 1.0F;
  while (maxTexel / scale > kMaxHalf && scale < 0x1p100F) scale *= 2.0F;
  if (scale > 1.0F) {
    for (float& t : texels) t /= scale;
  }
  ServerMessage message;
  EnvironmentFrame& out = *message.mutable_environment();
  out.set_texel_scale(scale);
  out.set_seq(seq);
  out.set_capture_ts_ns(captureTsNs);
  out.set_publish_unix_ns(publishUnixNs);
  out.set_face_px(std::uint32_t(cube.levels.front().facePx));
  out.set_levels(std::uint32_t(cube.levels.size()));
  out.set_raw_bytes(std::uint64_t(texels.size()) * 2);
  out.set_texels_zstd(packTexels(texels, zstdLevel, clampedCount));
  return message;
}

void attachPolarPreview(ServerMessage& environment, const EnvMap& polar, int widthPx) {
  VEM_EXPECTS(environment.has_environment());
  VEM_EXPECTS(widthPx >= 1 && widthPx <= kMaxPreviewWidthPx);
  const std::vector<glm::vec3> disc = sampleDisc(polar, widthPx);
  PolarPreview& preview = *environment.mutable_environment()->mutable_preview();
  preview.set_width_px(std::uint32_t(widthPx));
  preview.set_height_px(std::uint32_t(widthPx));
  toneMapInto(disc, *preview.mutable_srgb8());
}

std::string serialize(ServerMessage message) {
  message.set_protocol_major(kProtocolMajor);
  message.set_protocol_minor(kProtocolMinor);
  return message.SerializeAsString();
}

std::int64_t unixNowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace vem::stream
