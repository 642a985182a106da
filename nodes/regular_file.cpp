#include "compiler/regular_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace wg {

FileRead readRegularFile(const std::string& path, std::uintmax_t maxBytes, std::string& bytes) {
  std::error_code ec;
  auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) return {FileReadStatus::NotFound, "no such file"};
  if (std::filesystem::is_directory(status)) return {FileReadStatus::NotRegular, "it is a directory"};
  if (!std::filesystem::is_regular_file(status)) return {FileReadStatus::NotRegular, "not a regular file (a FIFO, device or socket)"};
  std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return {FileReadStatus::Unreadable, ec.message()};
  if (size > maxBytes) return {FileReadStatus::TooLarge, "larger than the limit", size};
  std::ifstream in(path, std::ios::binary);
  if (!in) return {FileReadStatus::Unreadable, std::strerror(errno)};
  bytes.resize(size);
  // A file that grew since it was measured is read only up to the measured size.
  if (size && !in.read(bytes.data(), static_cast<std::streamsize>(size))) return {FileReadStatus::Unreadable, "read error"};
  return {FileReadStatus::Ok, "", size};
}

}  // namespace wg
