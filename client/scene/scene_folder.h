// SceneFolder: the folder a scene file's references must stay inside. A scene file names other
// files (OBJ: `mtllib`; glTF and GLB: buffer and image URIs); each is resolved against the folder
// that holds the scene file (the path as given, made absolute), after `..` and symbolic links
// (std::filesystem::weakly_canonical), and refused when it lands outside that folder, unless the
// policy allows it:
// - absolute paths and `file:` URIs count as outside;
// - a symbolic link inside the folder that points outside counts as outside;
// - a refused file is never opened: resolving only looks at the folders on its way.
// The loaders open the resolved path, never the reference as written. No units.
#pragma once

#include <expected>
#include <filesystem>
#include <string>
#include <string_view>

namespace vem::scene {

struct OutsideFolderPolicy {
  bool allowed = false;  // references may lead anywhere (vemview --scene-allow-outside)
  // How the shell's user allows it, added to a refusal in parentheses
  // ("pass --scene-allow-outside to allow it"); empty: nothing added.
  std::string howToAllow;
};

class SceneFolder {
 public:
  SceneFolder(const std::filesystem::path& sceneFile, OutsideFolderPolicy policy);

  // The file `reference` (as the scene file spells it; `what` names the field, "mtllib") leads
  // to, resolved, or the refusal as the "what" part of a sentence about the scene file:
  // "mtllib '../../etc/passwd' lies outside the scene's folder /x/y (pass ... to allow it)".
  // The reference is escaped (util/printable.h) in the refusal.
  [[nodiscard]] std::expected<std::filesystem::path, std::string> resolve(
      std::string_view what, std::string_view reference) const;

  // The folder, absolute, its links resolved.
  [[nodiscard]] const std::filesystem::path& path() const { return folder_; }

 private:
  std::filesystem::path folder_;
  OutsideFolderPolicy policy_;
};

}  // namespace vem::scene
