// vem_bench: the light pipeline's benchmarks (Google Benchmark) and the accuracy study, written as
// one markdown report. `cmake --build build --target bench` runs it into docs/BENCHMARKS.md.
//   vem_bench [--report FILE] [google benchmark flags...]
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/chrono.h>
#include <fmt/format.h>

#include "accuracy_study.h"
#include "bench_fixtures.h"
#include "calib_benchmarks.h"
#include "recording_benchmarks.h"
#include "report_writer.h"
#include "stage_benchmarks.h"
#include "vemd_benchmarks.h"

namespace {

// Keeps each benchmark's real time per iteration (microseconds) by name: the median of the
// repetitions when there are several, else the single run's mean.
class CapturingReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.error_occurred) continue;
      const double toMicro = run.time_unit == benchmark::kMillisecond  ? 1e3
                             : run.time_unit == benchmark::kNanosecond ? 1e-3
                                                                       : 1.0;
      const double us = run.GetAdjustedRealTime() * toMicro;
      const std::string name = run.run_name.str();
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "min") {
        minTimesUs[name] = us;
      } else if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") {
        timesUs[name] = us;
        medians.insert(name);
      } else if (run.run_type == Run::RT_Iteration && !medians.contains(name)) {
        timesUs[name] = us;
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, double> timesUs;
  std::map<std::string, double> minTimesUs;  // fastest repetition, where computed
  std::set<std::string> medians;
};

}  // namespace

int main(int argc, char** argv) {
  std::string reportPath;
  std::vector<std::string> included;  // --include FILE: a markdown section another program made
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--report") == 0 && i + 1 < argc) {
      reportPath = argv[++i];
    } else if (std::strcmp(argv[i], "--include") == 0 && i + 1 < argc) {
      std::ifstream section(argv[++i]);
      std::ostringstream text;
      text << section.rdbuf();
      if (!section) {
        std::cerr << "vem_bench: --include " << argv[i] << ": cannot read the file\n";
        return 1;
      }
      included.push_back(text.str());
    } else {
      args.push_back(argv[i]);
    }
  }
  int benchArgc = int(args.size());
  benchmark::Initialize(&benchArgc, args.data());
  if (vem::bench::sharedHdris().empty()) {
    std::cerr << "vem_bench: no HDRIs found under " << VEM_SHARED_DATA_DIR
              << "/hdri; the accuracy study needs them\n";
    return 1;
  }
  const std::vector<std::size_t> counts{16, 64, 256, 1024, 4096};
  vem::bench::registerStageBenchmarks();
  vem::bench::registerCalibrationBenchmarks();
  vem::bench::registerRecordingBenchmarks();
  vem::bench::registerVemdBenchmarks();
  vem::bench::registerAccuracyTimingBenchmarks(counts);
  CapturingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  if (reportPath.empty()) return 0;

  vem::bench::ReportInputs inputs{reporter.timesUs, reporter.minTimesUs, counts, included};
  std::ofstream out(reportPath);
  out << vem::bench::writeReport(inputs, std::filesystem::path(reportPath).parent_path());
  if (!out) {
    std::cerr << "vem_bench: could not write " << reportPath << "\n";
    return 1;
  }
  std::cerr << "vem_bench: wrote " << reportPath << "\n";
  return 0;
}
