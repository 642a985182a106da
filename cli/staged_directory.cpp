#include "cli/staged_directory.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "compiler/literal.hpp"

namespace wg {

namespace {
std::string systemError(const std::string& what, const std::filesystem::path& path) {
  return what + " '" + quoteUserText(path.string(), 300) + "': " + std::strerror(errno);
}
}  // namespace

StagedDirectory::~StagedDirectory() {
  std::error_code ec;
  if (!staging_.empty()) std::filesystem::remove_all(staging_, ec);
  if (published_) return;
  // A failed run leaves no folder it made; remove() only takes empty ones.
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) std::filesystem::remove(*it, ec);
}

std::string StagedDirectory::ensureStaging() {
  if (!staging_.empty()) return "";
  std::error_code ec;
  for (std::filesystem::path p = std::filesystem::absolute(directory_, ec); !p.empty() && !std::filesystem::exists(p, ec);
       p = p.parent_path())
    created_.insert(created_.begin(), p);
  std::filesystem::create_directories(directory_, ec);
  if (ec) return "cannot create the output directory '" + quoteUserText(directory_.string(), 300) + "': " + ec.message();
  std::string pattern = (directory_ / ".weathergen-staging-XXXXXX").string();
  if (!::mkdtemp(pattern.data())) return systemError("cannot create a staging folder in", directory_);
  staging_ = pattern;
  return "";
}

namespace {
// Whether `path` is a regular file (not followed through a link) holding exactly `bytes`
// that this process may touch: its owner's or root's (another user's file, even one in
// our own folder, is replaced as a rewrite would). Read a chunk at a time into one small
// buffer, so comparing allocates nothing and stops at the first difference.
bool keepsExactly(const std::filesystem::path& path, std::string_view bytes) {
  int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st {};
  const uid_t self = ::geteuid();
  bool same = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && (st.st_uid == self || self == 0) &&
              static_cast<std::size_t>(st.st_size) == bytes.size();
  char chunk[64 * 1024];
  for (std::size_t done = 0; same && done < bytes.size();) {
    ssize_t n = ::read(fd, chunk, std::min(sizeof chunk, bytes.size() - done));
    if (n < 0 && errno == EINTR) continue;
    same = n > 0 && std::memcmp(chunk, bytes.data() + done, static_cast<std::size_t>(n)) == 0;
    done += same ? static_cast<std::size_t>(n) : 0;
  }
  ::close(fd);
  return same;
}
}  // namespace

std::string StagedDirectory::stage(const std::string& name, std::string_view bytes) {
  // An unchanged output is not written again, only touched on publishing: a warm
  // rebuild is its reads, not the disk's file creation (docs/BENCHMARKS.md, "Compile
  // speed").
  if (keepsExactly(directory_ / name, bytes)) {
    unchanged_.push_back(name);
    return "";
  }
  if (std::string e = ensureStaging(); !e.empty()) return e;
  std::filesystem::path path = staging_ / name;
  int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) return systemError("cannot write", directory_ / name);
  for (std::size_t done = 0; done < bytes.size();) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      std::string e = systemError("cannot write", directory_ / name);
      ::close(fd);
      return e;
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0) return systemError("cannot write", directory_ / name);
  names_.push_back(name);
  return "";
}

// One syncfs for every staged file, before any is renamed into place, so a crash cannot
// leave an empty or partial file under a final name. An fsync per file made importing
// 3,000 materials take 10 s on a busy disk (docs/BENCHMARKS.md).
std::string StagedDirectory::syncStaged() {
  if (names_.empty()) return "";
  int fd = ::open(staging_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return systemError("cannot open the staging folder", staging_);
  const bool synced = ::syncfs(fd) == 0;
  std::string error = synced ? "" : systemError("cannot write", directory_);
  ::close(fd);
  return error;
}

std::string StagedDirectory::readyToPublish() {
  if (ready_) return "";
  if (std::string e = syncStaged(); !e.empty()) return e;
  for (const auto& name : names_) {
    std::filesystem::path target = directory_ / name;
    std::error_code ec;
    if (std::filesystem::is_directory(std::filesystem::symlink_status(target, ec)))
      return "cannot write '" + quoteUserText(target.string(), 300) + "': a directory has that name";
  }
  ready_ = true;
  return "";
}

std::string StagedDirectory::publish() {
  if (std::string e = readyToPublish(); !e.empty()) return e;
  // Now, as a rewrite would have, so that make and ninja see these outputs as fresh;
  // before any rename, so that a touch that fails leaves the folder's bytes as they were.
  for (const auto& name : unchanged_)
    if (::utimensat(AT_FDCWD, (directory_ / name).c_str(), nullptr, AT_SYMLINK_NOFOLLOW) != 0)
      return systemError("cannot write", directory_ / name);
  published_ = true;  // from here on the folder holds output, whatever happens next
  for (const auto& name : names_)
    if (::rename((staging_ / name).c_str(), (directory_ / name).c_str()) != 0) return systemError("cannot write", directory_ / name);
  return "";
}

}  // namespace wg
