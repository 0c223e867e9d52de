// QuietStdErr: keeps std::cerr quiet for the scope of one call. OpenCV 4.6's imread and imdecode
// print their own line to std::cerr when a file fails to decode (hard-coded, not through its
// logger), while our error value already says it in one sentence. Not thread-safe: std::cerr is
// one global stream; use it only where files are read from one thread.
#pragma once

#include <iostream>
#include <sstream>

namespace vem::util {

class QuietStdErr {
 public:
  QuietStdErr() : saved_(std::cerr.rdbuf(sink_.rdbuf())) {}
  ~QuietStdErr() { std::cerr.rdbuf(saved_); }
  QuietStdErr(const QuietStdErr&) = delete;
  QuietStdErr& operator=(const QuietStdErr&) = delete;

 private:
  std::ostringstream sink_;
  std::streambuf* saved_;
};

}  // namespace vem::util
