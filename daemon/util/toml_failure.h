// TomlFailure: the first thing wrong in a TOML file, as toml_reader.h reports it: a cause and one
// sentence naming the file, the field and what was expected
// ("cam.toml: geometric.k: expected 5 values (k1 to k5), found 4"). Kept apart from the reader so
// that error types can name it without seeing toml++.
#pragma once

#include <string>

namespace vem::util {

enum class TomlProblem {
  BadSyntax,       // not TOML at all
  UnknownVersion,  // a format version this program does not read
  MissingField,    // a required key or section is absent
  WrongUnit,       // a quantity in another unit than the field's
  BadValue,        // the wrong type, out of range, an unknown key, ...
};

struct TomlFailure {
  TomlProblem cause = TomlProblem::BadValue;
  std::string message;
};

}  // namespace vem::util
