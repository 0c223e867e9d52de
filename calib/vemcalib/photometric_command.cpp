// `vemcalib photometric`: the camera's response from frames of grey patches of known luminance
// (paper 004 section 5.1). Measures each patch, fits the response by least squares, prints every
// patch's error and writes the response into the camera file, or refuses and writes nothing.
#include <algorithm>
#include <cstdlib>
#include <map>
#include <memory>

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include "calib/core/photometric_fit.h"
#include "calib/io/camera_file.h"
#include "calib/io/patch_file.h"
#include "calibration_summary.h"
#include "camera_output.h"
#include "commands.h"
#include "util/cli_value_names.h"
#include "frame_arguments.h"

namespace vem::calibtool {
namespace {

struct PhotometricOptions {
  std::vector<std::string> frames;
  std::string patches;
  std::string out;
  calib::FitModel model = calib::FitModel::Log;
  std::optional<double> blackLevelCode;
  std::optional<double> saturationCode;
  std::optional<int> bits;
  double gain = 1.0;
  double maxResidualPercent = calib::PhotometricFitOptions{}.maxResidualPercent;
  double maxCheckErrorPercent = calib::PhotometricFitOptions{}.maxCheckErrorPercent;
};

// What the fit needs, loaded and checked against each other.
struct PhotometricInputs {
  std::optional<calib::CameraCalibration> existing;  // the --out file, when there is one
  std::vector<calib::PatchSpec> patches;
  std::vector<RawFrame> frames;
};

std::expected<std::vector<RawFrame>, std::string> loadFrames(const PhotometricOptions& o,
                                                             std::optional<int> bits) {
  std::vector<RawFrame> frames;
  for (const std::string& argument : o.frames) {
    auto frame = loadFrameArgument(argument, bits, o.gain);
    if (!frame) return std::unexpected(frame.error());
    const RawFrame& first = frames.empty() ? *frame : frames.front();
    if (frame->width != first.width || frame->height != first.height ||
        frame->format != first.format || frame->exposureUs != first.exposureUs)
      return std::unexpected(fmt::format(
          "{}: the frame is {} at {:g} us but {} is {} at {:g} us (every --frame must share size, "
          "format and exposure)",
          argument, describeFrame(*frame), frame->exposureUs, o.frames.front(),
          describeFrame(first), first.exposureUs));
    frames.push_back(std::move(*frame));
  }
  return frames;
}

std::optional<std::string> regionProblem(const calib::PatchSpec& patch, const RawFrame& frame,
                                         const std::string& patchesPath) {
  if (patch.x + patch.width <= frame.width && patch.y + patch.height <= frame.height)
    return std::nullopt;
  return fmt::format(
      "{}: patch \"{}\": region: x {} to {}, y {} to {} reaches beyond the {} x {} frame",
      patchesPath, patch.name, patch.x, patch.x + patch.width - 1, patch.y,
      patch.y + patch.height - 1, frame.width, frame.height);
}

std::expected<PhotometricInputs, std::string> loadInputs(const PhotometricOptions& o) {
  PhotometricInputs in;
  auto existing = loadCameraToMerge(o.out);
  if (!existing) return std::unexpected(existing.error());
  in.existing = std::move(*existing);
  auto patches = calib::io::loadPatchFile(o.patches);
  if (!patches) return std::unexpected(patches.error().message);
  in.patches = std::move(*patches);
  std::optional<int> bits = o.bits;
  if (!bits && in.existing) bits = in.existing->camera.pixelFormat.bits;
  auto frames = loadFrames(o, bits);
  if (!frames) return std::unexpected(frames.error());
  in.frames = std::move(*frames);
  if (in.existing)
    if (auto mismatch = frameMismatch(in.existing->camera, o.out, in.frames.front()))
      return std::unexpected(*mismatch + " (--out merges into that file)");
  for (const calib::PatchSpec& patch : in.patches)
    if (auto problem = regionProblem(patch, in.frames.front(), o.patches))
      return std::unexpected(*problem);
  return in;
}

std::expected<calib::PhotometricFitOptions, std::string> fitOptionsFor(
    const PhotometricOptions& o, const PhotometricInputs& in) {
  const PixelFormat format = in.frames.front().format;
  const std::optional<calib::PhotometricCalibration> known =
      in.existing ? in.existing->photometric : std::nullopt;
  calib::PhotometricFitOptions fit;
  fit.model = o.model;
  fit.blackLevelCode = o.blackLevelCode.value_or(known ? known->blackLevelCode : 0.0);
  fit.saturationCode = o.saturationCode.value_or(known ? known->saturationCode : format.maxCode());
  fit.maxResidualPercent = o.maxResidualPercent;
  fit.maxCheckErrorPercent = o.maxCheckErrorPercent;
  if (fit.saturationCode > format.maxCode())
    return std::unexpected(fmt::format("the saturation code {:g} is above {}, the largest {} code",
                                       fit.saturationCode, format.maxCode(),
                                       pixelFormatName(format)));
  if (!(fit.blackLevelCode < fit.saturationCode))
    return std::unexpected(
        fmt::format("the black level {:g} must lie below the saturation code {:g}",
                    fit.blackLevelCode, fit.saturationCode));
  return fit;
}

void printTable(const std::vector<calib::PatchResult>& results, int channels) {
  std::size_t nameWidth = 5;
  for (const auto& r : results) nameWidth = std::max(nameWidth, r.name.size());
  const bool colour = channels == 3;
  fmt::print("{:<{}}  use    {}luminance    mean code  fitted          error\n", "patch", nameWidth,
             colour ? "channel  " : "");
  fmt::print("{:<{}}         {}cd/m2                   cd/m2           %\n", "", nameWidth,
             colour ? "         " : "");
  for (const auto& r : results) {
    for (int c = 0; c < channels; ++c) {
      const auto ch = std::size_t(c);
      const std::string channel = colour ? fmt::format("{:<9}", "RGB"[c]) : "";
      fmt::print("{:<{}}  {:<5}  {}{:<11.6g}  {:>9.2f}  {:<11.6g}  {:>+7.3f}\n", r.name, nameWidth,
                 r.check ? "check" : "fit", channel, r.luminanceCdM2, r.meanCode[ch],
                 r.fittedLuminanceCdM2[ch], r.errorPercent[ch]);
    }
  }
}

void printSummary(const calib::PhotometricFit& fit, const calib::PhotometricFitOptions& options,
                  PixelFormat format) {
  const calib::PhotometricQuality& q = fit.quality;
  fmt::print(
      "fit: {} response from {} patches: rms residual {:.3g} %, largest {:.3g} % (limit {:g} %)\n",
      calib::responseModelName(fit.calibration.response), q.fitPatches, q.rmsResidualPercent,
      q.maxResidualPercent, options.maxResidualPercent);
  if (q.checkPatches > 0) {
    fmt::print("check: {} patches: largest error {:.3g} % (limit {:g} %)\n", q.checkPatches,
               q.maxCheckErrorPercent, options.maxCheckErrorPercent);
  } else {
    fmt::print("check: no check patches (mark some with check = true to test the fit)\n");
  }
  for (const std::string& line : responseLines(fit.calibration, format))
    fmt::print("response: {}\n", line);
}

int writeCalibration(const PhotometricOptions& o, const PhotometricInputs& in,
                     const calib::PhotometricFit& fit) {
  calib::CameraCalibration calibration = in.existing.value_or(newCameraFor(in.frames.front()));
  calibration.photometric = fit.calibration;
  calibration.photometricQuality = fit.quality;
  calibration.photometricQuality.date = utcDateNow();
  if (auto saved = calib::io::saveCameraFile(calibration, o.out); !saved) {
    spdlog::error("{}", saved.error().message);
    return cli::kExitFailure;
  }
  fmt::print("wrote {}: {}\n", o.out,
             in.existing ? "the photometric section (the rest of the file is kept)"
                         : "a new camera file (model and serial \"unknown\": edit them there)");
  return EXIT_SUCCESS;
}

int runPhotometric(const PhotometricOptions& o) {
  const auto inputs = loadInputs(o);
  if (!inputs) return reportFailure(inputs.error());
  const auto options = fitOptionsFor(o, *inputs);
  if (!options) return reportFailure(options.error());
  std::vector<calib::PatchMeasurement> measured;
  for (const calib::PatchSpec& patch : inputs->patches)
    measured.push_back(calib::measurePatch(inputs->frames, patch, options->blackLevelCode,
                                           options->saturationCode));
  const PixelFormat format = inputs->frames.front().format;
  const auto fit = calib::fitPhotometric(measured, *options);
  if (!fit) {
    if (!fit.error().patches.empty()) printTable(fit.error().patches, format.channels);
    spdlog::error("{} (nothing was written)", fit.error().message);
    return cli::kExitFailure;
  }
  printTable(fit->patches, format.channels);
  printSummary(*fit, *options, format);
  return writeCalibration(o, *inputs, *fit);
}

constexpr const char* kPhotometricFooter = R"(Example:
  vemcalib simulate patches --camera config/camera-example.toml --out sim
  vemcalib photometric --frame sim/patches-1.png sim/patches-2.png sim/patches-3.png \
      --patches sim/patches.toml --bits 12 --black-level 64 --saturation 4095 --out sim/camera.toml
Each --frame is FILE or FILE@EXPOSURE_US (default 1000 us); all share size, format and exposure.
PATCHES is a TOML file of [[patch]] tables: name, region = { value = [x, y, width, height],
unit = "px" }, luminance = { value = ..., unit = "cd/m2" } and, for patches left out of the fit
to check it, check = true (docs/calibration.md).
Prints each patch's known and fitted luminance and its error in percent, then the fit.
Refuses, in one sentence, writing nothing: fewer than 3 fit patches; a patch saturated or under
the black level; codes not increasing with luminance; a fit residual above --max-residual or a
check error above --max-check-error. Otherwise it replaces the photometric section of CAMERA_FILE
(the rest is kept) or creates the file.)";

}  // namespace

void addPhotometricCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<PhotometricOptions>();
  CLI::App* cmd = app.add_subcommand(
      "photometric", "Fit the camera's response to frames of grey patches of known luminance");
  cmd->footer(kPhotometricFooter);
  cmd->add_option("--frame", o->frames, "Raw frames of the patches: FILE[@EXPOSURE_US] ...")
      ->required();
  cmd->add_option("--patches", o->patches, "Patch list (TOML): regions and luminances")->required();
  cmd->add_option("--out", o->out, "Camera file to update or create (TOML)")->required();
  const std::map<std::string, calib::FitModel> models{{"log", calib::FitModel::Log},
                                                      {"linear", calib::FitModel::Linear}};
  cmd->add_option("--model", o->model, "log (default: HDR log sensor) | linear")
      ->transform(CLI::CheckedTransformer(models, CLI::ignore_case));
  cmd->add_option("--black-level", o->blackLevelCode,
                  "Black level in codes (default: the --out file's, else 0)")
      ->check(help::quiet(CLI::NonNegativeNumber));
  cmd->add_option("--saturation", o->saturationCode,
                  "Saturation code (default: the --out file's, else the format's largest code)")
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--bits", o->bits,
                  "Bits per code in 16-bit images, e.g. 12 (default: the --out file's, else the "
                  "image's depth)")
      ->check(CLI::IsMember({8, 10, 12, 16}));
  cmd->add_option("--gain", o->gain, "Linear gain the frames were taken with")
      ->capture_default_str()
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--max-residual", o->maxResidualPercent,
                  "Largest fit-patch residual accepted, percent")
      ->capture_default_str()
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->add_option("--max-check-error", o->maxCheckErrorPercent,
                  "Largest check-patch error accepted, percent")
      ->capture_default_str()
      ->check(help::quiet(CLI::PositiveNumber));
  cmd->callback([o, &exitCode] { exitCode = runPhotometric(*o); });
}

}  // namespace vem::calibtool
