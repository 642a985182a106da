#include "nodes/regular_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

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
  const std::uintmax_t size = kind.size;
  if (size > maxBytes) return {FileReadStatus::TooLarge, "larger than the limit", size};
  std::ifstream in(path, std::ios::binary);
  if (!in) return {FileReadStatus::Unreadable, std::strerror(errno)};
  bytes.resize(size);
  // A file that grew since it was measured is read only up to the measured size.
  if (size && !in.read(bytes.data(), static_cast<std::streamsize>(size))) return {FileReadStatus::Unreadable, "read error"};
  return {FileReadStatus::Ok, "", size};
}

}  // namespace wg
