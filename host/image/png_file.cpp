#include "host/image/png_file.hpp"

#include <stb_image_write.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include "nodes/image_file.hpp"

namespace wg::image {

namespace {

namespace fs = std::filesystem;

constexpr std::array<unsigned char, 8> kPngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

using File = std::unique_ptr<FILE, int (*)(FILE*)>;

// Unique within the process (counter) and across processes (pid); hidden and
// recognisable so a crash mid-write leaves an obvious leftover rather than a PNG.
fs::path temporaryPathFor(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return target.parent_path() / name;
}

void appendBytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

std::string errnoText() { return std::strerror(errno); }

// Writes `bytes` to a new file at `path`; "" or an error (the file may be left behind).
std::string writeNewFile(const fs::path& path, const std::string& bytes) {
  // "x": fail rather than clobber if the name is somehow taken.
  File file(std::fopen(path.c_str(), "wbx"), &std::fclose);
  if (!file) return errnoText();
  if (std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size()) return errnoText();
  // fclose flushes: its failure (e.g. disk full) is a failed write too.
  if (std::fclose(file.release()) != 0) return errnoText();
  return "";
}

}  // namespace

std::string encodePng(const Image& image, std::string& bytes) {
  if (!image.valid()) return "the image is empty or its buffer has the wrong size";
  if (image.width > kMaxPngDimension || image.height > kMaxPngDimension)
    return "the image is larger than " + std::to_string(kMaxPngDimension) + " pixels";
  bytes.clear();
  const int stride = image.width * kImageChannels;
  if (!stbi_write_png_to_func(&appendBytes, &bytes, image.width, image.height, kImageChannels, image.rgba.data(), stride))
    return "PNG encoding failed";
  return "";
}

std::string writePng(const std::string& path, const Image& image) {
  const std::string prefix = "cannot write " + path + ": ";
  const fs::path target(path);
  if (target.filename().empty()) return prefix + "not a file name";

  std::string encoded;
  if (std::string error = encodePng(image, encoded); !error.empty()) return prefix + error;

  const fs::path temporary = temporaryPathFor(target);
  std::error_code ignored;
  if (std::string error = writeNewFile(temporary, encoded); !error.empty()) {
    fs::remove(temporary, ignored);
    return prefix + error;
  }
  // rename() within one directory is atomic on POSIX: `path` is either the old file or
  // the complete new one.
  std::error_code renameError;
  fs::rename(temporary, target, renameError);
  if (renameError) {
    fs::remove(temporary, ignored);
    return prefix + renameError.message();
  }
  return "";
}

std::optional<Image> readPng(const std::string& path, std::string& error) {
  std::array<unsigned char, kPngSignature.size()> head{};
  {
    File file(std::fopen(path.c_str(), "rb"), &std::fclose);
    if (!file) {
      error = path + ": " + (errno == ENOENT ? std::string("file not found") : errnoText());
      return std::nullopt;
    }
    if (std::fread(head.data(), 1, head.size(), file.get()) != head.size() || head != kPngSignature) {
      error = path + ": not a PNG file";
      return std::nullopt;
    }
  }
  std::string loadError;
  std::optional<Image> image = loadImageFile(path, loadError);
  if (!image) error = path + ": " + loadError;
  return image;
}

}  // namespace wg::image
