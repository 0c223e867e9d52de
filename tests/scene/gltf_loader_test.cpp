// The glTF loader: one-triangle files with an embedded buffer, written here; node transforms,
// normals, materials and the refusals.
#include "client/scene/gltf_loader.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene_test_files.h"

namespace vem::scene {
namespace {

using test_files::firstHalf;
using test_files::GltfTriangle;
using test_files::OpenWatch;
using test_files::TempDir;
using ::testing::HasSubstr;

constexpr float kEps = 1e-5F;

void expectNear(glm::vec3 actual, glm::vec3 expected) {
  EXPECT_NEAR(actual.x, expected.x, kEps);
  EXPECT_NEAR(actual.y, expected.y, kEps);
  EXPECT_NEAR(actual.z, expected.z, kEps);
}

Scene loadOrFail(const GltfTriangle& triangle) {
  TempDir dir;
  auto loaded = loadGltf(dir.write("tri.gltf", triangle.json()));
  if (!loaded) {
    ADD_FAILURE() << loaded.error().message;
    return {};
  }
  EXPECT_EQ(firstContractViolation(loaded->scene), "");
  return std::move(loaded->scene);
}

std::string refusal(const GltfTriangle& triangle) {
  TempDir dir;
  const auto path = dir.write("tri.gltf", triangle.json());
  auto loaded = loadGltf(path);
  if (loaded) {
    ADD_FAILURE() << "the file was loaded, where a refusal was expected";
    return {};
  }
  EXPECT_EQ(loaded.error().error, SceneFileError::BadContents);
  EXPECT_THAT(loaded.error().message, HasSubstr(path.string()));
  return loaded.error().message;
}

TEST(GltfLoader, TriangleRoundTripsPositionsNormalsAndIndices) {
  const Scene scene = loadOrFail(GltfTriangle{});
  ASSERT_EQ(scene.meshes.size(), 1U);
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.positions.size(), 3U);
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  expectNear(mesh.positions[1], {1, 0, 0});
  expectNear(mesh.normals[2], {0, 0, 1});
}

TEST(GltfLoader, NodeTranslationMovesPositions) {
  GltfTriangle triangle;
  triangle.nodes = R"([{"mesh": 0, "translation": [2, 3, 4]}])";
  const Scene scene = loadOrFail(triangle);
  ASSERT_EQ(scene.meshes.size(), 1U);
  expectNear(scene.meshes[0].positions[0], {2, 3, 4});
  expectNear(scene.meshes[0].positions[2], {2, 4, 4});
  expectNear(scene.meshes[0].normals[0], {0, 0, 1});
}

TEST(GltfLoader, TrsRotationRotatesPositionsAndNormals) {
  GltfTriangle triangle;  // a quarter turn about +X: +Y goes to +Z, +Z to -Y
  const double h = std::sqrt(0.5);
  triangle.nodes = fmt::format(R"([{{"mesh": 0, "rotation": [{}, 0, 0, {}]}}])", h, h);
  const Scene scene = loadOrFail(triangle);
  ASSERT_EQ(scene.meshes.size(), 1U);
  expectNear(scene.meshes[0].positions[2], {0, 0, 1});
  expectNear(scene.meshes[0].normals[0], {0, -1, 0});
}

TEST(GltfLoader, ChildTransformsComposeWithTheirParents) {
  GltfTriangle triangle;
  const double h = std::sqrt(0.5);
  triangle.nodes = fmt::format(
      R"([{{"children": [1], "translation": [0, 5, 0]}}, {{"mesh": 0, "rotation": [{}, 0, 0, {}]}}])",
      h, h);
  const Scene scene = loadOrFail(triangle);
  ASSERT_EQ(scene.meshes.size(), 1U);
  expectNear(scene.meshes[0].positions[2], {0, 5, 1});  // rotated first, then translated
}

TEST(GltfLoader, MatrixScaleTransformsNormalsByTheInverseTranspose) {
  GltfTriangle triangle;  // normal (1, 1, 0) / sqrt 2, stretched twice along y
  triangle.positions = {{0, 0, 0}, {0, 0, 1}, {1, -1, 0}};
  const glm::vec3 n = glm::normalize(glm::vec3(1, 1, 0));
  triangle.normals = {n, n, n};
  triangle.nodes = R"([{"mesh": 0, "matrix": [1,0,0,0, 0,2,0,0, 0,0,1,0, 0,0,0,1]}])";
  const Scene scene = loadOrFail(triangle);
  ASSERT_EQ(scene.meshes.size(), 1U);
  expectNear(scene.meshes[0].positions[2], {1, -2, 0});
  expectNear(scene.meshes[0].normals[0], glm::normalize(glm::vec3(2, 1, 0)));
}

TEST(GltfLoader, MirroringTransformReversesWindingSoFrontsStayCounterClockwise) {
  GltfTriangle triangle;
  triangle.nodes = R"([{"mesh": 0, "scale": [-1, 1, 1]}])";
  const Scene scene = loadOrFail(triangle);
  ASSERT_EQ(scene.meshes.size(), 1U);
  const Mesh& mesh = scene.meshes[0];
  const glm::vec3 a = mesh.positions[mesh.indices[0]];
  const glm::vec3 geometric =
      glm::cross(mesh.positions[mesh.indices[1]] - a, mesh.positions[mesh.indices[2]] - a);
  EXPECT_GT(glm::dot(geometric, mesh.normals[0]), 0.0F);
}

TEST(GltfLoader, MissingNormalsAreComputedFromTheWinding) {
  GltfTriangle triangle;
  triangle.normals.clear();
  const Scene scene = loadOrFail(triangle);
  ASSERT_EQ(scene.meshes.size(), 1U);
  for (const glm::vec3& normal : scene.meshes[0].normals) {
    expectNear(normal, {0, 0, 1});
  }
}

TEST(GltfLoader, RoughDielectricIsLambertian) {
  const Scene scene = loadOrFail(GltfTriangle{});
  ASSERT_EQ(scene.materials.size(), 1U);
  EXPECT_EQ(scene.materials[0].lobe, Lobe::Lambertian);
  expectNear(scene.materials[0].diffuseAlbedo, {0.5F, 0.6F, 0.7F});
}

TEST(GltfLoader, SmoothDielectricIsGgxWithF0Of4Percent) {
  GltfTriangle triangle;
  triangle.roughness = 0.5;
  const Scene scene = loadOrFail(triangle);
  ASSERT_EQ(scene.materials.size(), 1U);
  EXPECT_EQ(scene.materials[0].lobe, Lobe::Ggx);
  EXPECT_FLOAT_EQ(scene.materials[0].roughness, 0.5F);
  expectNear(scene.materials[0].specularAlbedo, glm::vec3(0.04F));
  expectNear(scene.materials[0].diffuseAlbedo, {0.5F, 0.6F, 0.7F});
}

TEST(GltfLoader, MetalHasItsColourInTheSpecularLobeAndNoDiffuse) {
  GltfTriangle triangle;
  triangle.metallic = 1.0;
  const Scene scene = loadOrFail(triangle);
  ASSERT_EQ(scene.materials.size(), 1U);
  EXPECT_EQ(scene.materials[0].lobe, Lobe::Ggx);
  expectNear(scene.materials[0].specularAlbedo, {0.5F, 0.6F, 0.7F});
  expectNear(scene.materials[0].diffuseAlbedo, glm::vec3(0.0F));
}

TEST(GltfLoaderRefuses, AMissingFileAsNotFound) {
  TempDir dir;
  const auto path = dir.path() / "absent.gltf";
  const auto loaded = loadGltf(path);
  ASSERT_FALSE(loaded);
  EXPECT_EQ(loaded.error().error, SceneFileError::NotFound);
  EXPECT_THAT(loaded.error().message, HasSubstr(path.string()));
}

TEST(GltfLoaderRefuses, ATruncatedFile) {
  TempDir dir;
  const auto path = dir.write("cut.gltf", firstHalf(GltfTriangle{}.json()));
  const auto loaded = loadGltf(path);
  ASSERT_FALSE(loaded);
  EXPECT_EQ(loaded.error().error, SceneFileError::BadContents);
  EXPECT_THAT(loaded.error().message, HasSubstr(path.string()));
  EXPECT_THAT(loaded.error().message, HasSubstr("not a valid glTF 2.0 file"));
}

TEST(GltfLoaderRefuses, AnAccessorPastTheEndOfItsBuffer) {
  GltfTriangle triangle;
  triangle.positionCount = 30;
  EXPECT_THAT(refusal(triangle), HasSubstr("accessor 0 (30 elements of 12 bytes from byte 0) runs "
                                           "past the end of buffer view 0"));
}

// count * 12 bytes wraps around to 0 in 64 bits: a product-based check would let it through and
// allocate 2^62 positions.
TEST(GltfLoaderRefuses, AnAccessorCountWhoseByteSizeWrapsAround) {
  GltfTriangle triangle;
  triangle.positionCount = std::uint64_t{1} << 62U;
  EXPECT_THAT(refusal(triangle), HasSubstr("accessor 0 (4611686018427387904 elements of 12 bytes "
                                           "from byte 0) runs past the end of buffer view 0"));
}

TEST(GltfLoaderRefuses, AnAccessorCountOfTheLargestUnsigned64BitNumber) {
  GltfTriangle triangle;
  triangle.positionCount = ~std::uint64_t{0};
  EXPECT_THAT(refusal(triangle), HasSubstr("accessor 0 (18446744073709551615 elements of 12 bytes "
                                           "from byte 0) runs past the end of buffer view 0"));
}

TEST(GltfLoaderRefuses, AnIndexPastTheVertexCount) {
  GltfTriangle triangle;
  triangle.indices = {0, 1, 7};
  EXPECT_THAT(refusal(triangle), HasSubstr("index 2 is 7, but there are only 3 vertices"));
}

TEST(GltfLoaderRefuses, ANanPosition) {
  GltfTriangle triangle;
  triangle.positions[1].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THAT(refusal(triangle), HasSubstr("mesh 0 ('tri') primitive 0: position 1 is not finite"));
}

TEST(GltfLoaderRefuses, LinePrimitives) {
  GltfTriangle triangle;
  triangle.mode = 1;
  EXPECT_THAT(refusal(triangle), HasSubstr("mode 1 is not supported, where 4 (triangles)"));
}

TEST(GltfLoaderRefuses, APrimitiveWithoutPositions) {
  GltfTriangle triangle;
  std::string json = triangle.json();
  json.replace(json.find(R"("POSITION": 0, )"), 15, "");
  TempDir dir;
  const auto loaded = loadGltf(dir.write("nopos.gltf", json));
  ASSERT_FALSE(loaded);
  EXPECT_THAT(loaded.error().message, HasSubstr("has no POSITION attribute"));
}

// The scene's folder: tmp/scene/ holds the glTF file; tmp/outside.bin (the triangle's buffer, the
// right size) lies beside it.
struct OutsideBuffer {
  TempDir dir;
  GltfTriangle triangle;
  std::filesystem::path outside = dir.write("outside.bin", bytesOf(triangle.bufferBytes()));

  static std::string bytesOf(const std::vector<unsigned char>& bytes) {
    return {bytes.begin(), bytes.end()};
  }
  // The refusal of tmp/scene/tri.gltf with the buffer URI `uri`, checking that the outside file
  // was not opened.
  std::string refusalFor(const std::string& uri) {
    triangle.bufferUri = uri;
    const OpenWatch watch(outside);
    const auto path = dir.write("scene/tri.gltf", triangle.json());
    const auto loaded = loadGltf(path);
    EXPECT_FALSE(watch.opened());
    if (loaded) {
      ADD_FAILURE() << "the file was loaded, where a refusal was expected";
      return {};
    }
    EXPECT_EQ(loaded.error().error, SceneFileError::BadContents);
    EXPECT_THAT(loaded.error().message, HasSubstr(path.string() + ": "));
    return loaded.error().message;
  }
  std::string folder() const { return std::filesystem::canonical(dir.path() / "scene").string(); }
};

TEST(GltfLoaderRefuses, BufferUriOutsideTheSceneFolderWithoutOpeningIt) {
  OutsideBuffer scene;
  const std::string message = scene.refusalFor("../outside.bin");
  EXPECT_THAT(message,
              HasSubstr("URI '../outside.bin' lies outside the scene's folder " + scene.folder()));
}

TEST(GltfLoaderRefuses, PercentEncodedDotsLeavingTheFolderWithoutOpeningIt) {
  OutsideBuffer scene;
  EXPECT_THAT(scene.refusalFor("%2e%2e/outside.bin"),
              HasSubstr("URI '../outside.bin' lies outside the scene's folder"));
}

TEST(GltfLoaderRefuses, AnAbsoluteBufferUriWithoutOpeningIt) {
  OutsideBuffer scene;
  EXPECT_THAT(scene.refusalFor(scene.outside.string()),
              HasSubstr("URI '" + scene.outside.string() + "' lies outside"));
}

TEST(GltfLoaderRefuses, AFileUriWithoutOpeningIt) {
  OutsideBuffer scene;
  EXPECT_THAT(scene.refusalFor("file://" + scene.outside.string()),
              HasSubstr("URI 'file://" + scene.outside.string() + "' lies outside"));
}

TEST(GltfLoaderRefuses, BufferUriThroughALinkThatLeadsOutsideWithoutOpeningIt) {
  OutsideBuffer scene;
  scene.dir.link("scene/inside.bin", scene.outside);
  EXPECT_THAT(scene.refusalFor("inside.bin"),
              HasSubstr("URI 'inside.bin' lies outside the scene's folder"));
}

TEST(GltfLoaderRefuses, ImageUriOutsideTheSceneFolderWithoutOpeningIt) {
  TempDir dir;
  const auto outside = dir.write("outside.png", "not read");
  const OpenWatch watch(outside);
  GltfTriangle triangle;
  triangle.extra = R"("images": [{"uri": "../outside.png"}])";
  const auto loaded = loadGltf(dir.write("scene/tri.gltf", triangle.json()));
  ASSERT_FALSE(loaded);
  EXPECT_THAT(loaded.error().message, HasSubstr("URI '../outside.png' lies outside"));
  EXPECT_FALSE(watch.opened());
}

TEST(GltfLoader, BufferFileInTheSceneFolderLoads) {
  TempDir dir;
  GltfTriangle triangle;
  triangle.bufferUri = "data/tri.bin";
  dir.write("scene/data/tri.bin", OutsideBuffer::bytesOf(triangle.bufferBytes()));
  const auto loaded = loadGltf(dir.write("scene/tri.gltf", triangle.json()));
  ASSERT_TRUE(loaded) << loaded.error().message;
  EXPECT_EQ(triangleCount(loaded->scene), 1U);
}

TEST(GltfLoader, BufferUriOutsideTheFolderLoadsWhenAllowed) {
  OutsideBuffer scene;
  scene.triangle.bufferUri = "../outside.bin";
  OutsideFolderPolicy allowed;
  allowed.allowed = true;
  const auto loaded = loadGltf(scene.dir.write("scene/tri.gltf", scene.triangle.json()), allowed);
  ASSERT_TRUE(loaded) << loaded.error().message;
  EXPECT_EQ(triangleCount(loaded->scene), 1U);
}

// tinygltf reads a GLB's BIN chunk up to 8 bytes past the end when its length claims them.
TEST(GltfLoaderRefuses, AGlbBinChunkThatRunsPastTheEndOfTheFile) {
  TempDir dir;
  GltfTriangle triangle;
  triangle.bufferUri = GltfTriangle::kNoUri;
  const auto bin = triangle.bufferBytes();
  triangle.byteLength = static_cast<std::int64_t>(bin.size()) + 8;
  const auto path = dir.write("tri.glb", test_files::glb(triangle.json(), bin, 8));
  const auto loaded = loadGltf(path);
  ASSERT_FALSE(loaded);
  EXPECT_THAT(loaded.error().message, HasSubstr("its BIN chunk claims 88 bytes from byte "));
  EXPECT_THAT(loaded.error().message, HasSubstr("past the end of the file's"));
}

TEST(GltfLoader, GlbWithItsBufferInTheBinChunkLoads) {
  TempDir dir;
  GltfTriangle triangle;
  triangle.bufferUri = GltfTriangle::kNoUri;
  const auto loaded =
      loadGltf(dir.write("tri.glb", test_files::glb(triangle.json(), triangle.bufferBytes())));
  ASSERT_TRUE(loaded) << loaded.error().message;
  EXPECT_EQ(triangleCount(loaded->scene), 1U);
}

// tinygltf said only "Failed to decode 'uri'" and quoted the whole URI.
TEST(GltfLoaderRefuses, ABufferByteLengthLargerThanTheFileSayingSo) {
  GltfTriangle triangle;
  triangle.byteLength = 1'000'000'000'000'000;
  EXPECT_THAT(refusal(triangle), HasSubstr("buffer 0 has byteLength 1000000000000000, where the 80 "
                                           "bytes its data: URI holds were expected"));
}

TEST(GltfLoaderRefuses, ANodeListedTwiceAmongItsParentsChildren) {
  GltfTriangle triangle;
  triangle.nodes = R"([{"children": [1, 1]}, {"mesh": 0}])";
  EXPECT_THAT(refusal(triangle), HasSubstr("node 1 is listed twice among node 0's children"));
}

// glTF nodes form trees: shared children would let a small file draw a mesh 1000^k times.
TEST(GltfLoaderRefuses, ANodeThatIsTheChildOfTwoNodes) {
  GltfTriangle triangle;
  triangle.nodes = R"([{"children": [1, 2]}, {"children": [3]}, {"children": [3]}, {"mesh": 0}])";
  EXPECT_THAT(refusal(triangle), HasSubstr("node 3 is a child of node 1 and of node 2, where a "
                                           "tree (one parent) was expected"));
}

TEST(GltfLoaderRefuses, ARootThatIsAlsoAChild) {
  GltfTriangle triangle;
  triangle.nodes = R"([{"mesh": 0, "children": [1]}, {"children": [0]}])";
  EXPECT_THAT(refusal(triangle),
              HasSubstr("node 0 is a root of the scene and a child of node 1, where a tree"));
}

// The walk was recursive: a long chain of nodes overflowed the stack.
TEST(GltfLoader, AChainOf100000NodesLoads) {
  GltfTriangle triangle;
  constexpr int kNodes = 100000;
  std::string nodes = "[";
  for (int i = 0; i + 1 < kNodes; ++i) {
    nodes += fmt::format(R"({{"children": [{}]}},)", i + 1);
  }
  triangle.nodes = nodes + R"({"mesh": 0}])";
  const Scene scene = loadOrFail(triangle);
  EXPECT_EQ(triangleCount(scene), 1U);
}

TEST(GltfLoaderRefuses, NodesDrawingAMeshPastTheSceneLimits) {
  GltfTriangle triangle;
  triangle.nodes = R"([{"children": [1, 2, 3]}, {"mesh": 0}, {"mesh": 0}, {"mesh": 0}])";
  TempDir dir;
  const auto path = dir.write("tri.gltf", triangle.json());
  const auto loaded = loadGltf(path, {}, GltfLimits{100, 2});
  ASSERT_FALSE(loaded);
  EXPECT_THAT(loaded.error().message,
              HasSubstr("mesh 0 ('tri') primitive 0, drawn by node 3, adds 3 vertices and 1 "
                        "triangles to the 6 and 2 drawn before it, where a scene of at most 100 "
                        "vertices and 2 triangles was expected"));
  EXPECT_TRUE(loadGltf(path, {}, GltfLimits{100, 3}));
}

}  // namespace
}  // namespace vem::scene
