#include "import/gltf_asset.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "compiler/literal.hpp"
#include "import/glb_container.hpp"
#include "import/gltf_resources.hpp"
#include "import/gltf_schema.hpp"
#include "import/node_hierarchy.hpp"
#include "nodes/regular_file.hpp"

namespace wg::gltf {

namespace {

constexpr JsonLimits kJsonLimits{64u << 20, 64};  // glTF JSON of large scenes runs to tens of MiB

// Why an image was refused: unreadable (WG5004) or past a limit (WG5007).
struct ImageProblem {
  DiagCode code = DiagCode::GltfResource;
  std::string message, hint;
};

// What the tinygltf callbacks share: the model's folder and the images they accept.
struct LoadContext {
  std::filesystem::path folder;
  std::vector<EncodedImage> images;
  std::vector<ImageProblem> imageErrors;  // per image index; empty message when fine
  std::size_t imageBytes = 0;            // kept so far, against kMaxImageBytes
};

// Every image is kept encoded; many images may share one large buffer view.
constexpr std::size_t kMaxImageBytes = 1ull << 30;
// The buffers together, as they declare them.
constexpr std::uint64_t kMaxBufferBytes = 1ull << 30;

std::string imageExtension(const unsigned char* bytes, int size) {
  static constexpr std::array<unsigned char, 8> kPng = {0x89, 'P', 'N', 'G', 0x0D, 0x0A, 0x1A, 0x0A};
  if (size >= 8 && std::memcmp(bytes, kPng.data(), kPng.size()) == 0) return ".png";
  if (size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF) return ".jpg";
  return "";
}

// Keeps the encoded bytes; reads only the header (the graph loader decodes later, with
// its own limits), so a header claiming 60000x60000 pixels allocates nothing.
bool acceptImage(tinygltf::Image* image, const int index, std::string* err, std::string*, int, int,
                 const unsigned char* bytes, int size, void* user) {
  auto& ctx = *static_cast<LoadContext*>(user);
  if (index < 0) return false;
  auto slot = static_cast<std::size_t>(index);
  if (ctx.images.size() <= slot) ctx.images.resize(slot + 1), ctx.imageErrors.resize(slot + 1);
  EncodedImage& out = ctx.images[slot];
  out.extension = imageExtension(bytes, size);
  ImageProblem& problem = ctx.imageErrors[slot];
  constexpr auto kUnreadable = DiagCode::GltfResource, kInvalidData = DiagCode::GltfInvalidData;
  ImageHeader header;
  if (out.extension.empty()) problem = {kUnreadable, "it is neither PNG nor JPEG", "store images as PNG or JPEG"};
  else if (auto bad = imageHeaderProblem(bytes, static_cast<std::size_t>(size), out.extension == ".png", header))
    problem = {bad->overLimit ? kInvalidData : kUnreadable, bad->message, bad->hint};
  else if (ctx.imageBytes + static_cast<std::size_t>(size) > kMaxImageBytes)
    problem = {kInvalidData, "the model's images together exceed the limit of 1 GiB", "make the images smaller or fewer"};
  out.width = header.width;
  out.height = header.height;
  if (!problem.message.empty()) {
    *err += "image " + std::to_string(index) + ": " + problem.message;
    return false;
  }
  ctx.imageBytes += static_cast<std::size_t>(size);
  out.bytes.assign(bytes, bytes + size);
  image->width = out.width;
  image->height = out.height;
  image->component = header.components;
  return true;
}

bool fileExists(const std::string& path, void* user) {
  auto& ctx = *static_cast<LoadContext*>(user);
  return !confinedPath(ctx.folder, std::filesystem::path(path).lexically_relative(ctx.folder).string()).empty() &&
         inspectRegularFile(path).status == FileReadStatus::Ok;
}

std::string expandPath(const std::string& path, void*) { return path; }  // no ~ or $VAR expansion

bool readConfined(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  auto& ctx = *static_cast<LoadContext*>(user);
  std::filesystem::path inside = confinedPath(ctx.folder, std::filesystem::path(path).lexically_relative(ctx.folder).string());
  if (inside.empty()) {
    *err += "refused to read outside the model's folder";
    return false;
  }
  std::vector<std::uint8_t> bytes;
  if (std::string e = readWholeFile(inside, bytes); !e.empty()) {
    *err += e;
    return false;
  }
  out->assign(bytes.begin(), bytes.end());
  return true;
}

bool writeNothing(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  *err += "the importer never writes through tinygltf";
  return false;
}

bool checkRequiredExtensions(const JsonDocument& doc, DiagnosticList& diags) {
  auto it = doc.root().find("extensionsRequired");
  if (it == doc.root().end()) return true;
  bool ok = true;
  for (std::size_t i = 0; i < it->size(); ++i) {
    std::string name = (*it)[i].get<std::string>();
    if (canReadRequiredExtension(name)) continue;
    ok = false;
    std::string hint = name == "KHR_draco_mesh_compression"
                           ? "decompress the meshes first (for example 'gltf-transform decompress', or re-export from Blender without Draco)"
                           : "re-export the model without this extension";
    diags.report(DiagCode::GltfRequiredExtension, doc.locate(appendPointer("/extensionsRequired", i)), {quoteUserText(name), hint});
  }
  return ok;
}

// tinygltf hands an image its buffer view's bytes without checking that the view lies
// inside its buffer, so every view is checked against its buffer's declared byteLength
// first (tinygltf then insists each buffer holds exactly that many bytes). Unsigned
// comparisons that cannot overflow, whatever the file says.
bool checkDeclaredRanges(const JsonDocument& doc, DiagnosticList& diags) {
  const auto& root = doc.root();
  if (!root.contains("bufferViews")) return true;
  bool ok = true;
  const auto& views = root["bufferViews"];
  for (std::size_t i = 0; i < views.size(); ++i) {
    const auto& v = views[i];
    auto buffer = v["buffer"].get<std::size_t>();  // the schema check made it a valid index
    auto have = root["buffers"][buffer]["byteLength"].get<std::uint64_t>();
    auto offset = v.value("byteOffset", std::uint64_t{0}), length = v["byteLength"].get<std::uint64_t>();
    if (offset <= have && length <= have - offset) continue;
    ok = false;
    diags.report(DiagCode::GltfInvalidData, doc.locate(appendPointer("/bufferViews", i)),
                 {"buffer view " + std::to_string(i) + " (byteOffset " + std::to_string(offset) + ", byteLength " +
                      std::to_string(length) + ") does not fit buffer " + std::to_string(buffer) + " (" + std::to_string(have) +
                      " bytes)",
                  "re-export the model; its buffer views do not fit their buffers"});
  }
  return ok;
}

// tinygltf holds every buffer in memory, each as large as it declares (it refuses a file
// of another size), and forty buffers may name one 500 MiB file: their total is bounded
// before anything is read.
bool checkBufferTotal(const JsonDocument& doc, DiagnosticList& diags) {
  const auto& root = doc.root();
  if (!root.contains("buffers")) return true;
  const auto& buffers = root["buffers"];
  std::uint64_t total = 0;
  for (std::size_t i = 0; i < buffers.size(); ++i) {
    total += std::min(buffers[i]["byteLength"].get<std::uint64_t>(), kMaxBufferBytes + 1);  // the schema made it an integer
    if (total <= kMaxBufferBytes) continue;
    diags.report(DiagCode::ResourceLimit, doc.locate(appendPointer("/buffers", i)),
                 {"the size the buffers declare (buffers 0 to " + std::to_string(i) + ")", std::to_string(total) + " bytes", "1 GiB"});
    return false;
  }
  return true;
}

// tinygltf reports everything as text; images we refused have a better message already.
void reportParseFailure(const Asset& asset, const LoadContext& ctx, const std::string& err, DiagnosticList& diags) {
  bool reported = false;
  for (std::size_t i = 0; i < ctx.imageErrors.size(); ++i) {
    const ImageProblem& p = ctx.imageErrors[i];
    if (p.message.empty()) continue;
    reported = true;
    std::string pointer = appendPointer("/images", i), what = "image " + std::to_string(i);
    if (p.code == DiagCode::GltfInvalidData) diags.report(p.code, asset.locate(pointer), {what + ": " + p.message, p.hint});
    else diags.report(p.code, asset.locate(pointer), {what, p.message, p.hint});
  }
  if (!reported)
    diags.report(DiagCode::GltfContainer, asset.locate(""),
                 {quoteUserText(err, 300), "check that the file is glTF 2.0 and that its buffers are complete"});
}

bool parseWithTinygltf(Asset& asset, const std::vector<std::uint8_t>& bytes, bool glb, const std::filesystem::path& folder,
                       DiagnosticList& diags) {
  LoadContext ctx{folder, {}, {}};
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(acceptImage, &ctx);
  loader.SetFsCallbacks({fileExists, expandPath, readConfined, writeNothing, &ctx});
  std::string err, warn, base = folder.string();
  bool ok = glb ? loader.LoadBinaryFromMemory(&asset.model, &err, &warn, bytes.data(), static_cast<unsigned>(bytes.size()), base)
                : loader.LoadASCIIFromString(&asset.model, &err, &warn, asset.document->text().data(),
                                             static_cast<unsigned>(asset.document->text().size()), base);
  if (!ok) {
    reportParseFailure(asset, ctx, err, diags);
    return false;
  }
  ctx.images.resize(asset.model.images.size());
  // tinygltf only warns about an external image it cannot find, so every image must
  // have reached acceptImage.
  for (std::size_t i = 0; i < ctx.images.size(); ++i)
    if (ctx.images[i].bytes.empty()) {
      diags.report(DiagCode::GltfResource, asset.locate(appendPointer("/images", i)),
                   {"image " + std::to_string(i), "it could not be read (" + quoteUserText(warn, 200) + ")",
                    "check the file beside the model"});
      return false;
    }
  asset.images = std::move(ctx.images);
  return true;
}

// Every buffer holds the bytes it declares, so the checked views lie inside real data.
bool checkBufferRanges(const Asset& asset, DiagnosticList& diags) {
  bool ok = true;
  const auto& m = asset.model;
  for (std::size_t i = 0; i < m.buffers.size(); ++i) {
    // The schema check made byteLength present and an integer.
    auto byteLength = asset.document->root()["buffers"][i]["byteLength"].get<std::uint64_t>();
    if (m.buffers[i].data.size() >= byteLength) continue;
    ok = false;
    diags.report(DiagCode::GltfResource, asset.locate(appendPointer("/buffers", i)),
                 {"buffer " + std::to_string(i),
                  "it declares " + std::to_string(byteLength) + " bytes but holds " + std::to_string(m.buffers[i].data.size()),
                  "re-export the model; its binary data is truncated"});
  }
  return ok;
}

}  // namespace

std::vector<std::filesystem::path> Asset::inputFiles() const {
  std::filesystem::path model = std::filesystem::absolute(file);
  std::vector<std::filesystem::path> files{model};
  for (auto& f : externalFiles(*document, model.parent_path())) files.push_back(std::move(f));
  return files;
}

bool canReadRequiredExtension(std::string_view name) {
  return name == "KHR_texture_transform" || name == "KHR_materials_emissive_strength" || name == "KHR_mesh_quantization";
}

std::optional<Asset> loadAsset(const std::string& path, DiagnosticList& diags) {
  std::vector<std::uint8_t> bytes;
  if (std::string e = readWholeFile(path, bytes); !e.empty()) {
    diags.report(DiagCode::FileUnreadable, {path, "", 0, 0},
                 {quoteUserText(path), e, "pass the path of a .gltf or .glb file"});
    return std::nullopt;
  }
  std::filesystem::path folder = std::filesystem::absolute(path).parent_path();
  bool glb = looksLikeGlb(bytes);
  std::string text;
  std::optional<std::size_t> glbBin;  // the BIN chunk's size, when the file has one
  if (glb) {
    std::string error;
    auto chunks = splitGlb(bytes, error);
    if (!chunks) {
      diags.report(DiagCode::GltfContainer, {path, "", 0, 0},
                   {error, glbVersion(bytes) == 1 ? "a binary glTF 1.0 file: convert it to glTF 2.0 (re-export it, or run it through "
                                                    "a glTF 1.0 to 2.0 converter such as gltf-pipeline)"
                                                  : "the .glb file is truncated or corrupt; re-export it"});
      return std::nullopt;
    }
    text = std::string(chunks->json);
    if (!chunks->bin.empty()) glbBin = chunks->bin.size();
  } else {
    text.assign(bytes.begin(), bytes.end());
  }
  auto document = parseJsonDocument(path, std::move(text), diags, kJsonLimits);
  if (!document) return std::nullopt;
  Asset asset;
  asset.file = path;
  asset.document = std::make_shared<const JsonDocument>(std::move(*document));
  if (!checkSchema(*asset.document, diags) || !checkDeclaredRanges(*asset.document, diags) || !checkBufferTotal(*asset.document, diags) ||
      !checkRequiredExtensions(*asset.document, diags) || !checkResourceUris(*asset.document, folder, glbBin, diags))
    return std::nullopt;
  if (!parseWithTinygltf(asset, bytes, glb, folder, diags) || !checkBufferRanges(asset, diags) || !checkNodeHierarchy(asset, diags))
    return std::nullopt;
  return asset;
}

}  // namespace wg::gltf
