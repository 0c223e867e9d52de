// vemd replaying a recording as fast as possible (docs/vemd.md, docs/BENCHMARKS.md): 30 frames of
// the synthetic sky scene seen by a 1280 x 1024 Mono16 log camera (190-degree lens, read noise),
// recorded with RecordingWriter into a temporary file, then replayed through vemd's own loop:
// the capture thread reads and decompresses (ReplaySource at --rate max), one processing thread
// runs the pipeline (1024 x 256 polar map, 1024 Havran lights, Paper9 filter, clustering Q = 72)
// with no sinks. Registered as "vemd/replay_max_Mono16"; one iteration replays the 30 frames three
// times (--loop --frames 90); counters: frames_per_s, and each stage's mean microseconds per frame
// ("us_<stage>", including "us_read" for reading and decompressing one frame on the capture
// thread). Also "vemd/pipeline_Mono16": the pipeline alone, one frame per iteration, frames already
// in memory.
#pragma once

#include <map>
#include <string>

namespace vem::bench {

void registerVemdBenchmarks();

// The markdown section for docs/BENCHMARKS.md from the last runs (report_writer can append it).
[[nodiscard]] std::string vemdReportSection();

// The counters of the last run of "vemd/replay_max_Mono16" (empty before it ran), for the report.
[[nodiscard]] const std::map<std::string, double>& vemdBenchmarkCounters();

}  // namespace vem::bench
