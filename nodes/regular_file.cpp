#include "nodes/regular_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace wg {

FileRead inspectRegularFile(const std::string& path) {
  std::error_code ec;
  auto status = std::filesystem::status(path, ec);
  if (ec == std::errc::too_many_symbolic_link_levels) return {FileReadStatus::Unreadable, "a loop of symbolic links"};
  if (ec && ec != std::errc::no_such_file_or_directory && ec != std::errc::not_a_directory)
    return {FileReadStatus::Unreadable, ec.message()};
  if (ec || !std::filesystem::exists(status)) return {FileReadStatus::NotFound, "no such file"};
  if (std::filesystem::is_directory(status)) return {FileReadStatus::NotRegular, "it is a directory"};
  if (!std::filesystem::is_regular_file(status)) return {FileReadStatus::NotRegular, "not a regular file (a FIFO, device or socket)"};
  std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return {FileReadStatus::Unreadable, ec.message()};
  return {FileReadStatus::Ok, "", size};
}

FileRead readRegularFile(const std::string& path, std::uintmax_t maxBytes, std::string& bytes) {
  FileRead kind = inspectRegularFile(path);
  if (kind.status != FileReadStatus::Ok) return kind;
  if (kind.size > maxBytes) return {FileReadStatus::TooLarge, "larger than the limit", kind.size};
  // O_NONBLOCK and a second look at what was opened: a FIFO swapped in since the
  // inspection cannot block the read. The size is the opened file's too: a file renamed
  // over the path since (an editor's save, a cache writer) is read whole, not cut to
  // the old one's size.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return {FileReadStatus::Unreadable, std::strerror(errno)};
  struct stat opened {};
  if (::fstat(fd, &opened) != 0 || !S_ISREG(opened.st_mode)) {
    ::close(fd);
    return {FileReadStatus::NotRegular, "not a regular file (a FIFO, device or socket)"};
  }
  const auto size = static_cast<std::uintmax_t>(opened.st_size);
  if (size > maxBytes) {
    ::close(fd);
    return {FileReadStatus::TooLarge, "larger than the limit", size};
  }
  // Into the caller's string, so one kept from call to call reuses its memory. A file
  // that grows while it is read is read only up to the measured size.
  bytes.resize(size);
  std::size_t done = 0;
  int readError = 0;
  while (done < size) {
    const ssize_t n = ::read(fd, bytes.data() + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) readError = errno;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  ::close(fd);
  if (readError != 0) return {FileReadStatus::Unreadable, std::strerror(readError)};
  if (done != size) return {FileReadStatus::Unreadable, "it shrank while being read"};
  return {FileReadStatus::Ok, "", size};
}

}  // namespace wg
