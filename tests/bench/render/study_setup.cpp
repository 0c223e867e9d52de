#include "bench/render/study_setup.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <numeric>

#include <fmt/format.h>

#include "client/scene/default_scene.h"
#include "core/default_pattern.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"
#include "mapio/map_file.h"

namespace vem::bench {
namespace {

constexpr int kCubeLevels = 8;
constexpr double kTopFraction = 1e-3;

MapCharacter describeDynamicRange(const SamplingTables& tables) {
  struct Pixel {
    double luminance;
    double solidAngleSr;
  };
  std::vector<Pixel> pixels;
  pixels.reserve(tables.pixelLuminance.size());
  for (int y = 0; y < tables.height; ++y) {
    for (int x = 0; x < tables.width; ++x) {
      pixels.push_back({double(tables.pixelLuminance[std::size_t(y * tables.width + x)]),
                        tables.pixelSolidAngleSr[std::size_t(y)]});
    }
  }
  std::ranges::sort(pixels, std::greater{}, &Pixel::luminance);
  const double totalSr =
      std::accumulate(pixels.begin(), pixels.end(), 0.0,
                      [](double s, const Pixel& p) { return s + p.solidAngleSr; });
  double topPower = 0.0;
  double topSr = 0.0;
  for (const Pixel& p : pixels) {
    if (topSr >= kTopFraction * totalSr) break;
    topPower += p.luminance * p.solidAngleSr;
    topSr += p.solidAngleSr;
  }
  const double mean = tables.luminanceSr / totalSr;
  return {mean > 0.0 ? pixels.front().luminance / mean : 0.0,
          tables.luminanceSr > 0.0 ? topPower / tables.luminanceSr : 0.0};
}

// FNV-1a over raw bytes.
class Fnv {
 public:
  void add(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      hash_ = (hash_ ^ p[i]) * 0x100000001B3ULL;
    }
  }
  template <class T>
  void addValue(const T& value) {
    add(&value, sizeof(T));
  }
  [[nodiscard]] std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xCBF29CE484222325ULL;
};

void addGeometry(Fnv& fnv, const scene::Scene& s) {
  for (const scene::Mesh& mesh : s.meshes) {
    fnv.add(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3));
    fnv.add(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3));
    fnv.add(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t));
    fnv.addValue(mesh.material);
  }
  for (const scene::Material& m : s.materials) {
    fnv.addValue(m.diffuseAlbedo);
    fnv.addValue(m.lobe);
    fnv.addValue(m.specularAlbedo);
    fnv.addValue(m.exponent);
    fnv.addValue(m.roughness);
  }
}

std::uint64_t sceneKey(const scene::Scene& s, const scene::OrbitCamera& camera) {
  Fnv fnv;
  addGeometry(fnv, s);
  for (const float v :
       {camera.targetWorld.x, camera.targetWorld.y, camera.targetWorld.z, camera.distance,
        camera.azimuthRad, camera.elevationRad, camera.verticalFovRad}) {
    fnv.addValue(v);
  }
  return fnv.value();
}

std::uint64_t sceneKey(const scene::Scene& s, const scene::ViewCamera& camera) {
  Fnv fnv;
  addGeometry(fnv, s);
  fnv.addValue(camera.viewFromWorld);
  for (const float v : {camera.tanHalfFovY, camera.fyOverFx, camera.principalNdc.x,
                        camera.principalNdc.y, camera.nearPlane, camera.farPlane}) {
    fnv.addValue(v);
  }
  return fnv.value() ^ 0x9E3779B97F4A7C15ULL;
}

std::string describeScene(const scene::Scene& s) {
  std::string materials;
  for (const scene::Material& m : s.materials) {
    materials +=
        fmt::format("{}{} ({})", materials.empty() ? "" : ", ", m.name, scene::lobeName(m.lobe));
  }
  return fmt::format("`{}`: {} meshes, {} triangles; materials {}", s.name, s.meshes.size(),
                     scene::triangleCount(s), materials);
}

}  // namespace

std::optional<std::string> knownDamage(const std::string& mapName) {
  if (mapName == "park" || mapName == "sunrise") {
    return "damaged map: its sun is blue only (red and green near 0, ../shared/data/README.md), so "
           "its lights there are pure blue; a hard case, not a reference for a bright source";
  }
  return std::nullopt;
}

MapCharacter characterOf(const EnvMap& map) {
  return describeDynamicRange(buildSamplingTables(map));
}

std::expected<StudyMap, std::string> loadStudyMap(const std::filesystem::path& path,
                                                  int cubeFacePx) {
  auto map = mapio::loadMap(path);
  if (!map) return std::unexpected(map.error().message);
  if (map->layout != MapLayout::Sphere) {
    return std::unexpected(
        fmt::format("{}: expected an equirectangular (2:1) HDRI", path.string()));
  }
  StudyMap out;
  out.name = path.stem().string();
  out.path = path;
  out.damage = knownDamage(out.name);
  const SamplingTables tables = buildSamplingTables(*map);
  out.character = describeDynamicRange(tables);
  out.lights =
      generateLights(tables, defaultSamplingPattern(map->layout).first(kStudyMaxLights),
                     SamplerKind::Havran);
  out.cube = cubeMapFromEnvMap(*map, cubeFacePx, kCubeLevels);
  out.map = std::move(*map);
  return out;
}

std::expected<StudyScene, std::string> studySceneOf(scene::Scene scene) {
  if (const std::string broken = scene::firstContractViolation(scene); !broken.empty()) {
    return std::unexpected(scene.name + ": " + broken);
  }
  StudyScene out;
  const scene::OrbitCamera camera = scene::viewingCamera(scene);
  out.camera = camera;
  out.key = sceneKey(scene, camera);
  out.description = describeScene(scene);
  out.scene = std::move(scene);
  return out;
}

std::expected<StudyScene, std::string> studySceneSeenBy(scene::Scene scene,
                                                         const scene::ViewCamera& camera) {
  if (const std::string broken = scene::firstContractViolation(scene); !broken.empty()) {
    return std::unexpected(scene.name + ": " + broken);
  }
  StudyScene out;
  out.camera = camera;
  out.key = sceneKey(scene, camera);
  out.description = describeScene(scene);
  out.scene = std::move(scene);
  return out;
}

std::expected<StudyScene, std::string> studyScene() {
  scene::DefaultScene built = scene::defaultScene();
  if (const std::string broken = scene::firstContractViolation(built.scene); !broken.empty()) {
    return std::unexpected("the default scene: " + broken);
  }
  StudyScene out;
  const scene::OrbitCamera camera = scene::viewingCamera(built.scene);
  out.camera = camera;
  out.key = sceneKey(built.scene, camera);
  out.description = describeScene(built.scene);
  for (const std::string& note : built.notes) out.description += fmt::format(" ({})", note);
  out.scene = std::move(built.scene);
  return out;
}

render::ShadingLights studyLights(const StudyMap& map, const StudyScene& scene,
                                  const render::LightingGeometry& geometry,
                                  render::LightingOptions options) {
  options.glossyPass = scene::anyGlossy(scene.scene);
  options.clusterLayout = map.map.layout;
  return render::buildShadingLights(map.lights, geometry, options);
}

}  // namespace vem::bench
