// Merging one exposure group into one frame of the virtual HDR sensor: the pure core of
// bracketing (no source, no state over time). K raw frames of the LDR camera, each with the
// exposure and gain it reports, become radiance by calib's bracket merge (calib/core/
// bracket_merge.h: Debevec & Malik's weighted mean, zero weight for clipped and noise-floor codes)
// and then 16-bit log codes (virtual_hdr_sensor.h).
//
// Conventions: frames of one size and format (the LDR camera's), any order of exposure; the output
// is a RawFrame of the sensor's format and the frames' size, exposureUs and gain as the caller sets
// them (virtual_hdr_sensor.h's convention is the caller's to apply). Speed: the logarithm per
// sample comes from a 4096-entry table of log2 over the float mantissa, linearly interpolated
// (within 2e-4 codes of a + b ln L, far below the half-code rounding); the merge tables are built
// once per frame exposure and gain and reused while they repeat (BracketMergeScratch).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "calib/core/bracket_merge.h"
#include "calib/core/photometric_model.h"
#include "cameras/bracketing/virtual_hdr_sensor.h"
#include "frames/raw_frame.h"

namespace vem::cameras {

// What one merge saw, in samples (pixel x channel).
struct VirtualHdrMergeStats {
  std::size_t samples = 0;
  std::size_t unweighedSamples = 0;  // no exposure weighed them (calib: clipped + black + gap)
  std::size_t saturatedSamples = 0;  // encoded as 65535: at or above the sensor's maximum
  std::size_t darkSamples = 0;       // encoded as 0: below its minimum
};

// Storage a caller merging group after group keeps, so that a steady stream allocates nothing.
struct BracketMergeScratch {
  calib::MergedBracket merged;
  std::vector<calib::BracketLut> luts;  // the last tables built, reused for equal exposure x gain
};

// The merged radiance of `frames` (calib's merge with `ldr` and `weighting`) into scratch.merged.
void mergeBracketRadiance(std::span<const RawFrame> frames,
                          const calib::PhotometricCalibration& ldr,
                          const calib::BracketWeighting& weighting, BracketMergeScratch& scratch);

// Radiance (cd/m^2, the layout of `merged`) to the sensor's codes, into out.codes (resized); sets
// out's size and format, leaves its exposure and gain.
[[nodiscard]] VirtualHdrMergeStats encodeVirtualHdr(const calib::MergedBracket& merged,
                                                    const VirtualHdrSensor& sensor, RawFrame& out);

// Both: the group `frames` as one frame of `sensor`.
[[nodiscard]] VirtualHdrMergeStats mergeToVirtualHdr(std::span<const RawFrame> frames,
                                                     const calib::PhotometricCalibration& ldr,
                                                     const calib::BracketWeighting& weighting,
                                                     const VirtualHdrSensor& sensor,
                                                     BracketMergeScratch& scratch, RawFrame& out);

}  // namespace vem::cameras
