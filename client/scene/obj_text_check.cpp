#include "client/scene/obj_text_check.h"

#include <fmt/format.h>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>

#include "util/printable.h"

namespace vem::scene {
namespace {

constexpr std::size_t kCoordinates = 3;  // x y z; `v` lines may add w or r g b
constexpr std::size_t kMinFaceVertices = 3;

// The lines of a text, one at a time, without their endings.
class Lines {
 public:
  explicit Lines(std::string_view text) : rest_(text) {}

  std::optional<std::string_view> next() {
    if (rest_.empty()) {
      return std::nullopt;
    }
    ++number_;
    const std::size_t end = rest_.find_first_of("\r\n");
    const std::string_view line = rest_.substr(0, end);
    if (end == std::string_view::npos) {
      rest_ = {};
    } else {
      const bool crlf = rest_[end] == '\r' && end + 1 < rest_.size() && rest_[end + 1] == '\n';
      rest_.remove_prefix(end + (crlf ? 2 : 1));
    }
    return line;
  }
  [[nodiscard]] std::size_t number() const { return number_; }

 private:
  std::string_view rest_;
  std::size_t number_ = 0;
};

// The words of a line (split at spaces and tabs, as tinyobjloader does), one at a time.
class Words {
 public:
  explicit Words(std::string_view line) : rest_(line) {}

  std::optional<std::string_view> next() {
    const std::size_t first = rest_.find_first_not_of(" \t");
    if (first == std::string_view::npos) {
      rest_ = {};
      return std::nullopt;
    }
    rest_.remove_prefix(first);
    const std::size_t end = rest_.find_first_of(" \t");
    const std::string_view word = rest_.substr(0, end);
    rest_ = end == std::string_view::npos ? std::string_view{} : rest_.substr(end);
    return word;
  }

 private:
  std::string_view rest_;
};

enum class Element { Vertex, Texcoord, Normal };
constexpr std::size_t kElements = 3;
constexpr std::array<const char*, kElements> kSingular{"vertex", "texture coordinate", "normal"};
constexpr std::array<const char*, kElements> kPlural{"vertices", "texture coordinates", "normals"};

using Counts = std::array<std::uint64_t, kElements>;

std::optional<Element> elementOf(std::string_view keyword) {
  if (keyword == "v") return Element::Vertex;
  if (keyword == "vt") return Element::Texcoord;
  if (keyword == "vn") return Element::Normal;
  return std::nullopt;
}

bool finiteNumber(std::string_view token) {
  if (token.starts_with('+')) {
    token.remove_prefix(1);  // from_chars takes no explicit plus sign
  }
  double value = 0.0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc{} && end == token.data() + token.size() && std::isfinite(value);
}

// What is wrong with the coordinates of a `v` or `vn` line (after its keyword), or empty.
std::string coordinateProblem(Element element, Words words) {
  const char* what = element == Element::Vertex ? "vertex" : "normal";
  std::size_t count = 0;
  while (const auto word = words.next()) {
    if (!finiteNumber(*word)) {
      return fmt::format("{} coordinate '{}' is not a finite number", what, util::printable(*word));
    }
    ++count;
  }
  if (count < kCoordinates) {
    return fmt::format("{} has {} coordinates where 3 were expected", what, count);
  }
  return {};
}

// What is wrong with one index of a face corner (`text`, one of its slash-separated parts), given
// how many elements of its kind the file has and how many come before the face; or empty.
std::string indexProblem(std::string_view corner, std::string_view text, Element element,
                         std::uint64_t total, std::uint64_t before) {
  const auto kind = static_cast<std::size_t>(element);
  const std::string_view digits = text.starts_with('+') ? text.substr(1) : text;
  std::int64_t value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || ec == std::errc::invalid_argument || end != digits.data() + digits.size()) {
    return fmt::format("face corner '{}' has the {} index '{}', where a whole number was expected",
                       util::printable(corner), kSingular[kind], util::printable(text));
  }
  const bool huge = ec == std::errc::result_out_of_range;
  if (!huge && value == 0) {
    return fmt::format(
        "face corner '{}' refers to {} 0, where indices start at 1 (or count back "
        "from -1)",
        util::printable(corner), kSingular[kind]);
  }
  const bool negative = digits.starts_with('-');
  if (!negative && (huge || static_cast<std::uint64_t>(value) > total)) {
    return fmt::format("face corner '{}' refers to {} {}, but the file has {} {}",
                       util::printable(corner), kSingular[kind], digits, total, kPlural[kind]);
  }
  if (negative && (huge || value < -static_cast<std::int64_t>(before))) {
    return fmt::format(
        "face corner '{}' refers to {} {} (counting back), but only {} {} come "
        "before the face",
        util::printable(corner), kSingular[kind], digits, before, kPlural[kind]);
  }
  return {};
}

// What is wrong with one face corner (v, v/vt, v//vn or v/vt/vn), or empty.
std::string cornerProblem(std::string_view corner, const Counts& total, const Counts& before) {
  std::array<std::string_view, kElements> parts;
  std::size_t count = 0;
  for (std::size_t from = 0;;) {
    const std::size_t slash = corner.find('/', from);
    if (count == kElements) {
      count = kElements + 1;  // a fourth part
      break;
    }
    parts[count++] = corner.substr(from, slash == std::string_view::npos ? slash : slash - from);
    if (slash == std::string_view::npos) {
      break;
    }
    from = slash + 1;
  }
  const bool wellFormed = count <= kElements && !parts[0].empty() &&
                          (count != 2 || !parts[1].empty()) && (count != 3 || !parts[2].empty());
  if (!wellFormed) {
    return fmt::format("face corner '{}' is not v, v/vt, v//vn or v/vt/vn",
                       util::printable(corner));
  }
  for (std::size_t k = 0; k < count; ++k) {
    if (parts[k].empty()) {
      continue;  // v//vn
    }
    if (auto problem = indexProblem(corner, parts[k], static_cast<Element>(k), total[k], before[k]);
        !problem.empty()) {
      return problem;
    }
  }
  return {};
}

// What is wrong with an `f` line (after its keyword), or empty.
std::string faceProblem(Words words, const Counts& total, const Counts& before) {
  std::size_t corners = 0;
  for (Words counting = words; counting.next();) {
    ++corners;
  }
  if (corners < kMinFaceVertices || corners > kMaxFaceVertices) {
    return fmt::format(
        "face has {} vertices and cannot be triangulated, where {} to {} were "
        "expected",
        corners, kMinFaceVertices, kMaxFaceVertices);
  }
  while (const auto corner = words.next()) {
    if (auto problem = cornerProblem(*corner, total, before); !problem.empty()) {
      return problem;
    }
  }
  return {};
}

Counts countElements(std::string_view text) {
  Counts counts{};
  Lines lines(text);
  while (const auto line = lines.next()) {
    if (const auto keyword = Words(*line).next()) {
      if (const auto element = elementOf(*keyword)) {
        ++counts[static_cast<std::size_t>(*element)];
      }
    }
  }
  return counts;
}

}  // namespace

std::optional<SceneFileFailure> checkObjText(const std::filesystem::path& path,
                                             std::string_view text) {
  const Counts total = countElements(text);
  Counts before{};
  Lines lines(text);
  while (const auto line = lines.next()) {
    Words words(*line);
    const auto keyword = words.next();
    if (!keyword) {
      continue;
    }
    std::string problem;
    if (const auto element = elementOf(*keyword)) {
      if (*element != Element::Texcoord) {
        problem = coordinateProblem(*element, words);
      }
      ++before[static_cast<std::size_t>(*element)];
    } else if (*keyword == "f") {
      problem = faceProblem(words, total, before);
    }
    if (!problem.empty()) {
      return badContents(path, fmt::format("line {}: {}", lines.number(), problem));
    }
  }
  return std::nullopt;
}

}  // namespace vem::scene
