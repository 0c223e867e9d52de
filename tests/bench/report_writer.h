// Formats docs/BENCHMARKS.md from the measured times and the accuracy study, and draws the
// accuracy-against-time plot as an SVG beside it.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace vem::bench {

struct ReportInputs {
  const std::map<std::string, double>& timesUs;     // benchmark name -> microseconds (median)
  const std::map<std::string, double>& minTimesUs;  // the fastest repetition, where measured
  std::vector<std::size_t> counts;                  // the N of the accuracy study
  std::vector<std::string> includedSections;  // markdown made by other programs (--include)
};

// The markdown text; writes accuracy-vs-time.svg into `docsDir`.
[[nodiscard]] std::string writeReport(const ReportInputs& inputs,
                                      const std::filesystem::path& docsDir);

}  // namespace vem::bench
