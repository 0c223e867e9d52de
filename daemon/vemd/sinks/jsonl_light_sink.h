// JsonlLightSink: appends one JSON object per processed frame to a file, one line each, flushed
// (written to the kernel with one write()) per line, so `tail -f` and a crash both see whole lines.
//
// A line is the `vemtool lights` object (docs/conventions.md, light_json.h) with
// vemd's frame identity added after "frame":
//
//   {"frame":F,"seq":S,"capture_ts_ns":T,"filtered":true,"filtered_seq":S2,"count":N,
//    "lights":[{"id":K,"dir":[x,y,z],"rgb":[r,g,b]},...]}
//
// - "frame" counts the lines this sink wrote (0, 1, ...); "seq" and "capture_ts_ns" are the
//   captured frame's (frames/captured_frame.h: the source's sequence number, its clock in ns).
// - The lights are the published ones (published_lights.h): the temporal filter's output when the
//   frame has one ("filtered":true, and "filtered_seq" the frame they stand for), else the frame's
//   own lights ("filtered":false).
// - With a clustering, each light is a cluster with "members", and the line adds "clustered_from"
//   and "radius_rad", the radius e that frame's clustering was made with (so a cluster budget
//   changed while vemd runs shows from the next line on), as `vemtool lights --cluster` does.
// - Floats are written in their shortest round-trip form: parsing a number back as float gives the
//   light's float exactly.
//
// The file is opened for appending (a restarted vemd continues it). A write error (ENOSPC, EIO,
// a closed pipe) is returned once as a SinkFailure; the partial line is cut off again when the
// file allows it, and the sink does nothing from then on.
#pragma once

#include <cstdint>
#include <expected>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "frames/sink.h"
#include "util/unique_fd.h"

namespace vem::vemd {

// The line (without its newline) for `frame`, the sink's `line`-th.
[[nodiscard]] nlohmann::ordered_json lightsLineJson(const ProcessedFrame& frame,
                                                    std::uint64_t line);

class JsonlLightSink final : public Sink {
 public:
  // Opens (creating, 0644) `path` for appending; fails with one sentence when it cannot.
  [[nodiscard]] static std::expected<JsonlLightSink, SinkFailure> open(
      const std::filesystem::path& path);

  [[nodiscard]] std::string name() const override { return "jsonl"; }
  [[nodiscard]] std::expected<void, SinkFailure> consume(const ProcessedFrame& frame) override;
  [[nodiscard]] std::expected<void, SinkFailure> close() override;

  [[nodiscard]] std::uint64_t linesWritten() const { return lines_; }

 private:
  JsonlLightSink(std::filesystem::path path, util::UniqueFd fd);
  [[nodiscard]] SinkFailure fail(const std::string& what, int error);

  std::filesystem::path path_;
  util::UniqueFd fd_;
  std::uint64_t lines_ = 0;
  bool failed_ = false;
};

}  // namespace vem::vemd
