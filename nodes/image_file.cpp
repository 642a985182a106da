#include "nodes/image_file.hpp"

#include "nodes/png_header.hpp"
#include "nodes/regular_file.hpp"

#include <stb_image.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string_view>
#include <system_error>

namespace wg {

namespace {

constexpr std::string_view kUnsupportedFormat =
    "unsupported image format (supported: PNG, JPEG, TGA, BMP)";

enum class Format { Png, Jpeg, Tga, Bmp, Other };

// stb_image also decodes GIF, PSD, HDR, PIC and PNM; the format is decided here from the
// file's signature so that only the four formats the project documents are accepted.
constexpr std::array<unsigned char, 8> kPngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
constexpr std::array<unsigned char, 3> kJpegSignature = {0xFF, 0xD8, 0xFF};  // SOI + marker
constexpr std::array<unsigned char, 2> kBmpSignature = {'B', 'M'};

template <std::size_t N>
bool startsWith(const std::vector<unsigned char>& head, const std::array<unsigned char, N>& sig) {
  return head.size() >= N && std::equal(sig.begin(), sig.end(), head.begin());
}

bool hasTgaExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".tga";
}

std::vector<unsigned char> readHead(FILE* file) {
  std::vector<unsigned char> head(kPngHeaderBytes);  // the longest header read here
  head.resize(std::fread(head.data(), 1, head.size(), file));
  return head;
}

using OpenFile = std::unique_ptr<FILE, int (*)(FILE*)>;

Format detectFormat(const std::string& path, const std::vector<unsigned char>& head) {
  if (startsWith(head, kPngSignature)) return Format::Png;
  if (startsWith(head, kJpegSignature)) return Format::Jpeg;
  if (startsWith(head, kBmpSignature)) return Format::Bmp;
  // TGA has no signature; trust the extension and let stb_image check the header.
  if (hasTgaExtension(path)) return Format::Tga;
  return Format::Other;
}

std::string_view formatName(Format format) {
  switch (format) {
    case Format::Png: return "PNG";
    case Format::Jpeg: return "JPEG";
    case Format::Tga: return "TGA";
    case Format::Bmp: return "BMP";
    case Format::Other: break;
  }
  return "image";
}

std::string stbReason() {
  const char* reason = stbi_failure_reason();
  return reason ? reason : "unknown error";
}

ImageFileStatus tooLarge(int w, int h, int& width, int& height, std::string& error) {
  width = w;  // reported so the caller can show the actual size
  height = h;
  error = "image is " + std::to_string(w) + "x" + std::to_string(h) + ", larger than the " +
          std::to_string(kMaxImageFileDimension) + "x" + std::to_string(kMaxImageFileDimension) +
          " limit; resize it";
  return ImageFileStatus::TooLarge;
}

// A PNG's size is read from its IHDR before stb sees it, so a header claiming
// 60000x60000 is reported as too large rather than as an unreadable file.
std::optional<ImageFileStatus> checkPngHeader(const std::vector<unsigned char>& head, int& width,
                                              int& height, std::string& error) {
  const auto declared = pngDeclaredSize(head.data(), head.size());
  if (!declared) {
    error = "cannot read PNG header: no IHDR chunk after the signature";
    return ImageFileStatus::Unsupported;
  }
  const auto limit = static_cast<unsigned>(kMaxImageFileDimension);
  if (declared->width > limit || declared->height > limit) {
    constexpr unsigned kShownMax = 1u << 30;  // keeps the reported size an int
    return tooLarge(static_cast<int>(std::min(declared->width, kShownMax)),
                    static_cast<int>(std::min(declared->height, kShownMax)), width, height, error);
  }
  return std::nullopt;
}

// The image's format and size from one open file, read through one open file: the header
// checks and stb_image's own use it, so a compile opens each image once.
ImageFileStatus probeOpenImage(FILE* file, const std::string& path, int& width, int& height, std::string& error) {
  const std::vector<unsigned char> head = readHead(file);
  const Format format = detectFormat(path, head);
  if (format == Format::Other) {
    error = kUnsupportedFormat;
    return ImageFileStatus::Unsupported;
  }
  if (format == Format::Png) {
    if (auto status = checkPngHeader(head, width, height, error)) return *status;
  }
  int w = 0, h = 0, channels = 0;
  std::rewind(file);
  if (!stbi_info_from_file(file, &w, &h, &channels)) {  // stb_image seeks back to the start
    if (format == Format::Tga) {
      error = kUnsupportedFormat;  // a .tga name on something that is not a TGA
    } else {
      error = "cannot read " + std::string(formatName(format)) + " header: " + stbReason();
    }
    return ImageFileStatus::Unsupported;
  }
  if (w > kMaxImageFileDimension || h > kMaxImageFileDimension)
    return tooLarge(w, h, width, height, error);
  width = w;
  height = h;
  return ImageFileStatus::Ok;
}

// A regular file, opened; null with the status and error set otherwise.
OpenFile openImageFile(const std::string& path, ImageFileStatus& status, std::string& error) {
  OpenFile none(nullptr, &std::fclose);
  if (FileRead kind = inspectRegularFile(path); kind.status != FileReadStatus::Ok) {
    error = kind.status == FileReadStatus::NotFound ? "file not found" : kind.reason;
    status = kind.status == FileReadStatus::NotFound ? ImageFileStatus::NotFound : ImageFileStatus::Unsupported;
    return none;
  }
  OpenFile file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) {
    error = "cannot open the file";
    status = ImageFileStatus::Unsupported;
  }
  return file;
}

}  // namespace

ImageFileStatus probeImageFile(const std::string& path, int& width, int& height,
                               std::string& error) {
  width = height = 0;
  ImageFileStatus status = ImageFileStatus::Ok;
  OpenFile file = openImageFile(path, status, error);
  if (!file) return status;
  return probeOpenImage(file.get(), path, width, height, error);
}

std::optional<Image> loadImageFile(const std::string& path, std::string& error) {
  int width = 0, height = 0;
  ImageFileStatus status = ImageFileStatus::Ok;
  OpenFile file = openImageFile(path, status, error);
  if (!file || probeOpenImage(file.get(), path, width, height, error) != ImageFileStatus::Ok) return std::nullopt;
  int w = 0, h = 0, fileChannels = 0;
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_file(file.get(), &w, &h, &fileChannels, kImageChannels), &stbi_image_free);
  if (!pixels) {
    error = "cannot decode image: " + stbReason();
    return std::nullopt;
  }
  if (w != width || h != height) {  // the file changed between probe and load
    error = "image size changed while loading";
    return std::nullopt;
  }
  Image image = Image::blank(w, h);
  std::memcpy(image.rgba.data(), pixels.get(), image.rgba.size());
  return image;
}

}  // namespace wg
