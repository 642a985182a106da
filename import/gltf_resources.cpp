#include "import/gltf_resources.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <string_view>

#include <stb_image.h>

#include "compiler/literal.hpp"
#include "nodes/image_file.hpp"
#include "nodes/png_header.hpp"
#include "nodes/regular_file.hpp"

namespace wg::gltf {

namespace {

std::string stbReason() {
  const char* reason = stbi_failure_reason();
  return reason ? reason : "unknown error";
}

// Width and height from the header alone. PNG's IHDR is read directly: stb refuses to
// even report sizes it would not decode, and the limit's message should name the size.
bool headerSize(const unsigned char* bytes, int size, bool png, ImageHeader& header) {
  if (!png) return stbi_info_from_memory(bytes, size, &header.width, &header.height, &header.components) != 0;
  const auto declared = pngDeclaredSize(bytes, static_cast<std::size_t>(size));
  constexpr std::uint32_t kLargest = 1u << 30;
  if (!declared || declared->width > kLargest || declared->height > kLargest) return false;
  header = {static_cast<int>(declared->width), static_cast<int>(declared->height), 4};
  return true;
}

bool isBase64Char(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '/';
}

// Strict RFC 4648 base64: the alphabet, whole quads, and '=' only as final padding.
std::string base64Problem(std::string_view data) {
  if (data.size() % 4 != 0) return "its length " + std::to_string(data.size()) + " is not a multiple of 4";
  std::size_t padding = 0;
  while (padding < 2 && padding < data.size() && data[data.size() - 1 - padding] == '=') ++padding;
  for (std::size_t i = 0; i + padding < data.size(); ++i)
    if (!isBase64Char(data[i])) return "character " + std::to_string(i) + " is not base64";
  return "";
}

// "data:MEDIA;base64,PAYLOAD": "" or what is wrong.
std::string dataUriProblem(std::string_view uri, bool image) {
  std::size_t comma = uri.find(',');
  if (comma == std::string_view::npos) return "the data: URI has no ',' before its data";
  std::string_view header = uri.substr(5, comma - 5);
  constexpr std::string_view kBase64 = ";base64";
  if (!header.ends_with(kBase64)) return "the data: URI is not base64-encoded";
  std::string_view media = header.substr(0, header.size() - kBase64.size());
  bool allowed = image ? (media == "image/png" || media == "image/jpeg")
                       : (media == "application/octet-stream" || media == "application/gltf-buffer");
  if (!allowed)
    return "media type '" + quoteUserText(media) + "' is not " +
           (image ? "image/png or image/jpeg" : "application/octet-stream or application/gltf-buffer");
  if (std::string p = base64Problem(uri.substr(comma + 1)); !p.empty()) return "the data: URI is not valid base64: " + p;
  return "";
}

int hexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Percent-decodes a URI reference; "" in `problem` unless it is malformed or holds NUL.
std::string percentDecode(std::string_view uri, std::string& problem) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      out += uri[i];
      continue;
    }
    int hi = i + 2 < uri.size() ? hexValue(uri[i + 1]) : -1, lo = i + 2 < uri.size() ? hexValue(uri[i + 2]) : -1;
    if (hi < 0 || lo < 0) {
      problem = "a '%' is not followed by two hex digits";
      return "";
    }
    out += static_cast<char>(hi * 16 + lo);
    i += 2;
  }
  if (out.find('\0') != std::string::npos) problem = "the path holds a NUL character";
  return out;
}

// "" or what is wrong with a relative file reference.
std::string fileUriProblem(std::string_view uri, const std::filesystem::path& folder) {
  std::string problem;
  std::string path = percentDecode(uri, problem);
  if (!problem.empty()) return problem;
  if (path.empty()) return "the URI is empty";
  if (uri.find("://") != std::string_view::npos || uri.starts_with("file:")) return "only relative file paths are read, not URLs";
  // tinygltf decodes '+' as a space (form encoding, not RFC 3986), so it would look
  // for another file; %2B reaches it as '+'.
  if (uri.find('+') != std::string_view::npos) return "the reader takes '+' in a URI for a space; write it as %2B";
  std::filesystem::path resolved = confinedPath(folder, path);
  if (resolved.empty()) return "the path leaves the model's folder; images and buffers must sit beside the model or below it";
  std::error_code ec;
  auto status = std::filesystem::status(resolved, ec);
  if (ec || !std::filesystem::exists(status)) return "no such file beside the model";
  if (!std::filesystem::is_regular_file(status)) return "it is not a regular file";
  if (std::filesystem::file_size(resolved, ec) > kMaxResourceBytes) return "the file is larger than 512 MiB";
  return "";
}

// A buffer without a uri is the GLB's BIN chunk, which only buffer 0 may be.
std::string missingUriProblem(std::size_t index, std::optional<std::size_t> glbBinBytes) {
  if (index == 0 && glbBinBytes) return "";
  if (index == 0) return "it has no uri, and the file has no GLB BIN chunk for it";
  return "it has no uri; only the first buffer of a .glb may use its BIN chunk";
}

void checkUris(const JsonDocument& doc, const char* collection, bool image, const std::filesystem::path& folder,
               std::optional<std::size_t> glbBinBytes, DiagnosticList& diags, bool& ok) {
  auto it = doc.root().find(collection);
  if (it == doc.root().end() || !it->is_array()) return;
  for (std::size_t i = 0; i < it->size(); ++i) {
    const auto& element = (*it)[i];
    auto uri = element.find("uri");
    if (!image && uri == element.end()) {
      if (std::string problem = missingUriProblem(i, glbBinBytes); !problem.empty()) {
        ok = false;
        diags.report(DiagCode::GltfResource, doc.locate(appendPointer("/buffers", i)),
                     {"buffer " + std::to_string(i), problem, "give the buffer a uri, or store the model as a .glb"});
      }
      continue;
    }
    if (uri == element.end() || !uri->is_string()) continue;
    std::string text = uri->get<std::string>();
    std::string problem = text.starts_with("data:") ? dataUriProblem(text, image) : fileUriProblem(text, folder);
    if (problem.empty()) continue;
    ok = false;
    std::string pointer = appendPointer(appendPointer(appendPointer("", collection), i), "uri");
    diags.report(DiagCode::GltfResource, doc.locate(pointer),
                 {std::string(image ? "image " : "buffer ") + std::to_string(i) + " ('" + quoteUserText(text) + "')", problem,
                  "fix the URI, or re-export the model as a self-contained .glb"});
  }
}

}  // namespace

std::optional<ImageHeaderProblem> imageHeaderProblem(const unsigned char* bytes, std::size_t size, bool png, ImageHeader& header) {
  const int shown = static_cast<int>(std::min<std::size_t>(size, INT32_MAX));  // stb takes an int; a header is near the start
  if (!headerSize(bytes, shown, png, header)) return ImageHeaderProblem{false, "its header cannot be read", "re-save the image"};
  const std::string size_text = "its header claims " + std::to_string(header.width) + "x" + std::to_string(header.height) + " pixels";
  if (header.width < 1 || header.height < 1) return ImageHeaderProblem{true, size_text + "; an image has at least 1x1", "re-save the image"};
  if (header.width > kMaxImageFileDimension || header.height > kMaxImageFileDimension)
    return ImageHeaderProblem{true, size_text + "; the limit is " + std::to_string(kMaxImageFileDimension) + " on each side",
                              "resize the image to at most 8192 pixels on each side"};
  // As compile probes it: for a paletted PNG stb reads on to the palette.
  if (int w, h, n; !stbi_info_from_memory(bytes, shown, &w, &h, &n))
    return ImageHeaderProblem{false, "its header cannot be read (" + stbReason() + ")", "re-save the image"};
  return std::nullopt;
}

std::filesystem::path confinedPath(const std::filesystem::path& folder, const std::string& path) {
  std::filesystem::path relative(path);
  if (relative.is_absolute() || relative.has_root_name()) return {};
  std::error_code ec;
  std::filesystem::path root = std::filesystem::weakly_canonical(folder, ec);
  if (ec) return {};
  std::filesystem::path resolved = std::filesystem::weakly_canonical(root / relative, ec);
  if (ec) return {};
  auto [rootEnd, unused] = std::mismatch(root.begin(), root.end(), resolved.begin(), resolved.end());
  return rootEnd == root.end() ? resolved : std::filesystem::path{};
}

std::string readWholeFile(const std::filesystem::path& path, std::vector<std::uint8_t>& out) {
  std::string bytes;
  FileRead read = readRegularFile(path.string(), kMaxResourceBytes, bytes);
  if (read.status == FileReadStatus::TooLarge) return "larger than 512 MiB";
  if (read.status != FileReadStatus::Ok) return read.reason;
  out.assign(bytes.begin(), bytes.end());
  return "";
}

bool checkResourceUris(const JsonDocument& document, const std::filesystem::path& folder,
                       std::optional<std::size_t> glbBinBytes, DiagnosticList& diagnostics) {
  bool ok = true;
  checkUris(document, "buffers", false, folder, glbBinBytes, diagnostics, ok);
  checkUris(document, "images", true, folder, glbBinBytes, diagnostics, ok);
  return ok;
}

std::vector<std::filesystem::path> externalFiles(const JsonDocument& document, const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const char* collection : {"buffers", "images"}) {
    auto it = document.root().find(collection);
    if (it == document.root().end()) continue;
    for (const auto& element : *it) {
      auto uri = element.find("uri");
      if (uri == element.end() || !uri->is_string() || uri->get<std::string>().starts_with("data:")) continue;
      std::string problem;
      std::string path = percentDecode(uri->get<std::string>(), problem);
      if (std::filesystem::path resolved = confinedPath(folder, path); problem.empty() && !resolved.empty()) files.push_back(resolved);
    }
  }
  return files;
}

}  // namespace wg::gltf
