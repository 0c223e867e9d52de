// BracketingSource: a camera without an HDR sensor made into one by exposure bracketing (paper
// 002; Debevec & Malik 1997). It wraps the camera's own FrameSource (`inner`), cycles its exposure
// over K stops, groups the frames by the exposure each reports, merges each complete group into
// one HDR frame and hands that on as the frame of a virtual 16-bit log sensor
// (virtual_hdr_sensor.h), so vemd's pipeline, recordings and replay treat it as any HDR camera.
//
// - Exposure: before each inner->next() it asks inner->setExposure() for the next bracket exposure
//   in cycle order (bracket_settings.h), advancing only when a frame came, so a camera that applies
//   requests d frames late delivers the cycle d frames later. A refused request is counted and
//   grouping copes (its frames do not match); the requests go on.
// - Grouping: by the frames' reported exposure x gain and seq (bracket_grouper.h). Frames outside
//   a complete group are recycled to the inner source and counted with their reason (counters()).
//   The output rate is the capture rate / K, less the groups lost.
// - Output frame: seq = the count of groups delivered before it (0, 1, 2, ...); captureTsNs = the
//   middle of the group, the mean of frames (K-1)/2 and K/2's (for odd K the middle frame's own);
//   arrivalNs = the last frame's. The frame is 16-bit Mono16 or RGB16 (the camera's channels),
//   exposureUs = the sum of the nominal bracket exposures, gain 1.
// - describe(): spec "bracket:K@STOPS+<inner spec>", the inner camera's model, serial and size,
//   pixelFormat Mono16/RGB16, calibrationToml = the camera file of the virtual sensor (the inner
//   camera's lens and orientation, the log response; written by calib/io's camera file writer, so
//   it loads as any camera file), nominalRateHz = inner / K, clock and pace as the inner's.
// - Errors: an inner error passes through unchanged and drops the group in progress (Error). A
//   frame of another size or format than the camera file's is BadFrame. When 4K + 8 frames in a
//   row have not completed a group, next() returns BadFrame naming the last frame's exposure and
//   the expected ones (the camera ignores the requests, or the tolerance is too tight); the daemon
//   retries and the grouping goes on.
// - recycle(): the merged frames' buffers are this source's own: a spent merged frame keeps its
//   codes for a later merge (the inner frames went back to the inner source's recycle() as soon as
//   they were merged or dropped). interrupt() forwards to the inner source (its next() returns
//   Timeout, which passes through). Capture thread only, but interrupt().
#pragma once

#include <cstdint>
#include <expected>
#include <memory>
#include <string>
#include <vector>

#include "calib/core/bracket_merge.h"
#include "calib/core/camera_calibration.h"
#include "cameras/bracketing/bracket_grouper.h"
#include "cameras/bracketing/bracket_settings.h"
#include "cameras/bracketing/virtual_hdr_merge.h"
#include "cameras/bracketing/virtual_hdr_sensor.h"
#include "frames/frame_source.h"

namespace vem::cameras {

struct BracketCounters {
  std::uint64_t framesIn = 0;                 // frames taken from the inner source
  std::uint64_t groups = 0;                   // groups merged and delivered
  std::uint64_t framesDropped = 0;            // the three reasons below together
  std::uint64_t droppedOutOfCycle = 0;        // exposure not the next of the cycle (or none)
  std::uint64_t droppedForGap = 0;            // their group was broken by a lost frame (seq gap)
  std::uint64_t droppedForError = 0;          // their group was broken by an inner error/bad frame
  std::uint64_t exposureRequestsRefused = 0;  // inner->setExposure() said no
  std::uint64_t saturatedSamples = 0;         // merged samples at the virtual sensor's top code
  std::uint64_t darkSamples = 0;              // merged samples below its range (code 0)
  // Always: framesIn == groups * K + framesDropped + frames of the group in progress.
};

class BracketingSource final : public FrameSource {
 public:
  // Checks the settings, reads the inner camera file (it needs a photometric section whose
  // response depends on exposure, i.e. "table" or "linear") and asks for the first exposure.
  // NoDevice with one sentence when any of that fails, naming the inner source's spec.
  [[nodiscard]] static std::expected<std::unique_ptr<BracketingSource>, SourceError> create(
      std::unique_ptr<FrameSource> inner, BracketSettings settings);

  [[nodiscard]] SourceDescription describe() const override;
  [[nodiscard]] std::expected<CapturedFrame, SourceError> next() override;
  void recycle(CapturedFrame&& spent) override;
  void interrupt() override;
  // Refused: the source sets the exposure itself.
  [[nodiscard]] std::expected<void, std::string> setExposure(double exposureUs,
                                                             double gain) override;

  [[nodiscard]] const BracketCounters& counters() const { return counters_; }
  [[nodiscard]] const BracketSettings& settings() const { return settings_; }
  [[nodiscard]] const VirtualHdrSensor& sensor() const { return sensor_; }
  [[nodiscard]] const std::vector<double>& exposuresUs() const { return exposuresUs_; }
  // What the last merge saw (samples clipped, dark, unweighed).
  [[nodiscard]] const VirtualHdrMergeStats& lastMergeStats() const { return lastStats_; }

 private:
  BracketingSource(std::unique_ptr<FrameSource> inner, BracketSettings settings,
                   calib::CameraCalibration ldrCamera, VirtualHdrSensor sensor,
                   std::string virtualToml);
  void requestExposure();
  void dropPending(std::size_t frames, BracketDropReason reason);
  void dropFrame(CapturedFrame&& frame, BracketDropReason reason);
  void count(std::size_t frames, BracketDropReason reason);
  [[nodiscard]] CapturedFrame mergeGroup();
  [[nodiscard]] SourceError noGroupError(const RawFrame& last) const;

  std::unique_ptr<FrameSource> inner_;
  SourceDescription innerDescription_;
  BracketSettings settings_;
  std::vector<double> exposuresUs_;
  calib::CameraCalibration ldrCamera_;
  calib::BracketWeighting weighting_;
  VirtualHdrSensor sensor_;
  std::string virtualToml_;
  BracketGrouper grouper_;
  std::size_t requestIndex_ = 0;
  std::string lastRefusal_;

  // The group in progress: frames and their identities, in order.
  std::vector<RawFrame> pendingFrames_;
  std::vector<CapturedFrame> pendingIds_;  // seq and times; frame left empty

  BracketMergeScratch scratch_;
  std::vector<std::vector<std::uint16_t>> spareCodes_;
  VirtualHdrMergeStats lastStats_;
  BracketCounters counters_;
};

}  // namespace vem::cameras
