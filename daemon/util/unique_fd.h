// UniqueFd: owns one POSIX file descriptor and closes it when it goes (RAII); movable, not
// copyable. -1 means "none". close() closes now and reports what close(2) said, since a deferred
// write error (NFS, some disks) may only show there.
#pragma once

namespace vem::util {

class UniqueFd {
 public:
  UniqueFd() = default;
  explicit UniqueFd(int fd) : fd_(fd) {}
  UniqueFd(UniqueFd&& other) noexcept;
  UniqueFd& operator=(UniqueFd&& other) noexcept;
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;
  ~UniqueFd() { reset(); }

  [[nodiscard]] int get() const { return fd_; }
  [[nodiscard]] bool valid() const { return fd_ >= 0; }
  // Closes the one held (ignoring close(2)'s answer) and holds `fd` instead.
  void reset(int fd = -1);
  // Closes now; false (errno set) when close(2) reports an error. True when none was held.
  [[nodiscard]] bool close();

 private:
  int fd_ = -1;
};

}  // namespace vem::util
