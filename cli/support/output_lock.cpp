#include "output_lock.hpp"

#include <cerrno>
#include <cstring>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "output_files.hpp"

namespace rsi {
namespace {

/// The pid written in the lock file by its holder. The holder writes it just
/// after it locks, so a reader that comes in between sees an empty file:
/// retry for up to 100 ms before giving up ("unknown").
std::string holder_pid(int fd) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    char text[32] = {};
    const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
    if (n > 0) return std::string(text, static_cast<size_t>(n));
    ::usleep(1000);
  }
  return "unknown";
}

bool same_file(int fd, const std::string& path) {
  struct stat opened {};
  struct stat named {};
  return ::fstat(fd, &opened) == 0 && ::stat(path.c_str(), &named) == 0 &&
         opened.st_dev == named.st_dev && opened.st_ino == named.st_ino;
}

} // namespace

OutputLock::OutputLock(const std::string& dir, const std::string& option)
    : m_path(dir + "/.rsi-lock") {
  for (;;) {
    // O_CLOEXEC: a child (the report script) must not inherit the lock.
    const int fd = ::open(m_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw OutputError(option + " " + dir + ": cannot create the lock file " + m_path + " (" +
                        std::strerror(errno) + ")");
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int error = errno;
      const std::string pid = error == EWOULDBLOCK ? holder_pid(fd) : std::string();
      ::close(fd);
      if (error == EWOULDBLOCK)
        throw OutputError(option + " " + dir + ": another rsi run (pid " + pid + ") is writing it");
      throw OutputError(option + " " + dir + ": cannot lock " + m_path + " (" +
                        std::strerror(error) + ")");
    }
    // The previous holder may have unlinked the file between our open and
    // our flock: then this lock guards nothing, try again.
    if (same_file(fd, m_path)) {
      m_fd = fd;
      break;
    }
    ::close(fd);
  }
  const std::string pid = std::to_string(::getpid());
  if (::ftruncate(m_fd, 0) != 0 ||
      ::pwrite(m_fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    const std::string why = std::strerror(errno);
    ::unlink(m_path.c_str());
    ::close(m_fd);
    throw OutputError(option + " " + dir + ": cannot write the lock file " + m_path + " (" + why +
                      ")");
  }
}

OutputLock::~OutputLock() {
  // Unlink first: once the file is gone, a run that opened it before can
  // still lock it but sees that the path no longer names it.
  ::unlink(m_path.c_str());
  ::close(m_fd);
}

} // namespace rsi
