// Pipeline: what vemd does to each frame, as one value-in, value-out chain (docs/architecture.md,
// "Data flow of one frame"):
//
//   RawFrame --calibrate (code table, polar remap)--> EnvMap (polar, cd/m^2)
//            --tables--> SamplingTables --lights (pattern prefix)--> LightSet
//            --filter (TemporalFilter::push(seq))--> LightSet --cluster (optional)--> Clustering
//
// - Built once per calibration (the camera file is parsed by the setup, pipeline_setup.h): the
//   polar remap is built once; the code-to-luminance table is rebuilt only when a frame's exposure
//   or gain differ from the previous frame's (bit for bit). The sampling tables' storage is
//   recycled frame to frame.
// - State over time: only the temporal filter's rings, keyed by the frames' seq (gaps and
//   duplicates are handled there, temporal_filter.h).
// - Deterministic: the same frames in the same order give bit-identical lights.
// - Pure apart from reading the clock for the per-stage timings: no threads, files or logging.
//
// Units: map in cd/m^2 per channel (a calibrated camera), light rgb in cd/m^2 sr; timings in
// microseconds per stage ("calibrate", "tables", "lights", "filter", "cluster").
#pragma once

#include <cstddef>
#include <cstdint>
#include <expected>
#include <functional>
#include <optional>
#include <string>

#include "calib/core/camera_calibration.h"
#include "calib/core/photometric_model.h"
#include "calib/core/polar_remap.h"
#include "core/fir_design.h"
#include "core/light_clustering.h"
#include "core/light_generator.h"
#include "core/sampling_tables.h"
#include "core/temporal_filter.h"
#include "frames/captured_frame.h"
#include "frames/loop_control.h"
#include "frames/processed_frame.h"
#include "frames/processing_options.h"

namespace vem::vemd {

// The polar map's size limits. Start-up builds the polar remap (about 0.2 us and 12 bytes per map
// pixel) and every frame writes the map and its importance tables (about 17 bytes per pixel
// more), so time and memory grow with width x height; these bounds keep the largest map inside
// the unit's start timeout and vemd's memory budget (docs/vemd.md, "Limits", has the measured
// table).
inline constexpr int kMinMapSide = 4;
inline constexpr int kMaxMapWidth = 4096;
inline constexpr int kMaxMapHeight = 2048;

// Stage names in the order they run, as ProcessedFrame::timings lists them.
inline constexpr const char* kStageNames[] = {"calibrate", "tables", "lights", "filter", "cluster"};

class Pipeline final : public PipelineControl {
 public:
  // Builds the remap for `calibration` (`sourceName` names its camera in messages). Fails with
  // one sentence when the calibration lacks its photometric or geometric section, or the options
  // are out of range. `stopRequested`, when given, is asked between the rows of the
  // remap (the long part of start-up): true abandons the build, which then fails saying so.
  [[nodiscard]] static std::expected<Pipeline, std::string> create(
      calib::CameraCalibration calibration, const std::string& sourceName,
      const ProcessingOptions& options, const std::function<bool()>& stopRequested = {});

  // Why `frame` cannot be processed (another size or pixel format than the camera's, or codes
  // above the format's largest), or nullopt when it can. process() requires nullopt.
  [[nodiscard]] std::optional<std::string> frameProblem(const RawFrame& frame) const;

  // Runs every stage on `frame`. The result, and the map it points to, stay valid until the next
  // call; `captured` must outlive the use of the result (it is borrowed).
  [[nodiscard]] const ProcessedFrame& process(const CapturedFrame& captured);

  // Changes the options between frames, resetting only what changed: the light count and the
  // sampler take effect with the next frame; another filter preset starts a new filter (its
  // history is gone, so the next frames publish unfiltered lights until it fills); clustering
  // follows its new parameters; another map size rebuilds the polar remap. Fails, changing
  // nothing, with processingOptionsProblem's sentence.
  [[nodiscard]] std::expected<void, std::string> reconfigure(
      const ProcessingOptions& options) override;

  [[nodiscard]] const calib::CameraCalibration& calibration() const { return calibration_; }
  [[nodiscard]] const ProcessingOptions& options() const override { return options_; }
  [[nodiscard]] double filterDelayFrames() const override { return filter_.delayFrames(); }
  [[nodiscard]] std::uint64_t lutRebuilds() const { return lutRebuilds_; }

 private:
  Pipeline(calib::CameraCalibration calibration, const ProcessingOptions& options,
           calib::PolarRemap remap);

  void calibrate(const RawFrame& frame);
  void sample();
  void filter(std::uint64_t seq);
  void cluster();

  calib::CameraCalibration calibration_;
  ProcessingOptions options_;
  calib::PolarRemap remap_;
  calib::CodeToLuminanceLut lut_;
  bool lutValid_ = false;
  std::uint64_t lutRebuilds_ = 0;
  EnvMap polar_;
  SamplingTables tables_;
  // The lights' cells (light_cells.h): rebuilt only when the light count or the sampler changes.
  LightCells cells_;
  SamplerKind cellsSampler_ = SamplerKind::Havran;
  TemporalFilter filter_;
  ClusteringParams clusteringParams_;
  ProcessedFrame result_;
};

// One sentence naming the first option out of range, or nullopt.
[[nodiscard]] std::optional<std::string> processingOptionsProblem(const ProcessingOptions& options);

}  // namespace vem::vemd
