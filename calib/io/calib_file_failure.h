// The error value of every calibration-side file operation: a cause and one sentence naming the
// file, the field and what was expected.
#pragma once

#include <string>

namespace vem::calib::io {

enum class CalibFileError {
  NotFound,
  Unreadable,
  BadSyntax,
  UnknownVersion,
  MissingField,
  WrongUnit,
  BadValue,
  WriteFailed,
};

[[nodiscard]] const char* calibFileErrorName(CalibFileError error);

struct CalibFileFailure {
  CalibFileError cause;
  std::string message;
};

}  // namespace vem::calib::io
