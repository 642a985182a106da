// The files and data: URIs a glTF names for its buffers and images. Every reference is
// checked before anything is read: data: URIs must be strict base64 of an allowed media
// type, and a relative path must stay inside the model's folder (no "..", no absolute
// path, no NUL), name a regular file and fit the size limit. The same confinement
// guards the file callbacks tinygltf reads through.
#pragma once
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "compiler/json_document.hpp"

namespace wg::gltf {

// Largest model, external buffer or image file read (bytes).
inline constexpr std::uintmax_t kMaxResourceBytes = 512ull << 20;

// Checks every buffers[*].uri and images[*].uri, and that only a .glb's first buffer
// (its BIN chunk of `glbBinBytes`) goes without one; reports WG5004. False on error.
bool checkResourceUris(const JsonDocument& document, const std::filesystem::path& folder,
                       std::optional<std::size_t> glbBinBytes, DiagnosticList& diagnostics);

// The files a checked document reads (external buffers and images), resolved inside
// `folder` and percent-decoded as the checks read them.
std::vector<std::filesystem::path> externalFiles(const JsonDocument& document, const std::filesystem::path& folder);

// `path` resolved inside `folder`, or "" if it leaves it (through "..", an absolute
// path or a symbolic link).
std::filesystem::path confinedPath(const std::filesystem::path& folder, const std::string& path);

// What keeps an encoded PNG or JPEG from being read as compile reads it, from its header
// alone (at least 1x1, at most kMaxImageFileDimension a side, and a header stb_image
// reads: a paletted PNG's includes its palette); nullopt when it can be read.
// `overLimit`: the size is the problem (WG5007 in glTF) rather than the bytes.
struct ImageHeaderProblem {
  bool overLimit = false;
  std::string message, hint;
};
struct ImageHeader {
  int width = 0, height = 0, components = 0;
};
std::optional<ImageHeaderProblem> imageHeaderProblem(const unsigned char* bytes, std::size_t size, bool png, ImageHeader& header);

// Reads a whole regular file of at most kMaxResourceBytes; "" or the reason it failed.
std::string readWholeFile(const std::filesystem::path& path, std::vector<std::uint8_t>& out);

}  // namespace wg::gltf
