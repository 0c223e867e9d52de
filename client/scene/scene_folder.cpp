#include "client/scene/scene_folder.h"

#include <fmt/format.h>
#include <algorithm>
#include <cctype>
#include <system_error>
#include <utility>

#include "util/printable.h"

namespace vem::scene {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kFileScheme = "file:";

bool startsWithFileScheme(std::string_view reference) {
  return reference.size() >= kFileScheme.size() &&
         std::ranges::equal(
             reference.substr(0, kFileScheme.size()), kFileScheme,
             [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

// The path a reference names: a `file:` URI's path ("file:///a/b" -> "/a/b"), else as written.
fs::path pathOf(std::string_view reference) {
  if (startsWithFileScheme(reference)) {
    reference.remove_prefix(kFileScheme.size());
    if (reference.starts_with("//")) {
      reference.remove_prefix(2);  // an empty authority: "file:///a" is "/a"
    }
  }
  return fs::path(reference);
}

bool inside(const fs::path& folder, const fs::path& resolved) {
  const fs::path relative = resolved.lexically_relative(folder);
  return !relative.empty() && relative != "." && *relative.begin() != "..";
}

fs::path resolvedFolder(const fs::path& sceneFile) {
  std::error_code ec;
  fs::path folder = fs::absolute(sceneFile, ec).parent_path();
  if (ec) {
    folder = sceneFile.parent_path();
  }
  fs::path canonical = fs::weakly_canonical(folder, ec);
  return ec ? folder.lexically_normal() : canonical;
}

}  // namespace

SceneFolder::SceneFolder(const fs::path& sceneFile, OutsideFolderPolicy policy)
    : folder_(resolvedFolder(sceneFile)), policy_(std::move(policy)) {}

std::expected<fs::path, std::string> SceneFolder::resolve(std::string_view what,
                                                          std::string_view reference) const {
  const fs::path named = pathOf(reference);
  const bool absolute = startsWithFileScheme(reference) || named.is_absolute();
  std::error_code ec;
  const fs::path resolved = fs::weakly_canonical(absolute ? named : folder_ / named, ec);
  if (ec) {
    return std::unexpected(fmt::format("{} '{}' cannot be resolved ({})", what,
                                       util::printable(reference), ec.message()));
  }
  if (policy_.allowed || (!absolute && inside(folder_, resolved))) {
    return resolved;
  }
  return std::unexpected(fmt::format(
      "{} '{}' lies outside the scene's folder {}{}", what, util::printable(reference),
      util::printable(folder_.string()),
      policy_.howToAllow.empty() ? std::string() : fmt::format(" ({})", policy_.howToAllow)));
}

}  // namespace vem::scene
