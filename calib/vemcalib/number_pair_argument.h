// Two numbers named on vemcalib's command line as one value, "A,B": a pixel (--pixel 1006.4,127.9)
// or a direction (--probe-direction 140.3,14.4, azimuth and elevation in degrees).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <CLI/CLI.hpp>

namespace vem::calibtool {

// "12.5,-3" -> (12.5, -3); nullopt unless both are finite numbers.
[[nodiscard]] std::optional<std::pair<double, double>> parseNumberPair(std::string_view text);

// A CLI11 check: one sentence when the text is not two numbers; `names` says which ("X,Y").
[[nodiscard]] CLI::Validator numberPairValidator(std::string names);

}  // namespace vem::calibtool
