// loadScene: dispatch on the extension, and the refusals that are not a loader's.
#include "client/scene/scene_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "scene_test_files.h"

namespace vem::scene {
namespace {

using test_files::cubeObj;
using test_files::GltfTriangle;
using test_files::TempDir;
using ::testing::HasSubstr;

TEST(SceneFile, DispatchesObjCaseInsensitively) {
  TempDir dir;
  const auto scene = loadScene(dir.write("CUBE.OBJ", cubeObj(false)));
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(triangleCount(*scene), 12U);
}

TEST(SceneFile, DispatchesGltf) {
  TempDir dir;
  const auto scene = loadScene(dir.write("tri.gltf", GltfTriangle{}.json()));
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(triangleCount(*scene), 1U);
}

TEST(SceneFile, ObjTextInAGltfFileIsRefusedByTheGltfLoader) {
  TempDir dir;
  const auto path = dir.write("cube.gltf", cubeObj(false));
  const auto scene = loadScene(path);
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().error, SceneFileError::BadContents);
  EXPECT_THAT(scene.error().message, HasSubstr("not a valid glTF 2.0 file"));
}

TEST(SceneFileRefuses, AnUnsupportedExtension) {
  TempDir dir;
  const auto path = dir.write("bunny.ply", "ply\n");
  const auto scene = loadScene(path);
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().error, SceneFileError::UnsupportedFormat);
  EXPECT_THAT(scene.error().message, HasSubstr(path.string()));
  EXPECT_THAT(scene.error().message, HasSubstr("'.ply', where .obj, .gltf or .glb was expected"));
}

TEST(SceneFileRefuses, AMissingFile) {
  TempDir dir;
  const auto path = dir.path() / "absent.glb";
  const auto scene = loadScene(path);
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().error, SceneFileError::NotFound);
  EXPECT_THAT(scene.error().message, HasSubstr(path.string()));
}

TEST(SceneFileRefuses, ADirectoryAsUnreadable) {
  TempDir dir;
  const auto path = dir.path() / "folder.obj";
  std::filesystem::create_directory(path);
  const auto scene = loadScene(path);
  ASSERT_FALSE(scene);
  EXPECT_EQ(scene.error().error, SceneFileError::Unreadable);
  EXPECT_THAT(scene.error().message, HasSubstr("is not a regular file"));
}

}  // namespace
}  // namespace vem::scene
