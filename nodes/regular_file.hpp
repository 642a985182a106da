// Reading an input file whole, safely: only a regular file (a FIFO would block, a
// device like /dev/zero would never end), with its size checked before reading.
#pragma once
#include <cstdint>
#include <string>

namespace wg {

enum class FileReadStatus { Ok, NotFound, NotRegular, TooLarge, Unreadable };

struct FileRead {
  FileReadStatus status = FileReadStatus::Ok;
  std::string reason;  // one line for the user, without the path: "no such file", ...
  std::uintmax_t size = 0;
};

// What `path` is, without reading it: Ok with its size for a regular file; otherwise
// NotFound, NotRegular ("it is a directory", "not a regular file (a FIFO, device or
// socket)") or Unreadable ("a loop of symbolic links", permissions...).
FileRead inspectRegularFile(const std::string& path);

// Reads `path` into `bytes` when it is a regular file of at most maxBytes.
FileRead readRegularFile(const std::string& path, std::uintmax_t maxBytes, std::string& bytes);

}  // namespace wg
