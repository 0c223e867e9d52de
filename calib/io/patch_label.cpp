#include "calib/io/patch_label.h"

namespace vem::calib::io::detail {

std::string patchLabel(std::size_t index, const toml::table& table) {
  const toml::node* name = table.get("name");
  if (name != nullptr && name->is_string()) return "patch \"" + name->as_string()->get() + "\"";
  return "patch " + std::to_string(index + 1);
}

}  // namespace vem::calib::io::detail
