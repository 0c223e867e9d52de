#include "bench/markdown_output.h"

#include <fstream>
#include <iostream>

namespace vem::bench {

bool emitMarkdown(const std::string& program, const std::string& markdown,
                  const std::string& reportPath) {
  std::cout << markdown;
  if (reportPath.empty()) return true;
  std::ofstream out(reportPath);
  out << markdown;
  if (!out) {
    std::cerr << program << ": cannot write " << reportPath << "\n";
    return false;
  }
  return true;
}

}  // namespace vem::bench
