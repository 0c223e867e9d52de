// `vemtool info F.vem`: what a VEM recording holds (docs/vem-format.md): its header, frame count,
// time span and rate, sequence and timestamp gaps, damaged records and the state of its index.
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <fmt/chrono.h>
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "recording/recording_reader.h"
#include "util/printable.h"

namespace vem::tool {
namespace {

struct InfoOptions {
  std::string input;
  bool json = false;
};

// ISO 8601 UTC to the millisecond, "2026-12-03T14:30:36.123Z", through fmt's chrono support (its
// time points print whole seconds; the seconds of the minute print as a duration with the ms).
std::string isoUtcMs(std::int64_t unixNs) {
  using namespace std::chrono;
  const auto ms = floor<milliseconds>(sys_time<nanoseconds>(nanoseconds(unixNs)));
  return fmt::format("{:%Y-%m-%dT%H:%M:}{:%S}Z", floor<seconds>(ms), ms - floor<minutes>(ms));
}

// "seq goes back from 10 to 5 at frame 7 of 90 (byte 123456)" and the like.
std::string disorderText(const recording::SequenceDisorder& d, std::uint64_t frames) {
  const std::string where = fmt::format("at frame {} of {} (byte {})", d.frame, frames, d.offset);
  switch (d.step) {
    case recording::SequenceStep::Repeat: return fmt::format("seq {} repeats {}", d.toSeq, where);
    case recording::SequenceStep::Wrap:
      return fmt::format("seq wraps from {} to {} {}", d.fromSeq, d.toSeq, where);
    default: return fmt::format("seq goes back from {} to {} {}", d.fromSeq, d.toSeq, where);
  }
}

nlohmann::ordered_json disorderJson(const std::optional<recording::SequenceDisorder>& d) {
  if (!d) return nullptr;
  return {{"kind", recording::sequenceStepName(d->step)},
          {"from_seq", d->fromSeq},
          {"to_seq", d->toSeq},
          {"frame", d->frame},
          {"offset", d->offset}};
}

nlohmann::ordered_json summaryJson(const std::string& file, const recording::RecordingSummary& s) {
  const recording::RecordingHeader& h = s.header;
  nlohmann::ordered_json j;
  j["file"] = util::printable(file);  // a file name need not be UTF-8, which JSON must be
  j["format_version"] = h.formatVersion;
  j["file_bytes"] = s.fileBytes;
  j["camera"] = {{"model", h.cameraModel}, {"serial", h.cameraSerial}};
  j["sensor"] = {{"width_px", h.sensorWidthPx},
                 {"height_px", h.sensorHeightPx},
                 {"pixel_format", pixelFormatName(h.pixelFormat)}};
  j["nominal_rate_hz"] = h.nominalRateHz;
  j["calibration_toml_bytes"] = h.calibrationToml.size();
  j["created_unix_ns"] = h.createdUnixNs;
  j["created_utc"] = isoUtcMs(h.createdUnixNs);
  j["writer"] = {{"name", h.writerName}, {"version", h.writerVersion}};
  j["frames"] = s.frames;
  j["frames_with_lights"] = s.framesWithLights;
  j["first_seq"] = s.firstSeq ? nlohmann::ordered_json(*s.firstSeq) : nullptr;
  j["last_seq"] = s.lastSeq ? nlohmann::ordered_json(*s.lastSeq) : nullptr;
  j["first_ts_ns"] = s.firstTsNs ? nlohmann::ordered_json(*s.firstTsNs) : nullptr;
  j["last_ts_ns"] = s.lastTsNs ? nlohmann::ordered_json(*s.lastTsNs) : nullptr;
  j["mean_rate_hz"] = s.meanRateHz;
  j["sequence_gaps"] = s.sequenceGaps;
  j["missing_frames"] = s.missingFrames;
  j["sequence_disorders"] = s.sequenceDisorders;
  j["first_sequence_disorder"] = disorderJson(s.firstDisorder);
  j["timestamp_gaps"] = s.timestampGaps;
  j["longest_interval_ns"] = s.longestIntervalNs;
  j["damaged_records"] = s.damage.damagedRecords;
  j["damaged_bytes"] = s.damage.damagedBytes;
  j["truncated_tail_bytes"] = s.damage.truncatedTailBytes;
  j["unknown_records"] = s.damage.unknownRecords;
  j["index"] = recording::indexStateName(s.index);
  j["index_entries"] = s.indexEntries;
  return j;
}

std::string summaryText(const std::string& file, const recording::RecordingSummary& s) {
  const recording::RecordingHeader& h = s.header;
  // Names from outside (the file's, and those the header holds) are made printable.
  using util::printable;
  std::string t = fmt::format("{}: VEM recording, format version {}, {} bytes\n", printable(file),
                              h.formatVersion, s.fileBytes);
  t += fmt::format("camera:      {} (serial {}), {} x {} {}, nominal {} Hz\n",
                   printable(h.cameraModel), printable(h.cameraSerial), h.sensorWidthPx,
                   h.sensorHeightPx, pixelFormatName(h.pixelFormat), h.nominalRateHz);
  t += fmt::format("calibration: {}\n",
                   h.calibrationToml.empty()
                       ? std::string("none")
                       : fmt::format("{} bytes of TOML", h.calibrationToml.size()));
  t += fmt::format("writer:      {} {}, created {}\n", printable(h.writerName),
                   printable(h.writerVersion), isoUtcMs(h.createdUnixNs));
  t += fmt::format("frames:      {}", s.frames);
  if (s.firstSeq) t += fmt::format(" (seq {} .. {})", *s.firstSeq, *s.lastSeq);
  t += fmt::format(", {} with lights\n", s.framesWithLights);
  if (s.firstTsNs) {
    t += fmt::format("time:        {:.3f} s, mean rate {:.3f} Hz\n",
                     (double(*s.lastTsNs) - double(*s.firstTsNs)) * 1e-9, s.meanRateHz);
  }
  t += fmt::format(
      "gaps:        {} in sequence ({} frames missing, {} out of order), {} in time (> 1.5 frame "
      "periods; longest interval {:.3f} ms)\n",
      s.sequenceGaps, s.missingFrames, s.sequenceDisorders, s.timestampGaps,
      double(s.longestIntervalNs) * 1e-6);
  if (s.firstDisorder) {
    t += fmt::format("order:       first out of order: {}\n",
                     disorderText(*s.firstDisorder, s.frames));
  }
  t += fmt::format(
      "damage:      {} damaged records ({} bytes skipped), truncated tail {} bytes, {} "
      "unknown records\n",
      s.damage.damagedRecords, s.damage.damagedBytes, s.damage.truncatedTailBytes,
      s.damage.unknownRecords);
  t += fmt::format("index:       {}", recording::indexStateName(s.index));
  if (s.index == recording::IndexState::Valid || s.index == recording::IndexState::Stale) {
    t += fmt::format(" ({} entries)", s.indexEntries);
  }
  if (s.index != recording::IndexState::Valid) t += "; `vemtool recover` rebuilds it";
  return t + "\n";
}

int runInfo(const InfoOptions& o) {
  auto reader = recording::RecordingReader::open(o.input);
  if (!reader) {
    spdlog::error("{}", reader.error().message);
    return EXIT_FAILURE;
  }
  auto summary = reader->summarize();
  if (!summary) {
    spdlog::error("{}", summary.error().message);
    return EXIT_FAILURE;
  }
  if (o.json) {
    std::cout << summaryJson(o.input, *summary).dump(2) << '\n';
  } else {
    std::cout << summaryText(o.input, *summary);
  }
  return std::cout.good() ? EXIT_SUCCESS : EXIT_FAILURE;
}

}  // namespace

void addInfoCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand(
      "info", "Describe a VEM recording: header, frames, rate, gaps, damage, index");
  cmd->footer(
      "Example:\n  vemtool info session.vem --format json\n"
      "Reads every record (checking each CRC32C) but decompresses no pixels.");
  cmd->add_option("file", options->input, "The recording (.vem)")->required();
  cmd->add_option_function<std::string>(
         "--format", [options](const std::string& f) { options->json = f == "json"; },
         "text (default) | json")
      ->check(CLI::IsMember({"text", "json"}));
  cmd->callback([options, &exitCode] { exitCode = runInfo(*options); });
}

}  // namespace vem::tool
