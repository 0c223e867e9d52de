// The fuzzers' --write-seeds=DIR mode (.ci/fuzz.sh): before libFuzzer starts, write a few valid
// inputs into DIR as the corpus's seeds and exit 0.
#pragma once

#include <cstdlib>
#include <cstring>
#include <string>

namespace vem::fuzz {

// Call from LLVMFuzzerInitialize: when an argument is --write-seeds=DIR, calls writeSeeds(DIR) and
// exits 0; otherwise returns and libFuzzer goes on.
template <class WriteSeeds>
void handleWriteSeedsOption(int argc, char** argv, WriteSeeds writeSeeds) {
  constexpr const char kOption[] = "--write-seeds=";
  constexpr std::size_t kOptionLength = sizeof(kOption) - 1;
  for (int i = 1; i < argc; ++i) {
    if (std::strncmp(argv[i], kOption, kOptionLength) == 0) {
      writeSeeds(std::string(argv[i] + kOptionLength));
      std::exit(0);
    }
  }
}

}  // namespace vem::fuzz
