// `vemcalib response`: an LDR camera's response from an exposure bracket (Debevec & Malik 1997;
// calib/core/response_recovery.h), checked by merging the bracket with it (bracket_merge.h), then
// written into the camera file's photometric section as a table. Prints the curve (codes used,
// monotonicity, range in stops) and how well the exposures agree once merged; refuses, writing
// nothing, when the recovery refuses.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "calib/core/bracket_merge.h"
#include "calib/core/response_recovery.h"
#include "calib/io/camera_file.h"
#include "camera_output.h"
#include "commands.h"
#include "frame_arguments.h"
#include "mapio/map_file.h"
#include "util/cli_value_names.h"

namespace vem::calibtool {
namespace {

struct ResponseOptions {
  std::vector<std::string> brackets;
  std::string out;
  std::string mergeOut;
  double scaleCdM2 = 1.0;
  double blackLevelCode = 0.0;
  double saturationCode = 255.0;
};

// Each bracket must name its exposure: FILE@EXPOSURE_US.
std::expected<RawFrame, std::string> loadBracket(const std::string& token) {
  const auto argument = parseFrameArgument(token);
  if (!argument) return std::unexpected(argument.error());
  if (argument->path.string() == token) {
    return std::unexpected(
        fmt::format("--bracket {}: expected FILE@EXPOSURE_US, the image file and its exposure in "
                    "microseconds (e.g. bracket-1000.png@1000)",
                    token));
  }
  return loadFrameArgument(token, std::nullopt, 1.0);
}

std::expected<std::vector<RawFrame>, std::string> loadBrackets(const ResponseOptions& o) {
  std::vector<RawFrame> frames;
  for (const std::string& token : o.brackets) {
    auto frame = loadBracket(token);
    if (!frame) return std::unexpected(frame.error());
    if (!frames.empty() && (frame->width != frames[0].width || frame->height != frames[0].height ||
                            frame->format != frames[0].format)) {
      return std::unexpected(fmt::format(
          "--bracket {}: the frame is {} but {} is {} (every bracket must share size and format)",
          token, describeFrame(*frame), o.brackets.front(), describeFrame(frames[0])));
    }
    frames.push_back(std::move(*frame));
  }
  return frames;
}

// True when three exposures or more step by one ratio throughout (response_recovery.h: the curve
// then keeps a periodic ambiguity that only smoothness resolves).
bool evenlySpaced(std::span<const RawFrame> frames) {
  std::vector<double> exposures;
  for (const RawFrame& f : frames) exposures.push_back(f.exposureUs * f.gain);
  std::sort(exposures.begin(), exposures.end());
  if (exposures.size() < 3) return false;
  const double ratio = exposures[1] / exposures[0];
  for (std::size_t k = 2; k < exposures.size(); ++k) {
    if (std::abs(exposures[k] / exposures[k - 1] / ratio - 1.0) > 0.02) return false;
  }
  return true;
}

void printCurve(const calib::RecoveredResponse& recovered, std::span<const RawFrame> frames) {
  const auto [shortest, longest] = std::minmax_element(
      frames.begin(), frames.end(),
      [](const auto& a, const auto& b) { return a.exposureUs * a.gain < b.exposureUs * b.gain; });
  fmt::print(
      "response: Debevec-Malik from {} exposures, {:g} to {:g} us ({:.1f} stops), {} pixels "
      "per channel\n",
      frames.size(), shortest->exposureUs, longest->exposureUs,
      std::log2(longest->exposureUs / shortest->exposureUs), recovered.samplePixels);
  for (int c = 0; c < recovered.channels; ++c) {
    const calib::ChannelRecovery& r = recovered.perChannel[std::size_t(c)];
    fmt::print("  {}: codes {} to {} used, strictly increasing ({}), {:.1f} stops over them\n",
               recovered.channels == 1 ? std::string("grey") : std::string(1, "RGB"[c]),
               r.firstCode, r.lastCode,
               r.fixedCodes == 0 ? std::string("as fitted")
                                 : fmt::format("{} codes fixed up", r.fixedCodes),
               r.rangeStops);
  }
  if (evenlySpaced(frames)) {
    spdlog::warn(
        "the exposures step by one ratio throughout: the curve may ripple by a few "
        "percent (uneven ratios, e.g. 250, 1000, 3000, 16000 us, avoid that)");
  }
}

void printMergeCheck(const calib::BracketConsistency& consistency,
                     const calib::MergedBracket& merged) {
  if (consistency.comparedPairs == 0) {
    fmt::print("merge check: no sample is seen well by two exposures (nothing to compare)\n");
  } else {
    fmt::print(
        "merge check: exposures agree to a median {:.2f} % (rms {:.2f} %, largest {:.1f} %) "
        "over {} samples seen by two\n",
        consistency.medianPercent, consistency.rmsPercent, consistency.maxPercent,
        consistency.comparedPairs);
  }
  fmt::print(
      "merge: {} samples clipped in every exposure, {} in the noise floor in every "
      "exposure, {} in a gap between exposures\n",
      merged.clippedSamples, merged.blackSamples, merged.gapSamples);
}

int writeMergedMap(const std::string& path, const calib::MergedBracket& merged) {
  EnvMap map = EnvMap::filled(MapLayout::Sphere, merged.width, merged.height, glm::vec3(0.0F));
  const std::size_t channels = std::size_t(merged.channels);
  for (std::size_t p = 0; p < map.pixelCount(); ++p) {
    for (std::size_t c = 0; c < 3; ++c) {
      map.rgb[p * 3 + c] = merged.luminanceCdM2[p * channels + (channels == 1 ? 0 : c)];
    }
  }
  if (auto saved = mapio::saveMap(map, path); !saved) {
    return reportFailure(saved.error().message + ": nothing was written");
  }
  fmt::print("wrote {}: the merged bracket, {} x {} sensor pixels\n", path, merged.width,
             merged.height);
  return EXIT_SUCCESS;
}

int writeCalibration(const ResponseOptions& o, std::optional<calib::CameraCalibration> existing,
                     const RawFrame& first, const calib::PhotometricCalibration& photometric,
                     const calib::BracketConsistency& consistency) {
  const bool merging = existing.has_value();
  calib::CameraCalibration calibration = existing ? std::move(*existing) : newCameraFor(first);
  calibration.photometric = photometric;
  calibration.photometricQuality = calib::PhotometricQuality{
      consistency.rmsPercent, consistency.maxPercent, 0.0, 0, 0, utcDateNow()};
  if (!reportWritten(calib::io::saveCameraFile(calibration, o.out), o.out,
                     merging ? "the photometric section (the rest of the file is kept)"
                             : "a new camera file (model and serial \"unknown\": edit them there)"))
    return cli::kExitFailure;
  return EXIT_SUCCESS;
}

// The brackets and the camera file they update, checked against each other and the options.
struct ResponseInputs {
  std::optional<calib::CameraCalibration> existing;  // the --out file, when there is one
  std::vector<RawFrame> frames;
};

std::expected<ResponseInputs, std::string> loadInputs(const ResponseOptions& o) {
  if (!(o.blackLevelCode < o.saturationCode)) {
    return std::unexpected(
        fmt::format("the black level {:g} must lie below the saturation code {:g}",
                    o.blackLevelCode, o.saturationCode));
  }
  auto existing = loadCameraToMerge(o.out);
  if (!existing) return std::unexpected(existing.error());
  auto frames = loadBrackets(o);
  if (!frames) return std::unexpected(frames.error());
  if (*existing) {
    if (auto mismatch = frameMismatch((*existing)->camera, o.out, frames->front())) {
      return std::unexpected(*mismatch + " (--out merges into that file)");
    }
  }
  return ResponseInputs{std::move(*existing), std::move(*frames)};
}

// The merge check: the bracket merged through the recovered response, and the agreement between
// its exposures.
struct MergeCheck {
  calib::MergedBracket merged;
  calib::BracketConsistency consistency;
};

MergeCheck checkMerge(std::span<const RawFrame> frames,
                      const calib::PhotometricCalibration& photometric) {
  std::vector<calib::BracketLut> luts;
  for (const RawFrame& f : frames) {
    luts.push_back(buildBracketLut(photometric, f.format, f.exposureUs, f.gain, {}));
  }
  return MergeCheck{calib::mergeBracket(frames, luts), calib::bracketConsistency(frames, luts)};
}

int runResponse(const ResponseOptions& o) {
  auto inputs = loadInputs(o);
  if (!inputs) return reportFailure(inputs.error());
  calib::ResponseRecoveryOptions options;
  options.blackLevelCode = o.blackLevelCode;
  options.saturationCode = o.saturationCode;
  options.scaleCdM2 = o.scaleCdM2;
  const auto recovered = calib::recoverResponseWithReport(inputs->frames, options);
  if (!recovered) {
    return reportFailure(recovered.error().message + ": nothing was written");
  }
  printCurve(*recovered, inputs->frames);
  const calib::PhotometricCalibration photometric{recovered->response, o.blackLevelCode,
                                                  o.saturationCode};
  const MergeCheck check = checkMerge(inputs->frames, photometric);
  printMergeCheck(check.consistency, check.merged);
  if (!o.mergeOut.empty()) {
    if (const int status = writeMergedMap(o.mergeOut, check.merged); status != EXIT_SUCCESS) {
      return status;
    }
  }
  return writeCalibration(o, std::move(inputs->existing), inputs->frames.front(), photometric,
                          check.consistency);
}

constexpr const char* kResponseFooter = R"(Example:
  vemcalib simulate brackets --camera truth.toml --map ../shared/data/hdri/lobby.exr \
      --exposures 250,1000,3000,16000 --out brackets
  vemcalib response --bracket brackets/bracket-250.png@250 brackets/bracket-1000.png@1000 \
      brackets/bracket-3000.png@3000 brackets/bracket-16000.png@16000 --out camera.toml \
      --merge-out merged.exr
Each --bracket is FILE@EXPOSURE_US: an 8-bit image (grey or colour) of the same still scene, taken
with that exposure in microseconds at unit gain; at least 2 exposures spanning at least one stop.
Uneven ratios between successive exposures (here 4, 3, 5.3) recover the curve better than equal
ones, which leave it a periodic ambiguity that only the smoothness term resolves.
The response is Debevec & Malik's (1997) least-squares curve per channel, normalised so that code
128 reads 1; --scale gives the absolute scale when known (cd/m2 us per unit), else it stays
relative. The frames are then merged with it (a hat weighting that ignores codes within 4 of
black and of saturation) and the exposures' agreement is printed; [photometric.fit] records its
rms and largest disagreement in percent.
Refuses, in one sentence, writing nothing: fewer than 2 exposures, frames that are not 8-bit or
differ in size, equal exposures, exposures spanning less than a stop, a curve that falls.
Otherwise it replaces the photometric section of CAMERA_FILE (the rest is kept) or creates it.)";

}  // namespace

void addResponseCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ResponseOptions>();
  CLI::App* cmd = app.add_subcommand(
      "response", "Recover an LDR camera's response from an exposure bracket (Debevec-Malik)");
  cmd->footer(kResponseFooter);
  cmd->add_option("--bracket", o->brackets, "Frames of one scene: FILE@EXPOSURE_US ...")
      ->required();
  cmd->add_option("--out", o->out, "Camera file to update or create (TOML)")->required();
  cmd->add_option("--scale", o->scaleCdM2,
                  "Absolute scale, cd/m2 us per relative exposure unit (default 1: relative)")
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--black-level", o->blackLevelCode, "Black level in codes")
      ->capture_default_str()
      ->check(help::quiet(CLI::NonNegativeNumber));
  cmd->add_option("--saturation", o->saturationCode, "Saturation code")
      ->capture_default_str()
      ->type_name(help::rangeName(1.0, 255.0))
      ->check(help::quiet(CLI::Range(1.0, 255.0)));
  cmd->add_option("--merge-out", o->mergeOut,
                  "Also write the merged bracket (sensor pixels, luminance) as an EXR to look at");
  cmd->callback([o, &exitCode] { exitCode = runResponse(*o); });
}

}  // namespace vem::calibtool
