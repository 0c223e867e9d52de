// Tone mapping: the global operator of Reinhard et al. 2002 ("Photographic tone reproduction",
// equation 4) with its two parameters, the world (log-average) luminance and the key, smoothed over
// time so that a changing environment does not make the picture flicker (paper 004 section 5.1).
//
// - Luminance: Rec. 709 (core/color.h). Statistics over covered pixels only (render/linear_image.h)
//   or over all pixels when none is covered.
// - Per frame: Lw = exp(mean(log(delta + L))) over the pixels; the automatic key of Reinhard 2006
//   ("Parameter estimation for photographic tone reproduction"):
//   key = 0.18 * 4^((2 log2 Lw - log2 Lmin - log2 Lmax) / (log2 Lmax - log2 Lmin)), with Lmin and
//   Lmax the 1st and 99th percentiles of L (clamped to [kMinKey, kMaxKey]); Lwhite = Lmax scaled.
// - Over time: log Lw and the key follow the frame's values with a first-order low-pass of time
//   constant tauSec (exact for any frame interval dt: weight 1 - exp(-dt / tau)); the first frame
//   takes its own values.
// - Display: Ls = key / Lw * L; Ld = Ls (1 + Ls / Lwhite^2) / (1 + Ls); each channel scaled by
//   Ld / L, clamped to [0, 1], then sRGB-encoded. NaN or negative input gives black.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "client/render/linear_image.h"

namespace vem::render {

inline constexpr double kLogDelta = 1e-6;
inline constexpr double kMinKey = 0.045;
inline constexpr double kMaxKey = 0.72;

struct FrameLuminance {
  double logAverage = 0.0;  // Lw, > 0
  double low = 0.0;         // 1st percentile
  double high = 0.0;        // 99th percentile
};

struct ToneParams {
  double worldLuminance = 1.0;  // Lw (smoothed)
  double key = 0.18;            // a (smoothed)
  double whiteLuminance = 1.0;  // Lwhite, in scaled units (Ls)
};

[[nodiscard]] FrameLuminance measureLuminance(const LinearImage& image);
[[nodiscard]] double automaticKey(const FrameLuminance& frame);

class ToneSmoother {
 public:
  explicit ToneSmoother(double tauSec = 0.5) : tauSec_(tauSec) {}
  // Takes one frame's luminance, dtSec after the previous one; returns the parameters to use.
  ToneParams update(const FrameLuminance& frame, double dtSec);
  [[nodiscard]] std::optional<ToneParams> current() const { return current_; }

 private:
  double tauSec_;
  double logWorld_ = 0.0;
  double key_ = 0.18;
  double logWhite_ = 0.0;
  std::optional<ToneParams> current_;
};

// Linear radiance -> display value in [0, 1] (before sRGB encoding).
[[nodiscard]] glm::vec3 toneMap(glm::vec3 rgb, const ToneParams& params);
[[nodiscard]] float srgbEncode(float linear01);
// The inverse: an sRGB-encoded value in [0, 1] to linear (IEC 61966-2-1).
[[nodiscard]] float srgbDecode(float encoded01);
// The whole image, tone-mapped and sRGB-encoded, 8 bits, row 0 at the top, RGB order.
[[nodiscard]] std::vector<std::uint8_t> toneMappedSrgb8(const LinearImage& image,
                                                        const ToneParams& params);

// A display-referred image (linear, 1 = the display's white: a camera's 8-bit picture decoded),
// sRGB-encoded with no tone mapping, clipped at 1: what came in as 8-bit comes out unchanged.
[[nodiscard]] std::vector<std::uint8_t> displaySrgb8(const LinearImage& image);

}  // namespace vem::render
