// makeSource: the frame source a `--source` spec names, opened and ready:
//   replay:FILE       a VEM recording (replay_source.h), at source.rate, looping with source.loop
//   synthetic:SCENE   a synthetic scene through a simulated camera (synthetic_source.h)
// Fails with one sentence naming the spec and what was expected, or why the source cannot open.
#pragma once

#include <expected>
#include <memory>
#include <string>
#include <string_view>

#include "vemd/frame_source.h"
#include "vemd/vemd_config.h"

namespace vem::vemd {

struct SourceSpec {
  enum class Kind { Replay, Synthetic };
  Kind kind = Kind::Replay;
  std::string argument;  // the file, or the scene
};

// "replay:FILE" or "synthetic:SCENE" split; a sentence when it is neither.
[[nodiscard]] std::expected<SourceSpec, std::string> parseSourceSpec(std::string_view spec);

[[nodiscard]] std::expected<std::unique_ptr<FrameSource>, std::string> makeSource(
    const SourceConfig& config);

}  // namespace vem::vemd
