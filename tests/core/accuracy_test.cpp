// Accuracy of the lights on the 18 shared HDRIs: irradiance at 64 well-spread normals from the
// lights against exact integration over the map (irradiance.h), for N = 64, 256, 1024 and both
// samplers. The full tables are in docs/BENCHMARKS.md (cmake --build build --target bench).
#include <cstdio>

#include <gtest/gtest.h>

#include "core/default_pattern.h"
#include "core/irradiance.h"
#include "core/light_generator.h"
#include "core/sphere_points.h"
#include "core/upper_hemisphere.h"
#include "mapio/map_file.h"
#include "support/test_maps.h"

namespace vem {
namespace {

constexpr std::size_t kCounts[] = {64, 256, 1024};

struct Errors {
  double havran[3];
  double standard[3];
};

Errors errorsOf(const EnvMap& map) {
  static const auto normals = fibonacciSphere(64);
  const SamplingTables tables = buildSamplingTables(map);
  const auto reference = irradianceFromMap(map, normals);
  Errors e{};
  for (int k = 0; k < 3; ++k) {
    const auto pattern = defaultSamplingPattern(map.layout).first(kCounts[k]);
    e.havran[k] = relativeRmsError(
        irradianceFromLights(generateLights(tables, pattern, SamplerKind::Havran).lights,
                             normals),
        reference);
    e.standard[k] = relativeRmsError(
        irradianceFromLights(generateLights(tables, pattern, SamplerKind::Standard).lights,
                             normals),
        reference);
  }
  return e;
}

class SharedHdriAccuracy : public ::testing::TestWithParam<MapLayout> {};

TEST_P(SharedHdriAccuracy, HavranErrorConvergesOnEveryMapAndStaysNearTheStandardSamplers) {
  const auto paths = testing::sharedHdriPaths();
  if (paths.empty()) GTEST_SKIP() << "no HDRIs under " << VEM_SHARED_DATA_DIR;
  double meanHavran[3] = {0, 0, 0}, meanStandard[3] = {0, 0, 0};
  std::printf("%-10s %s\n", "map",
              "Havran/standard relative RMS irradiance error, N = 64 256 1024");
  for (const auto& path : paths) {
    auto loaded = mapio::loadMap(path);
    ASSERT_TRUE(loaded) << loaded.error().message;
    const EnvMap map =
        GetParam() == MapLayout::Sphere ? *loaded : upperHemisphere(*loaded);
    const Errors e = errorsOf(map);
    std::printf("%-10s %.4f/%.4f %.4f/%.4f %.4f/%.4f\n", path.stem().c_str(), e.havran[0],
                e.standard[0], e.havran[1], e.standard[1], e.havran[2], e.standard[2]);
    // Converges on every map: at 1024 lights under 2 %, and at least halved from 64 lights.
    EXPECT_LT(e.havran[2], 0.02) << path;
    EXPECT_LT(e.havran[2], e.havran[0] / 2) << path;
    for (int k = 0; k < 3; ++k) {
      meanHavran[k] += e.havran[k] / double(paths.size());
      meanStandard[k] += e.standard[k] / double(paths.size());
    }
  }
  EXPECT_LT(meanHavran[2], meanHavran[0] / 4) << "mean error from 64 to 1024 lights";
  for (int k = 0; k < 3; ++k) {
    std::printf("mean N=%zu: Havran %.4f standard %.4f\n", kCounts[k], meanHavran[k],
                meanStandard[k]);
    // Measured: within 1.5 x of the standard sampler's mean at every N (better at N = 1024 on the
    // sphere). It is NOT at or below the standard's on every map: see docs/sampling.md.
    EXPECT_LT(meanHavran[k], 1.5 * meanStandard[k]) << "N=" << kCounts[k];
  }
}

INSTANTIATE_TEST_SUITE_P(Layouts, SharedHdriAccuracy,
                         ::testing::Values(MapLayout::Sphere, MapLayout::Hemisphere),
                         [](const auto& param) { return std::string(layoutName(param.param)); });

}  // namespace
}  // namespace vem
