// The OBJ loader: round trips of files written here, normals, MTL lobes, and its refusals.
#include "client/scene/obj_loader.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <cmath>
#include <filesystem>
#include <string>

#include <glm/glm.hpp>

#include "client/scene/default_scene.h"
#include "client/scene/obj_text_check.h"
#include "scene_test_files.h"

namespace vem::scene {
namespace {

using test_files::cubeObj;
using test_files::firstHalf;
using test_files::OpenWatch;
using test_files::TempDir;
using ::testing::HasSubstr;

constexpr float kEps = 1e-5F;

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = kEps) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

LoadedScene loadOrFail(const std::filesystem::path& path) {
  auto loaded = loadObj(path);
  if (!loaded) {
    ADD_FAILURE() << loaded.error().message;
    return {};
  }
  return std::move(*loaded);
}

SceneFileFailure refusal(const std::filesystem::path& path) {
  auto loaded = loadObj(path);
  if (loaded) {
    ADD_FAILURE() << path << " was loaded, where a refusal was expected";
    return {};
  }
  EXPECT_THAT(loaded.error().message, HasSubstr(path.string()));
  return loaded.error();
}

TEST(ObjLoader, CubeRoundTripKeepsPositionsAndTriangulatesQuads) {
  TempDir dir;
  const LoadedScene loaded = loadOrFail(dir.write("cube.obj", cubeObj(false)));
  ASSERT_EQ(loaded.scene.meshes.size(), 1U);
  const Mesh& mesh = loaded.scene.meshes[0];
  EXPECT_EQ(mesh.triangleCount(), 12U);
  EXPECT_EQ(mesh.positions.size(), 8U);  // deduplicated by position when there are no normals
  for (const glm::vec3& p : mesh.positions) {
    expectNear(glm::abs(p), glm::vec3(0.5F));
  }
  EXPECT_EQ(firstContractViolation(loaded.scene), "");
}

TEST(ObjLoader, ComputedCubeNormalsAreUnitAndPointOutward) {
  TempDir dir;
  const LoadedScene loaded = loadOrFail(dir.write("cube.obj", cubeObj(false)));
  ASSERT_EQ(loaded.scene.meshes.size(), 1U);
  const Mesh& mesh = loaded.scene.meshes[0];
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(mesh.normals[i]), 1.0F, kEps);
    // Near the diagonal through the corner (not on it: the quads' diagonals break the symmetry).
    EXPECT_GT(glm::dot(mesh.normals[i], glm::normalize(mesh.positions[i])), 0.9F);
  }
}

TEST(ObjLoader, FileNormalsSplitVerticesByPositionAndNormalIndex) {
  TempDir dir;
  const LoadedScene loaded = loadOrFail(dir.write("cube.obj", cubeObj(true)));
  ASSERT_EQ(loaded.scene.meshes.size(), 1U);
  const Mesh& mesh = loaded.scene.meshes[0];
  EXPECT_EQ(mesh.positions.size(), 24U);  // each corner once per face meeting there
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
    const glm::vec3 a = mesh.positions[mesh.indices[3 * t]];
    const glm::vec3 b = mesh.positions[mesh.indices[3 * t + 1]];
    const glm::vec3 c = mesh.positions[mesh.indices[3 * t + 2]];
    const glm::vec3 faceNormal = glm::normalize(glm::cross(b - a, c - a));
    for (std::size_t k = 0; k < 3; ++k) {
      expectNear(mesh.normals[mesh.indices[3 * t + k]], faceNormal);
    }
  }
}

TEST(ObjLoader, ComputedNormalsOfAFlatQuadAreItsPlaneNormal) {
  TempDir dir;
  const auto path = dir.write("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 1\nv 0 1 1\nf 1 2 3 4\n");
  const LoadedScene loaded = loadOrFail(path);
  ASSERT_EQ(loaded.scene.meshes.size(), 1U);
  for (const glm::vec3& n : loaded.scene.meshes[0].normals) {
    expectNear(n, glm::normalize(glm::vec3(0, -1, 1)));
  }
}

TEST(ObjLoader, ComputedNormalsAreAreaWeighted) {
  // Vertex 1 is shared by a large triangle facing +Z and a small one facing +X.
  TempDir dir;
  const auto path = dir.write("fan.obj",
                              "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 -0.1\nv 0 0.1 0\n"
                              "f 1 2 3\nf 1 4 5\n");
  const LoadedScene loaded = loadOrFail(path);
  ASSERT_EQ(loaded.scene.meshes.size(), 1U);
  const Mesh& mesh = loaded.scene.meshes[0];
  // Areas 2 and 0.005: the normal leans 0.0025 rad from +Z towards +X.
  expectNear(mesh.normals[mesh.indices[0]], glm::normalize(glm::vec3(0.0025F, 0, 1)), 1e-4F);
}

TEST(ObjLoader, MtlMaterialsBecomeLambertianBlinnAndGgxLobes) {
  TempDir dir;
  dir.write("paints.mtl",
            "newmtl matte\nKd 0.5 0.4 0.3\nKs 0 0 0\n"
            "newmtl shiny\nKd 0.2 0.2 0.2\nKs 0.3 0.3 0.3\nNs 50\n"
            "newmtl rough\nKd 0.6 0.6 0.6\nKs 0 0 0\nPr 0.4\n");
  const auto path = dir.write("three.obj",
                              "mtllib paints.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                              "o tri\nusemtl matte\nf 1 2 3\nusemtl shiny\nf 1 2 3\n"
                              "usemtl rough\nf 1 2 3\n");
  const LoadedScene loaded = loadOrFail(path);
  ASSERT_EQ(loaded.scene.meshes.size(), 3U);  // one per (shape, material) pair
  const auto materialOf = [&](std::size_t mesh) {
    return loaded.scene.materials.at(loaded.scene.meshes[mesh].material);
  };
  EXPECT_EQ(materialOf(0).lobe, Lobe::Lambertian);
  expectNear(materialOf(0).diffuseAlbedo, {0.5F, 0.4F, 0.3F});
  EXPECT_EQ(materialOf(1).lobe, Lobe::Blinn);
  EXPECT_FLOAT_EQ(materialOf(1).exponent, 50.0F);
  expectNear(materialOf(1).specularAlbedo, glm::vec3(0.3F));
  EXPECT_EQ(materialOf(2).lobe, Lobe::Ggx);
  EXPECT_FLOAT_EQ(materialOf(2).roughness, 0.4F);
  expectNear(materialOf(2).specularAlbedo, glm::vec3(0.04F));
}

// MTL has no Phong highlight of its own, so a Phong material could not come from a file at all.
TEST(ObjLoader, MtlVemLobePhongGivesThePhongLobe) {
  TempDir dir;
  dir.write("paints.mtl",
            "newmtl phong\nKd 0.2 0.2 0.2\nKs 0.3 0.3 0.3\nNs 80\nvem_lobe phong\n"
            "newmtl blinn\nKd 0.2 0.2 0.2\nKs 0.3 0.3 0.3\nNs 80\nvem_lobe blinn\n");
  const auto path = dir.write("two.obj",
                              "mtllib paints.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                              "o tri\nusemtl phong\nf 1 2 3\nusemtl blinn\nf 1 2 3\n");
  const LoadedScene loaded = loadOrFail(path);
  ASSERT_EQ(loaded.scene.meshes.size(), 2U);
  const Material& phong = loaded.scene.materials.at(loaded.scene.meshes[0].material);
  EXPECT_EQ(phong.lobe, Lobe::Phong);
  EXPECT_FLOAT_EQ(phong.exponent, 80.0F);
  expectNear(phong.specularAlbedo, glm::vec3(0.3F));
  EXPECT_EQ(loaded.scene.materials.at(loaded.scene.meshes[1].material).lobe, Lobe::Blinn);
}

TEST(ObjLoader, NoMtlGivesOneDefaultGreyLambertian) {
  TempDir dir;
  const LoadedScene loaded = loadOrFail(dir.write("cube.obj", cubeObj(false)));
  ASSERT_EQ(loaded.scene.materials.size(), 1U);
  EXPECT_EQ(loaded.scene.materials[0].lobe, Lobe::Lambertian);
  expectNear(loaded.scene.materials[0].diffuseAlbedo, glm::vec3(0.8F));
}

TEST(ObjLoader, SharedBunnyLoadsWith3674Triangles) {
  const LoadedScene loaded = loadOrFail(defaultBunnyPath());
  EXPECT_EQ(triangleCount(loaded.scene), 3674U);
  EXPECT_EQ(firstContractViolation(loaded.scene), "");
}

TEST(ObjLoaderRefuses, AMissingFileAsNotFound) {
  TempDir dir;
  const auto failure = refusal(dir.path() / "absent.obj");
  EXPECT_EQ(failure.error, SceneFileError::NotFound);
  EXPECT_THAT(failure.message, HasSubstr("does not exist"));
}

TEST(ObjLoaderRefuses, AVemLobeThatIsNeitherPhongNorBlinn) {
  TempDir dir;
  dir.write("m.mtl", "newmtl odd\nKd 0.2 0.2 0.2\nKs 0.3 0.3 0.3\nNs 80\nvem_lobe ward\n");
  const auto failure = refusal(
      dir.write("tri.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl odd\nf 1 2 3\n"));
  EXPECT_EQ(failure.error, SceneFileError::BadContents);
  EXPECT_THAT(failure.message,
              HasSubstr("material 'odd' has vem_lobe 'ward', where phong or blinn was expected"));
}

TEST(ObjLoaderRefuses, AVemLobeBesidePr) {
  TempDir dir;
  dir.write("m.mtl", "newmtl both\nKd 0.2 0.2 0.2\nPr 0.3\nvem_lobe phong\n");
  const auto failure = refusal(
      dir.write("tri.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl both\nf 1 2 3\n"));
  EXPECT_EQ(failure.error, SceneFileError::BadContents);
  EXPECT_THAT(failure.message, HasSubstr("has both Pr (a GGX lobe) and vem_lobe"));
}

TEST(ObjLoaderRefuses, ATruncatedFile) {
  TempDir dir;
  const auto failure = refusal(dir.write("cut.obj", firstHalf(cubeObj(false))));
  EXPECT_EQ(failure.error, SceneFileError::BadContents);
  // Cut inside the vertex list: a short line, or vertices and no faces.
  EXPECT_THAT(failure.message, ::testing::AnyOf(HasSubstr("coordinates where 3 were expected"),
                                                HasSubstr("no faces")));
}

TEST(ObjLoaderRefuses, AFaceIndexOutOfRange) {
  TempDir dir;
  const auto failure = refusal(dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"));
  EXPECT_EQ(failure.error, SceneFileError::BadContents);
  EXPECT_THAT(failure.message, HasSubstr("refers to vertex 9, but the file has 3 vertices"));
}

TEST(ObjLoaderRefuses, AQuadIndexOutOfRangeThatTinyobjDropsSilently) {
  TempDir dir;
  const auto failure =
      refusal(dir.write("bad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\nf 1 2 3 7\n"));
  EXPECT_THAT(failure.message,
              HasSubstr("line 6: face corner '7' refers to vertex 7, but the file has 4 vertices"));
}

// tinyobjloader reads indices with atoi: this one was accepted, whatever it became.
TEST(ObjLoaderRefuses, AFaceIndexTooLargeForAnyIntegerWithItsLine) {
  TempDir dir;
  const auto failure =
      refusal(dir.write("huge.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999999\n"));
  EXPECT_EQ(failure.error, SceneFileError::BadContents);
  EXPECT_THAT(failure.message, HasSubstr("line 4: face corner '99999999999999999999999' refers to "
                                         "vertex 99999999999999999999999, but the file has 3 "
                                         "vertices"));
}

// 2^32 + 1 wrapped to a valid index and was reported as a zero-area triangle.
TEST(ObjLoaderRefuses, AFaceIndexPastTwoToTheThirtyTwoInsteadOfWrappingIt) {
  TempDir dir;
  const auto failure =
      refusal(dir.write("wrap.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967297\n"));
  EXPECT_THAT(
      failure.message,
      HasSubstr("line 4: face corner '4294967297' refers to vertex 4294967297, but the file "
                "has 3 vertices"));
}

// A normal index of 2^32 + 1 wrapped to normal 1 and loaded without a word.
TEST(ObjLoaderRefuses, ANormalIndexPastTwoToTheThirtyTwoInsteadOfWrappingIt) {
  TempDir dir;
  const auto failure = refusal(
      dir.write("wrapn.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//4294967297\n"));
  EXPECT_THAT(failure.message, HasSubstr("line 5: face corner '3//4294967297' refers to normal "
                                         "4294967297, but the file has 1 normals"));
}

TEST(ObjLoaderRefuses, ARelativeIndexBeforeTheFirstVertexWithItsLine) {
  TempDir dir;
  const auto failure =
      refusal(dir.write("back.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\nv 1 1 1\n"));
  EXPECT_THAT(failure.message, HasSubstr("line 4: face corner '-4' refers to vertex -4 (counting "
                                         "back), but only 3 vertices come before the face"));
}

TEST(ObjLoader, RelativeIndicesCountBackFromTheFace) {
  TempDir dir;
  const LoadedScene loaded =
      loadOrFail(dir.write("rel.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nv 5 5 5\n"));
  ASSERT_EQ(loaded.scene.meshes.size(), 1U);
  expectNear(loaded.scene.meshes[0].positions[0], {0, 0, 0});
  expectNear(loaded.scene.meshes[0].positions[2], {0, 1, 0});
}

// A convex polygon of `corners` vertices on the unit circle, as an OBJ file.
std::string polygonObj(std::size_t corners) {
  std::string obj;
  for (std::size_t i = 0; i < corners; ++i) {
    const double angle = 2.0 * 3.14159265358979 * static_cast<double>(i) / corners;
    obj += fmt::format("v {} {} 0\n", std::cos(angle), std::sin(angle));
  }
  obj += "f";
  for (std::size_t i = 1; i <= corners; ++i) {
    obj += fmt::format(" {}", i);
  }
  return obj + "\n";
}

TEST(ObjLoader, APolygonOfTheMostVerticesIsTriangulated) {
  TempDir dir;
  const LoadedScene loaded = loadOrFail(dir.write("most.obj", polygonObj(kMaxFaceVertices)));
  EXPECT_EQ(triangleCount(loaded.scene), kMaxFaceVertices - 2);
}

// Ear clipping took 65 s over a 100,000-vertex polygon; larger faces are refused at once.
TEST(ObjLoaderRefuses, APolygonOfMoreThan256VerticesWithItsLine) {
  TempDir dir;
  const auto failure = refusal(dir.write("big.obj", polygonObj(kMaxFaceVertices + 1)));
  EXPECT_THAT(failure.message, HasSubstr("line 258: face has 257 vertices and cannot be "
                                         "triangulated, where 3 to 256 were expected"));
}

TEST(ObjLoaderRefuses, ANanVertexWithItsLine) {
  TempDir dir;
  const auto failure = refusal(dir.write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"));
  EXPECT_THAT(failure.message, HasSubstr("line 2: vertex coordinate 'nan' is not a finite number"));
}

TEST(ObjLoaderRefuses, AnInfiniteNormal) {
  TempDir dir;
  const auto failure =
      refusal(dir.write("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 inf 1\nf 1//1 2//1 3//1\n"));
  EXPECT_THAT(failure.message, HasSubstr("line 4: normal coordinate 'inf'"));
}

// The scene's folder: tmp/scene/ holds the OBJ file, tmp/outside.mtl lies beside it.
constexpr const char* kOutsideMtl = "newmtl stolen\nKd 0.1 0.2 0.3\n";
std::string objUsing(const std::string& mtllib) {
  return "mtllib " + mtllib + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl stolen\nf 1 2 3\n";
}

TEST(ObjLoaderRefuses, MtllibOutsideTheSceneFolderWithoutOpeningIt) {
  TempDir dir;
  const auto outside = dir.write("outside.mtl", kOutsideMtl);
  const OpenWatch watch(outside);
  const auto failure = refusal(dir.write("scene/tri.obj", objUsing("../outside.mtl")));
  EXPECT_EQ(failure.error, SceneFileError::BadContents);
  EXPECT_THAT(failure.message,
              HasSubstr(fmt::format("mtllib '../outside.mtl' lies outside the scene's folder {}",
                                    std::filesystem::canonical(dir.path() / "scene").string())));
  EXPECT_FALSE(watch.opened());
}

TEST(ObjLoaderRefuses, AnAbsoluteMtllibWithoutOpeningIt) {
  TempDir dir;
  const auto outside = dir.write("outside.mtl", kOutsideMtl);
  const OpenWatch watch(outside);
  const auto failure = refusal(dir.write("scene/tri.obj", objUsing(outside.string())));
  EXPECT_THAT(failure.message, HasSubstr("mtllib '" + outside.string() + "' lies outside"));
  EXPECT_FALSE(watch.opened());
}

TEST(ObjLoaderRefuses, MtllibThroughALinkThatLeadsOutsideWithoutOpeningIt) {
  TempDir dir;
  const auto outside = dir.write("outside.mtl", kOutsideMtl);
  dir.link("scene/inside.mtl", outside);
  const OpenWatch watch(outside);
  const auto failure = refusal(dir.write("scene/tri.obj", objUsing("inside.mtl")));
  EXPECT_THAT(failure.message, HasSubstr("mtllib 'inside.mtl' lies outside the scene's folder"));
  EXPECT_FALSE(watch.opened());
}

TEST(ObjLoader, MtllibThatLeavesAndReentersTheFolderLoads) {
  TempDir dir;
  dir.write("scene/paints/m.mtl", kOutsideMtl);
  const LoadedScene loaded =
      loadOrFail(dir.write("scene/tri.obj", objUsing("paints/../../scene/paints/m.mtl")));
  ASSERT_EQ(loaded.scene.materials.size(), 1U);
  expectNear(loaded.scene.materials[0].diffuseAlbedo, {0.1F, 0.2F, 0.3F});
}

TEST(ObjLoader, MtllibOutsideTheFolderLoadsWhenAllowed) {
  TempDir dir;
  dir.write("outside.mtl", kOutsideMtl);
  OutsideFolderPolicy allowed;
  allowed.allowed = true;
  const auto loaded = loadObj(dir.write("scene/tri.obj", objUsing("../outside.mtl")), allowed);
  ASSERT_TRUE(loaded) << loaded.error().message;
  ASSERT_EQ(loaded->scene.materials.size(), 1U);
  expectNear(loaded->scene.materials[0].diffuseAlbedo, {0.1F, 0.2F, 0.3F});
}

TEST(ObjLoaderRefuses, MtllibOutsideSaysHowToAllowIt) {
  TempDir dir;
  OutsideFolderPolicy refused;
  refused.howToAllow = "pass --x to allow it";
  const auto loaded = loadObj(dir.write("scene/tri.obj", objUsing("../outside.mtl")), refused);
  ASSERT_FALSE(loaded);
  EXPECT_THAT(loaded.error().message, HasSubstr("lies outside the scene's folder "));
  EXPECT_TRUE(loaded.error().message.ends_with(" (pass --x to allow it)."))
      << loaded.error().message;
}

// Names from the file reach the message escaped: no forged line.
TEST(ObjLoaderRefuses, AMaterialNameWithATerminalControlEscapedInTheMessage) {
  TempDir dir;
  dir.write("m.mtl", "newmtl odd\x1b[2J\nKd 0.2 0.2 0.2\nKs 0.3 0.3 0.3\nvem_lobe ward\n");
  const auto failure = refusal(dir.write(
      "tri.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl odd\x1b[2J\nf 1 2 3\n"));
  EXPECT_THAT(failure.message, HasSubstr("material 'odd\\x1b[2J' has vem_lobe 'ward'"));
}

TEST(ObjLoaderRefuses, AFaceOfTwoVertices) {
  TempDir dir;
  const auto failure = refusal(dir.write("two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n"));
  EXPECT_THAT(failure.message, HasSubstr("cannot be triangulated"));
}

TEST(ObjLoaderRefuses, AZeroLengthNormal) {
  TempDir dir;
  const auto failure =
      refusal(dir.write("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n"));
  EXPECT_THAT(failure.message, HasSubstr("normal 1 has zero length"));
}

TEST(ObjLoaderRefuses, AVertexOnlyOnZeroAreaTriangles) {
  TempDir dir;
  const auto failure = refusal(dir.write("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"));
  EXPECT_THAT(failure.message, HasSubstr("normal is undefined"));
}

TEST(ObjLoaderRefuses, AFileWithNoTriangles) {
  TempDir dir;
  const auto failure = refusal(dir.write("empty.obj", "v 0 0 0\nv 1 0 0\n"));
  EXPECT_THAT(failure.message, HasSubstr("no faces"));
}

}  // namespace
}  // namespace vem::scene
