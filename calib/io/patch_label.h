// How a [[patch]] table of a patch list is named in messages (internal to vem_calibio), shared by
// the grey-patch file (patch_file.h) and the plate's colour-patch file (plate_colour_file.h):
// "patch 3" until its name is known, then "patch \"p3\"".
#pragma once

#include <cstddef>
#include <string>

#include <toml++/toml.h>

namespace vem::calib::io::detail {

[[nodiscard]] std::string patchLabel(std::size_t index, const toml::table& table);

}  // namespace vem::calib::io::detail
