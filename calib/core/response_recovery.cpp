#include "calib/core/response_recovery.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <opencv2/core.hpp>
#include <opencv2/photo.hpp>

namespace vem::calib {
namespace {

constexpr int kCodes = 256;
constexpr int kMinSamplePixels = 32;

std::unexpected<ResponseFailure> refuse(ResponseRefusal cause, std::string message) {
  return std::unexpected(ResponseFailure{cause, std::move(message)});
}

double exposureOf(const RawFrame& frame) { return frame.exposureUs * frame.gain; }

std::string channelName(int channel, int channels) {
  return channels == 1 ? std::string("grey") : std::string(1, "RGB"[channel]);
}

std::string describe(const RawFrame& frame) {
  return fmt::format("{}x{} {}", frame.width, frame.height, pixelFormatName(frame.format));
}

std::optional<ResponseFailure> checkFormats(std::span<const RawFrame> frames) {
  if (frames.size() < 2) {
    return ResponseFailure{ResponseRefusal::TooFewExposures,
                           fmt::format("response recovery needs frames at 2 or more exposures, "
                                       "got {}",
                                       frames.size())};
  }
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (frames[k].format.bits != 8) {
      return ResponseFailure{ResponseRefusal::NotEightBit,
                             fmt::format("frame {} is {}: response recovery reads 8-bit frames "
                                         "(Mono8 or RGB8) only",
                                         k + 1, pixelFormatName(frames[k].format))};
    }
    if (frames[k].width != frames[0].width || frames[k].height != frames[0].height ||
        frames[k].format != frames[0].format) {
      return ResponseFailure{ResponseRefusal::FramesDiffer,
                             fmt::format("frame {} is {} but frame 1 is {}: every frame of a "
                                         "bracket must come from the same camera mode",
                                         k + 1, describe(frames[k]), describe(frames[0]))};
    }
  }
  return std::nullopt;
}

std::optional<ResponseFailure> checkExposures(std::span<const RawFrame> frames,
                                              const ResponseRecoveryOptions& options) {
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (!(std::isfinite(exposureOf(frames[k])) && frames[k].exposureUs > 0.0 &&
          frames[k].gain > 0.0)) {
      return ResponseFailure{ResponseRefusal::BadExposure,
                             fmt::format("frame {} has exposure {} us and gain {}: both must be "
                                         "positive",
                                         k + 1, frames[k].exposureUs, frames[k].gain)};
    }
    for (std::size_t j = 0; j < k; ++j) {
      const double a = exposureOf(frames[j]);
      const double b = exposureOf(frames[k]);
      if (std::abs(a - b) <= 1e-6 * std::max(a, b)) {
        return ResponseFailure{ResponseRefusal::EqualExposures,
                               fmt::format("frames {} and {} have the same exposure ({} us x gain "
                                           "{}): each frame of a bracket needs its own exposure",
                                           j + 1, k + 1, frames[k].exposureUs, frames[k].gain)};
      }
    }
  }
  const auto [shortest, longest] = std::minmax_element(
      frames.begin(), frames.end(),
      [](const RawFrame& a, const RawFrame& b) { return exposureOf(a) < exposureOf(b); });
  const double spanStops = std::log2(exposureOf(*longest) / exposureOf(*shortest));
  if (spanStops < options.minSpanStops) {
    return ResponseFailure{
        ResponseRefusal::SpanTooSmall,
        fmt::format("the exposures span {:.2f} stops ({} to {} us x gain): "
                    "recovering a response needs at least {} stop(s)",
                    spanStops, exposureOf(*shortest), exposureOf(*longest), options.minSpanStops)};
  }
  return std::nullopt;
}

// A code within marginCode of black or of saturation tells nothing about the scene (noise floor,
// or clipped: a clipped pixel's noise can read a few codes below saturation).
struct UsableCodes {
  double above;  // usable codes are > above and < below
  double below;
  [[nodiscard]] bool usable(int code) const { return code > above && code < below; }
};

UsableCodes usableCodes(const ResponseRecoveryOptions& options) {
  return {options.blackLevelCode + options.marginCode, options.saturationCode - options.marginCode};
}

// Candidate sample pixels of `channel`, as (sum of codes over the frames, pixel), sorted: the sum
// is a monotone proxy of the scene's brightness. A candidate has a usable code in at least two
// frames (with one, its exposure is a free unknown that absorbs the observation).
std::vector<std::pair<int, std::size_t>> rankedCandidates(std::span<const RawFrame> frames,
                                                          int channel,
                                                          const ResponseRecoveryOptions& options) {
  const std::size_t channels = std::size_t(frames[0].format.channels);
  const std::size_t pixels = frames[0].codes.size() / channels;
  const UsableCodes codes = usableCodes(options);
  std::vector<std::pair<int, std::size_t>> ranked;
  for (std::size_t p = 0; p < pixels; ++p) {
    int sum = 0;
    int usable = 0;
    for (const RawFrame& frame : frames) {
      const int code = frame.codes[p * channels + std::size_t(channel)];
      usable += codes.usable(code) ? 1 : 0;
      sum += code;
    }
    if (usable >= 2) ranked.emplace_back(sum, p);
  }
  std::sort(ranked.begin(), ranked.end());
  return ranked;
}

// `count` of the ranked pixels, spread evenly over the range of their sums of codes.
std::vector<std::size_t> spreadOverRange(const std::vector<std::pair<int, std::size_t>>& ranked,
                                         int count) {
  std::vector<std::size_t> picked;
  if (ranked.empty() || count <= 0) return picked;
  std::vector<bool> used(ranked.size(), false);
  const double lo = ranked.front().first;
  const double step = (ranked.back().first - lo) / double(count);
  auto next = ranked.begin();
  for (int i = 0; i < count && next != ranked.end(); ++i) {
    const double target = lo + (i + 0.5) * step;
    next = std::lower_bound(next, ranked.end(), target,
                            [](const auto& entry, double t) { return entry.first < t; });
    if (next == ranked.end()) break;
    used[std::size_t(next - ranked.begin())] = true;
    picked.push_back(next->second);
    ++next;
  }
  // Fill up with pixels passed over, in rank order, when the sums bunch together.
  for (std::size_t r = 0; r < ranked.size() && picked.size() < std::size_t(count); ++r) {
    if (!used[r]) picked.push_back(ranked[r].second);
  }
  return picked;
}

// One 1 x N CV_8UC3 image per frame holding the chosen samples: with samples = N, OpenCV's sample
// grid visits each column once (x_points = N, y_points = 1). A mono frame fills all three
// channels alike. Unusable codes go to 0 or 255, where OpenCV's hat weighs them least (1 against
// 128 mid-range): it cannot leave an observation out.
std::vector<cv::Mat> sampleImages(std::span<const RawFrame> frames,
                                  const std::array<std::vector<std::size_t>, 3>& picked, int count,
                                  const UsableCodes& codes) {
  const std::size_t channels = std::size_t(frames[0].format.channels);
  std::vector<cv::Mat> images;
  for (const RawFrame& frame : frames) {
    cv::Mat image(1, count, CV_8UC3);
    for (int i = 0; i < count; ++i) {
      for (std::size_t c = 0; c < 3; ++c) {
        const std::size_t source = channels == 1 ? 0 : c;
        const int code = frame.codes[picked[source][std::size_t(i)] * channels + source];
        const int sampled = codes.usable(code) ? code : (code <= codes.above ? 0 : kCodes - 1);
        image.at<cv::Vec3b>(0, i)[int(c)] = cv::saturate_cast<std::uint8_t>(sampled);
      }
    }
    images.push_back(image);
  }
  return images;
}

// The informative code range of one channel: the usable codes its samples take.
ChannelRecovery informativeRange(std::span<const RawFrame> frames,
                                 const std::vector<std::size_t>& pixels, int channel,
                                 const UsableCodes& codes) {
  const std::size_t channels = std::size_t(frames[0].format.channels);
  ChannelRecovery range{kCodes - 1, 0, 0, 0.0};
  for (const RawFrame& frame : frames) {
    for (const std::size_t p : pixels) {
      const int code = frame.codes[p * channels + std::size_t(channel)];
      if (codes.usable(code)) {
        range.firstCode = std::min(range.firstCode, code);
        range.lastCode = std::max(range.lastCode, code);
      }
    }
  }
  return range;
}

// Pool-adjacent-violators: the non-decreasing sequence closest to `g` in least squares.
std::vector<double> isotonic(const std::vector<double>& g) {
  std::vector<double> means;
  std::vector<int> sizes;
  for (const double value : g) {
    means.push_back(value);
    sizes.push_back(1);
    while (means.size() > 1 && means[means.size() - 2] > means.back()) {
      const double total =
          means.back() * sizes.back() + means[means.size() - 2] * sizes[sizes.size() - 2];
      const int size = sizes.back() + sizes[sizes.size() - 2];
      means.pop_back();
      sizes.pop_back();
      means.back() = total / size;
      sizes.back() = size;
    }
  }
  std::vector<double> out;
  for (std::size_t b = 0; b < means.size(); ++b)
    out.insert(out.end(), std::size_t(sizes[b]), means[b]);
  return out;
}

// A decrease of g (log exposure) beyond the tolerated dip over the informative codes, as a refusal.
std::optional<ResponseFailure> checkIncreasing(const std::vector<double>& g,
                                               const ChannelRecovery& range,
                                               const std::string& channel,
                                               const ResponseRecoveryOptions& options) {
  if (range.lastCode <= range.firstCode) {
    return ResponseFailure{ResponseRefusal::NotIncreasing,
                           fmt::format("channel {} takes a single informative code: the frames "
                                       "show no brightness variation to fit a response to",
                                       channel)};
  }
  const double tolerance = std::log1p(-options.maxDipPercent / 100.0);
  int peak = range.firstCode;
  for (int z = range.firstCode + 1; z <= range.lastCode; ++z) {
    const double drop = g[std::size_t(z)] - g[std::size_t(peak)];
    if (drop >= 0.0) {
      peak = z;
    } else if (drop < tolerance) {
      return ResponseFailure{
          ResponseRefusal::NotIncreasing,
          fmt::format("the recovered response of channel {} falls by {:.0f}% from code {} to code "
                      "{}: the exposure times do not match the frames (swapped or mistyped "
                      "FILE@EXPOSURE_US?), or the scene moved",
                      channel, 100.0 * (1.0 - std::exp(drop)), peak, z)};
    }
  }
  return std::nullopt;
}

// Monotone fix-up, strict increase and normalisation at the mid code; counts the codes moved.
std::vector<double> monotoneTable(const std::vector<double>& g, ChannelRecovery& range) {
  std::vector<double> fixed = isotonic(g);
  for (int z = range.firstCode; z <= range.lastCode; ++z) {
    if (std::abs(fixed[std::size_t(z)] - g[std::size_t(z)]) > 1e-9) ++range.fixedCodes;
  }
  for (std::size_t z = 1; z < fixed.size(); ++z) {
    fixed[z] = std::max(fixed[z], fixed[z - 1] + 1e-6);
  }
  const double mid = fixed[kCodes / 2];
  std::vector<double> table(fixed.size());
  for (std::size_t z = 0; z < fixed.size(); ++z) table[z] = std::exp(fixed[z] - mid);
  range.rangeStops =
      std::log2(table[std::size_t(range.lastCode)] / table[std::size_t(range.firstCode)]);
  return table;
}

cv::Mat runDebevec(const std::vector<cv::Mat>& images, std::span<const RawFrame> frames,
                   const ResponseRecoveryOptions& options) {
  std::vector<float> timesS;
  for (const RawFrame& frame : frames) timesS.push_back(float(exposureOf(frame) * 1e-6));
  cv::Mat response;
  cv::createCalibrateDebevec(images[0].cols, float(options.smoothness), false)
      ->process(images, response, cv::Mat(timesS, true));
  return response;
}

// Each channel's sample pixels, as many in every channel (OpenCV fits the three channels of one
// image), spread over the scene's brightness; or a refusal when too few pixels are seen well.
std::expected<std::array<std::vector<std::size_t>, 3>, ResponseFailure> pickSamples(
    std::span<const RawFrame> frames, const ResponseRecoveryOptions& options) {
  const int channels = frames[0].format.channels;
  std::array<std::vector<std::pair<int, std::size_t>>, 3> ranked;
  std::size_t count = std::size_t(std::max(0, options.samplePixels));
  for (int c = 0; c < channels; ++c) {
    ranked[std::size_t(c)] = rankedCandidates(frames, c, options);
    count = std::min(count, ranked[std::size_t(c)].size());
  }
  if (count < std::size_t(kMinSamplePixels)) {
    return refuse(
        ResponseRefusal::TooFewInformativePixels,
        fmt::format("only {} pixels are seen well (more than {} codes from black and from "
                    "saturation) by two exposures or more; response recovery needs at least {}",
                    count, options.marginCode, kMinSamplePixels));
  }
  std::array<std::vector<std::size_t>, 3> picked;
  for (int c = 0; c < channels; ++c) {
    picked[std::size_t(c)] = spreadOverRange(ranked[std::size_t(c)], int(count));
  }
  return picked;
}

// One channel of OpenCV's response (relative exposure per code) as a checked, monotone table.
std::expected<std::vector<double>, ResponseFailure> channelTable(
    const cv::Mat& response, int channel, int channels, ChannelRecovery& range,
    const ResponseRecoveryOptions& options) {
  std::vector<double> g(kCodes);
  for (int z = 0; z < kCodes; ++z) {
    g[std::size_t(z)] = std::log(double(response.at<cv::Vec3f>(z)[channel]));
  }
  if (auto failure = checkIncreasing(g, range, channelName(channel, channels), options)) {
    return std::unexpected(std::move(*failure));
  }
  return monotoneTable(g, range);
}

}  // namespace

std::expected<RecoveredResponse, ResponseFailure> recoverResponseWithReport(
    std::span<const RawFrame> frames, const ResponseRecoveryOptions& options) {
  if (auto failure = checkFormats(frames)) return std::unexpected(std::move(*failure));
  if (auto failure = checkExposures(frames, options)) return std::unexpected(std::move(*failure));
  const auto picked = pickSamples(frames, options);
  if (!picked) return std::unexpected(picked.error());
  const int count = int((*picked)[0].size());
  const UsableCodes codes = usableCodes(options);
  const cv::Mat response = runDebevec(sampleImages(frames, *picked, count, codes), frames, options);
  RecoveredResponse result;
  result.channels = frames[0].format.channels;
  result.samplePixels = count;
  result.response.scaleCdM2 = options.scaleCdM2;
  for (int c = 0; c < result.channels; ++c) {
    ChannelRecovery& range = result.perChannel[std::size_t(c)];
    range = informativeRange(frames, (*picked)[std::size_t(c)], c, codes);
    auto table = channelTable(response, c, result.channels, range, options);
    if (!table) return std::unexpected(std::move(table.error()));
    result.response.exposureByCode[std::size_t(c)] = std::move(*table);
  }
  return result;
}

std::expected<TabulatedResponse, ResponseFailure> recoverResponse(
    std::span<const RawFrame> frames, const ResponseRecoveryOptions& options) {
  auto recovered = recoverResponseWithReport(frames, options);
  if (!recovered) return std::unexpected(std::move(recovered.error()));
  return std::move(recovered->response);
}

}  // namespace vem::calib
