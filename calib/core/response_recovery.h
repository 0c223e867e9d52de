// Recovering an LDR camera's response from an exposure bracket (Debevec & Malik 1997, "Recovering
// High Dynamic Range Radiance Maps from Photographs", SIGGRAPH 97, section 2.1; paper 002 brackets
// its phone camera this way): K frames of one still scene at known, different exposures determine
// g(z) = ln X(z), the log relative exposure behind each code z, up to one constant, by a
// least-squares fit with a smoothness term (OpenCV's CalibrateDebevec).
//
// Conventions and units:
// - Frames: 8-bit RawFrames (Mono8 or RGB8) of one size and format, aligned, of a static scene;
//   each frame's exposure is exposureUs x gain (microseconds x linear gain). Channels are fitted
//   independently.
// - Result: a TabulatedResponse (photometric_model.h) with 256 codes per channel;
//   exposureByCode[c][z] is the relative exposure of code z normalised so that code 128 reads 1 in
//   every channel (so the channels' relative white balance is not recovered: grey at code 128 reads
//   alike in every channel). A mono camera fills channel 0 only. scaleCdM2 = options.scaleCdM2 (1:
//   relative units, until a patch of known luminance gives the scale).
// - Usable codes: more than marginCode above the black level and below saturation; the others say
//   nothing about the scene (noise floor, clipping: a clipped pixel's noise can read a few codes
//   below saturation). Informative codes: the usable codes the samples take. Over them the fitted
//   curve must increase; dips up to maxDipPercent (noise) are fixed, larger ones refused.
//   Monotone fix-up: isotonic regression of g over all 256 codes (the closest non-decreasing curve
//   in least squares, pool-adjacent-violators), then a step of 1e-6 where it is flat, so the table
//   increases strictly everywhere (codes outside the informative range keep the fit's smooth
//   extrapolation).
// - Samples: per channel, up to samplePixels pixels with usable codes in two frames or more,
//   spread evenly over the scene's brightness (ranked by the sum of their codes over the frames).
//   OpenCV cannot leave an observation out, so a sample's unusable codes are handed to it as 0 or
//   255, where its hat weighs them least.
// - Exposure ratios: with every ratio between successive exposures equal (250, 1000, 4000 us), the
//   data leave g unknown up to a perturbation periodic in ln X with that ratio's period (Grossberg
//   & Nayar 2003, "What can be known about the radiometric response from images?"); only the
//   smoothness term resolves it, and noise shows as ripples of a few percent. Uneven ratios (250,
//   1000, 3000, 16000 us) remove the ambiguity.
#pragma once

#include <array>
#include <expected>
#include <span>
#include <string>

#include "calib/core/photometric_model.h"
#include "frames/raw_frame.h"

namespace vem::calib {

struct ResponseRecoveryOptions {
  int samplePixels = 200;         // per channel; Debevec & Malik need N (K - 1) > 255
  double smoothness = 10.0;       // lambda, weighing g'' against the data
  double blackLevelCode = 0.0;    // codes at or below carry no information
  double saturationCode = 255.0;  // codes at or above are clipped
  double marginCode = 4.0;        // codes this close to either are avoided when sampling
  double maxDipPercent = 2.0;     // largest decrease over informative codes that is fixed
  double minSpanStops = 1.0;      // longest / shortest exposure, in stops
  double scaleCdM2 = 1.0;         // written into the result
};

enum class ResponseRefusal {
  TooFewExposures,
  NotEightBit,
  FramesDiffer,
  BadExposure,
  EqualExposures,
  SpanTooSmall,
  TooFewInformativePixels,
  NotIncreasing,
};

struct ResponseFailure {
  ResponseRefusal cause;
  std::string message;  // one sentence naming the frame (1-based, in the order given) or channel
};

// What the fit saw, per channel.
struct ChannelRecovery {
  int firstCode = 0;  // informative code range
  int lastCode = 0;
  int fixedCodes = 0;       // codes the monotone fix-up moved
  double rangeStops = 0.0;  // log2 X(lastCode) / X(firstCode)
};

struct RecoveredResponse {
  TabulatedResponse response;
  int channels = 1;
  int samplePixels = 0;  // per channel
  std::array<ChannelRecovery, 3> perChannel{};
};

[[nodiscard]] std::expected<RecoveredResponse, ResponseFailure> recoverResponseWithReport(
    std::span<const RawFrame> frames, const ResponseRecoveryOptions& options);

[[nodiscard]] std::expected<TabulatedResponse, ResponseFailure> recoverResponse(
    std::span<const RawFrame> frames, const ResponseRecoveryOptions& options);

}  // namespace vem::calib
