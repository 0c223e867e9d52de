#include "util/owner_only_file.h"

#include <sys/stat.h>

#include <fstream>
#include <sstream>

#include "util/printable.h"

namespace vem::util {

std::expected<std::string, std::string> readOwnerOnlyFile(const std::filesystem::path& path,
                                                          std::string_view field) {
  const std::string prefix = std::string(field) + ": " + printable(path.string());
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return std::unexpected(prefix + ": cannot read it");
  if ((info.st_mode & (S_IRWXG | S_IRWXO)) != 0) {
    std::ostringstream mode;
    mode << std::oct << (info.st_mode & 07777);
    return std::unexpected(prefix + " can be read by group or others (mode " + mode.str() +
                           "); allow its owner only (chmod 600)");
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) return std::unexpected(prefix + ": cannot read it");
  return text.str();
}

}  // namespace vem::util
