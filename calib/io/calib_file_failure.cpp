#include "calib/io/calib_file_failure.h"

namespace vem::calib::io {

const char* calibFileErrorName(CalibFileError error) {
  switch (error) {
    case CalibFileError::NotFound: return "not found";
    case CalibFileError::Unreadable: return "unreadable";
    case CalibFileError::BadSyntax: return "bad syntax";
    case CalibFileError::UnknownVersion: return "unknown version";
    case CalibFileError::MissingField: return "missing field";
    case CalibFileError::WrongUnit: return "wrong unit";
    case CalibFileError::BadValue: return "bad value";
    case CalibFileError::WriteFailed: return "write failed";
  }
  return "unknown";
}

}  // namespace vem::calib::io
