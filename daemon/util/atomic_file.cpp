#include "util/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <random>

#include "util/unique_fd.h"
#include "util/write_all.h"

namespace vem::util {
namespace {

// Built by append(): GCC 12 at -O3 warns falsely (-Wrestrict) on operator+ chains of strings.
FileReplaceFailure failure(const std::filesystem::path& target, std::string step, int error) {
  FileReplaceFailure out{error, std::move(step), {}};
  out.message.append(target.string())
      .append(": ")
      .append(out.step)
      .append(" (")
      .append(std::strerror(error))
      .append("); any earlier file there is unchanged");
  return out;
}

// ".<name>.tmp-<pid>-<count>-<random>" beside the target: hidden, unique to this call.
std::filesystem::path temporarySibling(const std::filesystem::path& target) {
  static std::atomic<unsigned> count{0};
  const unsigned salt = std::random_device{}();
  std::string name = ".";
  name.append(target.filename().string())
      .append(".tmp-")
      .append(std::to_string(::getpid()))
      .append("-")
      .append(std::to_string(count++))
      .append("-")
      .append(std::to_string(salt));
  return target.parent_path() / name;
}

}  // namespace

std::string FileReplaceFailure::reason() const {
  std::string out = step;
  out.append(": ").append(std::strerror(error));
  return out;
}

std::expected<std::filesystem::path, FileReplaceFailure> writeTemporarySibling(
    const std::filesystem::path& target, std::span<const std::byte> bytes) {
  const std::filesystem::path temporary = temporarySibling(target);
  UniqueFd fd(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666));
  if (!fd.valid())
    return std::unexpected(failure(target, "cannot create a temporary file beside it", errno));
  const char* step = nullptr;
  int error = 0;
  if (auto written = writeAll(fd.get(), bytes); !written) {
    step = "cannot write the temporary file";
    error = written.error().error;
  } else if (::fsync(fd.get()) != 0) {
    step = "cannot flush the temporary file";
    error = errno;
  } else if (!fd.close()) {
    step = "cannot close the temporary file";
    error = errno;
  }
  if (step == nullptr) return temporary;
  fd.reset();
  ::unlink(temporary.c_str());
  return std::unexpected(failure(target, step, error));
}

std::expected<void, FileReplaceFailure> renameOver(const std::filesystem::path& temporary,
                                                   const std::filesystem::path& target) {
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    return std::unexpected(failure(target, "cannot rename the temporary file over it", error));
  }
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  const UniqueFd dir(::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (dir.valid()) ::fsync(dir.get());  // makes the rename durable; best effort
  return {};
}

std::expected<void, FileReplaceFailure> replaceFileAtomically(const std::filesystem::path& target,
                                                              std::span<const std::byte> bytes) {
  auto temporary = writeTemporarySibling(target, bytes);
  if (!temporary) return std::unexpected(std::move(temporary.error()));
  return renameOver(*temporary, target);
}

}  // namespace vem::util
