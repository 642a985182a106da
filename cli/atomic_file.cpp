#include "cli/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "compiler/literal.hpp"

namespace wg {

namespace {

std::string failure(const char* what, const std::string& path, int error) {
  return std::string(what) + " '" + quoteUserText(path, 300) + "': " + std::strerror(error);
}

// A temporary beside `path`, created exclusively and never through a link: a name
// someone planted (a symlink to a file of theirs) is skipped, never written through.
int createTemporary(const std::string& path, std::string& temp) {
  static std::atomic<unsigned> counter{0};
  constexpr int kAttempts = 16;
  for (int i = 0; i < kAttempts; ++i) {
    temp = path + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

bool writeAll(int fd, std::string_view bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

std::string writeFileAtomically(const std::string& path, std::string_view bytes) {
  std::string temp;
  int fd = createTemporary(path, temp);
  if (fd < 0) return failure("cannot create a temporary file for", path, errno);
  // fsync before the rename, so a crash cannot leave an empty file under the final name.
  bool ok = writeAll(fd, bytes) && ::fsync(fd) == 0;
  int error = errno;
  ok = (::close(fd) == 0) && ok;
  if (ok && ::rename(temp.c_str(), path.c_str()) == 0) return "";
  error = ok ? errno : error;
  ::unlink(temp.c_str());
  return failure("cannot write", path, error);
}

}  // namespace wg
