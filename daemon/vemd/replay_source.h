// ReplaySource: a VEM recording (docs/vem-format.md) played back as a frame source, bit for bit:
// the codes, exposure and gain as recorded, so replaying gives the lights the live run gave.
//
// - Opening reads the first intact frame: a recording that holds none is refused then, in one
//   sentence naming the file, rather than replayed as an empty run.
// - Pace (SourceRate): "recorded" keeps the recording's timestamp spacing, a number of Hz a fixed
//   period, "max" none at all (the daemon then takes frames as fast as it processes them). At the
//   recorded pace a capture time that jumps back, or ahead by more than 10 s, is replayed as one
//   nominal frame period (FrameSchedule); the first of a run of such jumps is logged as a warning,
//   and the end of the run with their count.
// - Loop: at the end the recording starts again; seq and captureTsNs keep increasing across laps
//   (each lap is shifted to follow the previous one by one frame period), so the temporal filter
//   sees one continuous stream. Without loop the end is EndOfStream.
// - seq and captureTsNs are the recording's (shifted on later laps), on the recording's clock;
//   arrivalNs is when next() handed the frame over. Damaged records are skipped by the reader
//   (damagedRecords() counts them).
// - Buffers: recycled frames lend their code buffers to the next decode (no allocation per frame
//   in a steady stream).
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frames/frame_source.h"
#include "recording/recording_reader.h"
#include "vemd/pacer.h"
#include "vemd/source_rate.h"

namespace vem::vemd {

struct ReplayOptions {
  SourceRate rate;
  bool loop = false;
};

class ReplaySource final : public FrameSource {
 public:
  // Opens the recording; NoDevice with the reader's sentence when it cannot.
  [[nodiscard]] static std::expected<std::unique_ptr<ReplaySource>, SourceError> open(
      const std::filesystem::path& path, const ReplayOptions& options);

  [[nodiscard]] SourceDescription describe() const override;
  [[nodiscard]] std::expected<CapturedFrame, SourceError> next() override;
  void recycle(CapturedFrame&& spent) override;
  void interrupt() override;

  [[nodiscard]] std::uint64_t laps() const { return laps_; }
  [[nodiscard]] std::uint64_t damagedRecords() const;

 private:
  ReplaySource(recording::RecordingReader reader, const ReplayOptions& options);
  // Reads the next frame into recorded_, starting a new lap at the end when looping.
  [[nodiscard]] std::expected<bool, SourceError> readNext();
  // Logs the first of a run of capture-time jumps, and the end of the run with its count.
  void reportJump(const std::optional<TimestampJump>& jump);
  void startNextLap();
  [[nodiscard]] std::int64_t lapPeriodNs() const;

  recording::RecordingReader reader_;
  ReplayOptions options_;
  std::string name_;  // the file's name, printable (util/printable.h), for messages
  recording::RecordedFrame recorded_;
  std::vector<std::vector<std::uint16_t>> spareCodes_;
  Pacer pacer_;
  FrameSchedule schedule_;
  bool frameRead_ = false;     // recorded_ holds the first frame, read by open()
  bool frameWaiting_ = false;  // recorded_ holds a frame read before an interrupted wait
  std::int64_t waitingDueNs_ = 0;
  std::uint64_t jumpsInARow_ = 0;  // capture-time jumps since the last regular step

  // Laps: the first and last frame of the lap so far (recording's numbers) and the shift of the
  // current lap.
  std::uint64_t laps_ = 0;
  std::uint64_t framesThisLap_ = 0;
  std::uint64_t firstSeq_ = 0, lastSeq_ = 0;
  std::int64_t firstTsNs_ = 0, lastTsNs_ = 0;
  std::uint64_t seqShift_ = 0;
  std::int64_t tsShiftNs_ = 0;
  std::uint64_t damagedBeforeLap_ = 0;
};

}  // namespace vem::vemd
