// BracketSettings: how a camera without an HDR sensor brackets its exposure (paper 002: a phone
// camera's automatic exposure bracketing, merged to HDR after Debevec & Malik 1997), as the
// [camera.bracketing] section of vemd's configuration gives it (docs/cameras.md).
//
// Conventions and units:
// - K = count exposures per group, in cycle order k = 0 .. K-1, the shortest first:
//       exposureUs_k = baseExposureUs * 2^(stopsApart * k),  all at gain `gain` (linear, 1 =
//       unity).
//   A frame's effective exposure is exposureUs x gain (what the response sees); it matches
//   bracket exposure k when |effective / (exposureUs_k x gain) - 1| <= matchTolerance.
// - Every field is checked by bracketSettingsProblem(), which names the first field out of range
//   in one sentence.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace vem::cameras {

struct BracketSettings {
  // K, the exposures per group (2 to 9): the output rate is the camera's rate / K.
  int count = 3;
  // Stops (factors of 2) between successive exposures, 0.5 to 8: an 8-bit camera reads about 10
  // stops at one exposure, so steps of up to about 8 stops still overlap.
  double stopsApart = 2.0;
  // The shortest exposure in microseconds, above 0; the longest, base * 2^(stops (K - 1)), may be
  // at most 10 s (1e7 us) and should stay below the frame period.
  double baseExposureUs = 1000.0;
  // The analogue gain of every exposure, linear, above 0 and at most 1000.
  double gain = 1.0;
  // How far (relative) a frame's reported exposure x gain may be from the bracket exposure it is
  // taken for, above 0 and below (2^stops - 1) / (2^stops + 1) so that no frame can match two
  // neighbouring exposures (0.05 suits cameras that round exposures to a line time).
  double matchTolerance = 0.05;

  friend bool operator==(const BracketSettings&, const BracketSettings&) = default;
};

inline constexpr int kMinBracketCount = 2;
inline constexpr int kMaxBracketCount = 9;
inline constexpr double kMinStopsApart = 0.5;
inline constexpr double kMaxStopsApart = 8.0;
inline constexpr double kMaxBracketExposureUs = 1e7;
inline constexpr double kMaxBracketGain = 1000.0;

// One sentence naming the first field out of range and what it must be, or nullopt.
[[nodiscard]] std::optional<std::string> bracketSettingsProblem(const BracketSettings& settings);

// The K exposures in cycle order (microseconds, at settings.gain). Requires valid settings.
[[nodiscard]] std::vector<double> bracketExposuresUs(const BracketSettings& settings);

}  // namespace vem::cameras
