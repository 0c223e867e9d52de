// The [[patch]] tables of a patch list (internal to vem_calibio), shared by the grey-patch file
// (patch_file.h) and the plate's colour-patch file (plate_colour_file.h): how a table is named in
// messages, "patch 3" until its name is known, then "patch \"p3\"", and the loop that reads them.
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include <toml++/toml.h>

#include "util/toml_reader.h"

namespace vem::calib::io::detail {

[[nodiscard]] std::string patchLabel(std::size_t index, const toml::table& table);

// The patches of a list whose root holds [[patch]] tables alone, each read by `readPatch(reader)`
// (a util::TomlReader named by patchLabel, on the root's `status`) into a value with a `name`,
// until the first problem; a name used by an earlier patch is refused.
template <typename ReadPatch>
[[nodiscard]] auto readPatchTables(util::TomlReader& root, util::TomlStatus& status,
                                   ReadPatch readPatch)
    -> std::vector<std::invoke_result_t<ReadPatch&, util::TomlReader>> {
  root.onlyKeys({"patch"});
  const toml::array* tables = root.tableArray("patch");
  std::vector<std::invoke_result_t<ReadPatch&, util::TomlReader>> patches;
  std::set<std::string> names;
  for (std::size_t i = 0; tables != nullptr && i < tables->size() && status.ok(); ++i) {
    const toml::table& table = *tables->get(i)->as_table();
    util::TomlReader patch(table, patchLabel(i, table) + ": ", status);
    patches.push_back(readPatch(patch));
    patch.require(!status.ok() || names.insert(patches.back().name).second, "name",
                  "the name is used by an earlier patch too (expected unique names)");
  }
  return patches;
}

}  // namespace vem::calib::io::detail
