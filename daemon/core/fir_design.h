// FIR low-pass taps for the temporal filter: the paper's published filter, a Parks-McClellan
// designer for other capture rates, low-latency presets, and the measures that compare them.
//
// Conventions:
// - `FirTaps` weights are causal and normalised: weights()[k] weighs the frame k steps old
//   (k = 0 is the newest frame) and the weights sum to 1, so a constant input passes unchanged
//   (the paper's "energy is preserved by normalising the weighting coefficients").
// - Frequencies are in Hz at the capture rate `rateHz` (frames per second), or in cycles per frame
//   (Hz / rateHz, Nyquist = 0.5). Gains are amplitude ratios |H(f)| of the normalised taps.
//   Delays are group delays in frames (x 1000 / rateHz for milliseconds).
// - Designs are equiripple low-passes (Parks-McClellan, [OSB99] section 7.7) computed by
// liquid-dsp's
//   firdespm with equal pass/stop weights; the tap count is odd so the linear-phase delay
//   (K - 1) / 2 is a whole number of frames: the output then stands for a captured frame.
//
// Reference: paper 004 section 3.3 "Handling Dynamic Sequences": 9-tap equiripple filter designed
// for 21 Hz capture, pass 7 Hz, stop 9 Hz, taps w1..w9 below, delay 4 frames. Parks-McClellan with
// those stated edges does NOT give the published taps; the edges 5.88 / 8.064 Hz do (to 3e-6).
// docs/temporal-filter.md explains this and measures the presets.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vem {

// Causal FIR weights that sum to 1 (the invariant is enforced by the only constructor).
class FirTaps {
 public:
  // nullopt when `weights` is empty, holds a non-finite value or sums to (nearly) zero.
  [[nodiscard]] static std::optional<FirTaps> normalised(std::span<const double> weights);

  [[nodiscard]] const std::vector<double>& weights() const { return weights_; }
  [[nodiscard]] std::size_t size() const { return weights_.size(); }

 private:
  explicit FirTaps(std::vector<double> weights) : weights_(std::move(weights)) {}
  std::vector<double> weights_;
};

struct BandEdgesHz {
  double rateHz = 21.0;  // capture rate, frames per second
  double passHz = 7.0;   // end of the pass band
  double stopHz = 9.0;   // start of the stop band
};

struct LowPassSpec {
  int tapCount = 9;  // odd, 3 ..= kMaxDesignTaps
  BandEdgesHz edges;
};

inline constexpr int kMaxDesignTaps = 255;

// Paper 004 section 3.3, w1..w9 as printed (they sum to 1.09245; normalise before use).
inline constexpr std::array<double, 9> kPaperTapsRaw = {
    0.06216, 0.01296, -0.13816, 0.28315, 0.65223, 0.28315, -0.13816, 0.01296, 0.06216};
// The edges the paper states for its design.
inline constexpr BandEdgesHz kPaperStatedEdges{21.0, 7.0, 9.0};
// The edges with which Parks-McClellan reproduces the published taps (measured; see the doc).
inline constexpr BandEdgesHz kPaperEffectiveEdges{21.0, 5.88, 8.064};
// The low-latency linear-phase preset: 5 taps, 2 frames of delay, its stop band at the paper's 9
// Hz.
inline constexpr LowPassSpec kEquiripple5Spec{5, {21.0, 4.5, 9.0}};

// One sentence naming what is wrong with `spec`, or nullopt when it can be designed:
// rate finite and > 0, 0 < pass < stop < rate / 2, tap count odd in 3 ..= kMaxDesignTaps.
[[nodiscard]] std::optional<std::string> describeInvalid(const LowPassSpec& spec);

// The raw equiripple design (not normalised: its DC gain is 1 + the pass-band ripple), as a
// Parks-McClellan tool prints it. nullopt when the spec is invalid or the design fails.
[[nodiscard]] std::optional<std::vector<double>> designEquiripple(const LowPassSpec& spec);

// designEquiripple, normalised.
[[nodiscard]] std::optional<FirTaps> designLowPass(const LowPassSpec& spec);

// The minimum-phase filter with the same gain |H(f)| at every frequency: zeros of the transfer
// function outside the unit circle are reflected inside (roots by liquid-dsp). Its group delay at
// DC is far below (K - 1) / 2, at the price of a phase that is not linear (the delay varies with
// frequency). nullopt when the first or last weight is zero or the result fails its gain check.
[[nodiscard]] std::optional<FirTaps> minimumPhase(const FirTaps& taps);

enum class FilterPreset {
  None,         // one tap of 1: no filtering, no delay
  Paper9,       // the published taps, linear phase, delay 4 frames
  Equiripple5,  // kEquiripple5Spec, linear phase, delay 2 frames
  MinPhase9,    // minimumPhase(Paper9): the paper's gains with under one frame of delay at DC
};
inline constexpr std::array<FilterPreset, 4> kAllPresets = {
    FilterPreset::None, FilterPreset::Paper9, FilterPreset::Equiripple5, FilterPreset::MinPhase9};

[[nodiscard]] FirTaps presetTaps(FilterPreset preset);
[[nodiscard]] const char* presetName(FilterPreset preset);  // "none", "paper9", ...
[[nodiscard]] std::optional<FilterPreset> presetFromName(std::string_view name);

// |H| of the normalised taps at a frequency in cycles per frame.
[[nodiscard]] double gainAt(const FirTaps& taps, double cyclesPerFrame);
// Group delay -d(phase)/d(omega) in frames at a frequency in cycles per frame.
[[nodiscard]] double groupDelayFramesAt(const FirTaps& taps, double cyclesPerFrame);

struct FilterCharacteristics {
  double delayFrames = 0;        // group delay at DC
  double delayMs = 0;            // the same at the capture rate
  double delaySpreadFrames = 0;  // max - min group delay over [0, pass]: 0 for linear phase
  double halfPowerHz = 0;        // lowest frequency with gain 1/sqrt(2) (rate / 2 if none)
  double passGain = 0;           // gain at the pass edge
  double stopGainMax = 0;        // largest gain over [stop, rate / 2]
  double jitterRmsGain = 0;      // sqrt(sum w^2): output RMS per unit RMS of white input jitter
  double stepOvershoot = 0;      // max(0, max step response - 1)
  double stepUndershoot = 0;     // max(0, -min step response)
};

// Pure measurement of `taps` at a capture rate and band edges (which must satisfy
// 0 < pass < stop <= rate / 2).
[[nodiscard]] FilterCharacteristics characteriseFilter(const FirTaps& taps,
                                                       const BandEdgesHz& edges);

}  // namespace vem
