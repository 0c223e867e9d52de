#include "client/scene/obj_text_check.h"

#include <fmt/format.h>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace vem::scene {
namespace {

constexpr std::size_t kCoordinates = 3;  // x y z; `v` lines may add w or r g b

std::vector<std::string_view> tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t pos = 0;
  while ((pos = line.find_first_not_of(" \t\r", pos)) != std::string_view::npos) {
    const auto end = line.find_first_of(" \t\r", pos);
    out.push_back(line.substr(pos, end - pos));
    pos = end;
  }
  return out;
}

bool finiteNumber(std::string_view token) {
  if (token.starts_with('+')) {
    token.remove_prefix(1);  // from_chars takes no explicit plus sign
  }
  double value = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc{} && end == token.data() + token.size() && std::isfinite(value);
}

// What is wrong with one line, or empty.
std::string lineProblem(std::string_view line) {
  const auto parts = tokens(line);
  if (parts.empty() || (parts[0] != "v" && parts[0] != "vn")) {
    return {};
  }
  const char* what = parts[0] == "v" ? "vertex" : "normal";
  if (parts.size() < 1 + kCoordinates) {
    return fmt::format("{} has {} coordinates where 3 were expected", what, parts.size() - 1);
  }
  for (std::size_t i = 1; i < parts.size(); ++i) {
    if (!finiteNumber(parts[i])) {
      return fmt::format("{} coordinate '{}' is not a finite number", what, parts[i]);
    }
  }
  return {};
}

}  // namespace

std::optional<SceneFileFailure> findBadObjCoordinate(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  for (std::size_t lineNumber = 1; std::getline(in, line); ++lineNumber) {
    if (auto problem = lineProblem(line); !problem.empty()) {
      return badContents(path, fmt::format("line {}: {}", lineNumber, problem));
    }
  }
  return std::nullopt;
}

}  // namespace vem::scene
