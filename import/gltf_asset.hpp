// One glTF 2.0 file (.gltf or .glb), read and checked as a whole before anything uses
// it: the container, the JSON (with every location kept for diagnostics), the schema
// and every index, the required extensions, the buffers and images it names, and the
// node hierarchy. tinygltf (Debian's libtinygltf) does the parsing; the checks around
// it make a hostile file a diagnostic instead of a crash, a hang or a read outside the
// model's folder.
#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <tiny_gltf.h>
#include <vector>

#include "compiler/diagnostic.hpp"
#include "compiler/json_document.hpp"

namespace wg::gltf {

// An image as the file holds it: PNG or JPEG bytes, never re-encoded.
struct EncodedImage {
  std::vector<std::uint8_t> bytes;
  std::string extension;  // ".png" or ".jpg"
  int width = 0, height = 0;
};

struct Asset {
  std::string file;  // as the user named it
  std::shared_ptr<const JsonDocument> document;
  tinygltf::Model model;
  std::vector<EncodedImage> images;  // parallel to model.images

  SourceLocation locate(const std::string& pointer) const { return document->locate(pointer); }
  // The model file and every external buffer and image it reads, resolved.
  std::vector<std::filesystem::path> inputFiles() const;
};

// Extensions a model may list in extensionsRequired: their meaning is read.
bool canReadRequiredExtension(std::string_view name);

// Reads and checks `path`; on any error returns nullopt with diagnostics (WG1001,
// WG1002, WG1007, WG5001-WG5007).
std::optional<Asset> loadAsset(const std::string& path, DiagnosticList& diagnostics);

}  // namespace wg::gltf
