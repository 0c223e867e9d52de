// The benchmark programs' markdown output: printed to stdout and, with --report FILE.md, written
// to that file too (the `bench` target includes it in docs/BENCHMARKS.md).
#pragma once

#include <string>

namespace vem::bench {

// Prints `markdown` and writes it to `reportPath` unless that is empty. False, with one sentence
// on stderr naming `program` and the file, when the file cannot be written.
[[nodiscard]] bool emitMarkdown(const std::string& program, const std::string& markdown,
                                const std::string& reportPath);

}  // namespace vem::bench
