#include "bench/render/reference_cache.h"

#include <chrono>
#include <fstream>

#include <fmt/format.h>

#include "client/render/image_files.h"

namespace vem::bench {
namespace {

std::uint64_t pixelHash(const EnvMap& map) {
  std::uint64_t hash = 0xCBF29CE484222325ULL;
  const auto* bytes = reinterpret_cast<const unsigned char*>(map.rgb.data());
  for (std::size_t i = 0; i < map.rgb.size() * sizeof(float); ++i) {
    hash = (hash ^ bytes[i]) * 0x100000001B3ULL;
  }
  return hash;
}

std::filesystem::path cacheStem(const StudyScene& scene, const StudyMap& map, int widthPx,
                                int heightPx, const embree::ReferenceOptions& options,
                                const std::filesystem::path& cacheDir) {
  return cacheDir / fmt::format("reference-{}-{:016x}-{}x{}-scene{:016x}-err{:.4f}-seed{:x}",
                                map.name, pixelHash(map.map), widthPx, heightPx, scene.key,
                                options.targetRelativeError, options.seed);
}

// The cached reference, unless it is missing, of another size, or stopped short of convergence
// by a smaller sample cap than `maxSamples`.
std::optional<StudyReference> loadCached(const std::filesystem::path& stem, int widthPx,
                                         int heightPx, int maxSamples) {
  std::ifstream facts(stem.string() + ".txt");
  StudyReference out;
  int converged = 0;
  if (!(facts >> out.samplesPerPixel >> out.relativeError >> converged >> out.renderSeconds)) {
    return std::nullopt;
  }
  if (converged == 0 && out.samplesPerPixel < maxSamples) return std::nullopt;
  auto image = render::loadLinearExr(stem.string() + ".exr");
  if (!image || image->widthPx != widthPx || image->heightPx != heightPx) return std::nullopt;
  out.image = std::move(*image);
  out.converged = converged != 0;
  out.fromCache = true;
  return out;
}

std::expected<void, std::string> store(const std::filesystem::path& stem,
                                       const StudyReference& reference) {
  std::error_code ignored;
  std::filesystem::create_directories(stem.parent_path(), ignored);
  if (auto saved = render::saveLinearExr(reference.image, stem.string() + ".exr"); !saved) {
    return saved;
  }
  std::ofstream facts(stem.string() + ".txt");
  facts << fmt::format("{} {:.17g} {} {:.3f}\n", reference.samplesPerPixel, reference.relativeError,
                       reference.converged ? 1 : 0, reference.renderSeconds);
  if (!facts) return std::unexpected(fmt::format("cannot write {}.txt", stem.string()));
  return {};
}

}  // namespace

void setCoverage(const embree::EmbreeScene& embreeScene, const scene::ViewCamera& camera,
                 render::LinearImage& image) {
  for (int y = 0; y < image.heightPx; ++y) {
    for (int x = 0; x < image.widthPx; ++x) {
      const scene::Ray ray =
          camera.primaryRay(float(x) + 0.5F, float(y) + 0.5F, image.widthPx, image.heightPx);
      image.covered[std::size_t(y * image.widthPx + x)] =
          embreeScene.intersect(ray).has_value() ? 1 : 0;
    }
  }
}

std::expected<StudyReference, std::string> cachedReference(const embree::EmbreeScene& embreeScene,
                                                           const StudyScene& scene,
                                                           const StudyMap& map, int widthPx,
                                                           int heightPx,
                                                           const embree::ReferenceOptions& options,
                                                           const std::filesystem::path& cacheDir) {
  const std::filesystem::path stem = cacheStem(scene, map, widthPx, heightPx, options, cacheDir);
  if (std::optional<StudyReference> cached =
          loadCached(stem, widthPx, heightPx, options.maxSamples)) {
    setCoverage(embreeScene, scene.camera, cached->image);
    return std::move(*cached);
  }
  const auto start = std::chrono::steady_clock::now();
  embree::ReferenceResult result =
      embree::renderReference(embreeScene, scene.camera, widthPx, heightPx, map.map, options);
  StudyReference out{
      std::move(result.image),
      result.samplesPerPixel,
      result.relativeError,
      result.converged,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
      false};
  if (auto stored = store(stem, out); !stored) return std::unexpected(stored.error());
  return out;
}

}  // namespace vem::bench
