#include "import/gltf_schema.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string_view>

#include "compiler/literal.hpp"

namespace wg::gltf {

namespace {

enum class Type : std::uint8_t {
  Root, Asset, Scene, Node, Mesh, Primitive, Accessor, BufferView, Buffer, Material, Pbr, TextureInfo,
  Texture, Image, Sampler, TextureTransform, EmissiveStrength, Opaque
};

enum class Kind : std::uint8_t { Index, Number, String, Bool, Object, IndexArray, NumberArray, StringArray, ObjectArray, IndexMap };

// The values an enumerated integer property may take (glTF 2.0, 5.x).
constexpr std::int64_t kComponentTypes[] = {5120, 5121, 5122, 5123, 5125, 5126};
constexpr std::int64_t kModes[] = {0, 1, 2, 3, 4, 5, 6};
constexpr std::int64_t kMagFilters[] = {9728, 9729};
constexpr std::int64_t kMinFilters[] = {9728, 9729, 9984, 9985, 9986, 9987};
constexpr std::int64_t kWraps[] = {33071, 33648, 10497};

struct Rule {
  Type owner;
  std::string_view key;
  Kind kind;
  Type child = Type::Opaque;      // for Object and ObjectArray
  std::string_view refersTo = {};  // top-level collection an Index names
  int length = 0;                  // exact NumberArray length; 0: any
  bool required = false;
  std::span<const std::int64_t> allowed = {};  // an Index's only values; empty: any
  std::size_t minItems = 0;                    // an ObjectArray's fewest elements
};

using enum Type;
using K = Kind;
constexpr bool kRequired = true;

// glTF 2.0 schema, restricted to what the importer and the model renderer read.
constexpr std::array kRules = {
    Rule{Root, "asset", K::Object, Asset, {}, 0, kRequired},
    Rule{Root, "scene", K::Index, Opaque, "scenes"},
    Rule{Root, "scenes", K::ObjectArray, Scene},
    Rule{Root, "nodes", K::ObjectArray, Node},
    Rule{Root, "meshes", K::ObjectArray, Mesh},
    Rule{Root, "accessors", K::ObjectArray, Accessor},
    Rule{Root, "bufferViews", K::ObjectArray, BufferView},
    Rule{Root, "buffers", K::ObjectArray, Buffer},
    Rule{Root, "materials", K::ObjectArray, Material},
    Rule{Root, "textures", K::ObjectArray, Texture},
    Rule{Root, "images", K::ObjectArray, Image},
    Rule{Root, "samplers", K::ObjectArray, Sampler},
    Rule{Root, "skins", K::ObjectArray},
    Rule{Root, "cameras", K::ObjectArray},
    Rule{Root, "animations", K::ObjectArray},
    Rule{Root, "extensionsUsed", K::StringArray},
    Rule{Root, "extensionsRequired", K::StringArray},
    Rule{Asset, "version", K::String, Opaque, {}, 0, kRequired},
    Rule{Asset, "minVersion", K::String},
    Rule{Asset, "generator", K::String},
    Rule{Asset, "copyright", K::String},
    Rule{Scene, "nodes", K::IndexArray, Opaque, "nodes"},
    Rule{Node, "children", K::IndexArray, Opaque, "nodes"},
    Rule{Node, "mesh", K::Index, Opaque, "meshes"},
    Rule{Node, "camera", K::Index, Opaque, "cameras"},
    Rule{Node, "skin", K::Index, Opaque, "skins"},
    Rule{Node, "matrix", K::NumberArray, Opaque, {}, 16},
    Rule{Node, "rotation", K::NumberArray, Opaque, {}, 4},
    Rule{Node, "scale", K::NumberArray, Opaque, {}, 3},
    Rule{Node, "translation", K::NumberArray, Opaque, {}, 3},
    Rule{Node, "weights", K::NumberArray},
    Rule{Mesh, "primitives", K::ObjectArray, Primitive, {}, 0, kRequired, {}, 1},
    Rule{Mesh, "weights", K::NumberArray},
    Rule{Primitive, "attributes", K::IndexMap, Opaque, "accessors", 0, kRequired},
    Rule{Primitive, "indices", K::Index, Opaque, "accessors"},
    Rule{Primitive, "material", K::Index, Opaque, "materials"},
    Rule{Primitive, "mode", K::Index, Opaque, {}, 0, false, kModes},
    Rule{Primitive, "targets", K::ObjectArray},
    Rule{Accessor, "bufferView", K::Index, Opaque, "bufferViews"},
    Rule{Accessor, "byteOffset", K::Index},
    Rule{Accessor, "componentType", K::Index, Opaque, {}, 0, kRequired, kComponentTypes},
    Rule{Accessor, "normalized", K::Bool},
    Rule{Accessor, "count", K::Index, Opaque, {}, 0, kRequired},
    Rule{Accessor, "type", K::String, Opaque, {}, 0, kRequired},
    Rule{Accessor, "max", K::NumberArray},
    Rule{Accessor, "min", K::NumberArray},
    Rule{Accessor, "sparse", K::Object},
    Rule{BufferView, "buffer", K::Index, Opaque, "buffers", 0, kRequired},
    Rule{BufferView, "byteOffset", K::Index},
    Rule{BufferView, "byteLength", K::Index, Opaque, {}, 0, kRequired},
    Rule{BufferView, "byteStride", K::Index},
    Rule{BufferView, "target", K::Index},
    Rule{Buffer, "uri", K::String},
    Rule{Buffer, "byteLength", K::Index, Opaque, {}, 0, kRequired},
    Rule{Material, "pbrMetallicRoughness", K::Object, Pbr},
    Rule{Material, "normalTexture", K::Object, TextureInfo},
    Rule{Material, "occlusionTexture", K::Object, TextureInfo},
    Rule{Material, "emissiveTexture", K::Object, TextureInfo},
    Rule{Material, "emissiveFactor", K::NumberArray, Opaque, {}, 3},
    Rule{Material, "alphaMode", K::String},
    Rule{Material, "alphaCutoff", K::Number},
    Rule{Material, "doubleSided", K::Bool},
    Rule{Pbr, "baseColorFactor", K::NumberArray, Opaque, {}, 4},
    Rule{Pbr, "baseColorTexture", K::Object, TextureInfo},
    Rule{Pbr, "metallicFactor", K::Number},
    Rule{Pbr, "roughnessFactor", K::Number},
    Rule{Pbr, "metallicRoughnessTexture", K::Object, TextureInfo},
    Rule{TextureInfo, "index", K::Index, Opaque, "textures", 0, kRequired},
    Rule{TextureInfo, "texCoord", K::Index},
    Rule{TextureInfo, "scale", K::Number},
    Rule{TextureInfo, "strength", K::Number},
    Rule{Texture, "sampler", K::Index, Opaque, "samplers"},
    Rule{Texture, "source", K::Index, Opaque, "images"},
    Rule{Image, "uri", K::String},
    Rule{Image, "mimeType", K::String},
    Rule{Image, "bufferView", K::Index, Opaque, "bufferViews"},
    Rule{Sampler, "magFilter", K::Index, Opaque, {}, 0, false, kMagFilters},
    Rule{Sampler, "minFilter", K::Index, Opaque, {}, 0, false, kMinFilters},
    Rule{Sampler, "wrapS", K::Index, Opaque, {}, 0, false, kWraps},
    Rule{Sampler, "wrapT", K::Index, Opaque, {}, 0, false, kWraps},
    Rule{TextureTransform, "offset", K::NumberArray, Opaque, {}, 2},
    Rule{TextureTransform, "rotation", K::Number},
    Rule{TextureTransform, "scale", K::NumberArray, Opaque, {}, 2},
    Rule{TextureTransform, "texCoord", K::Index},
    Rule{EmissiveStrength, "emissiveStrength", K::Number},
};

// The extensions whose contents the importer reads, and the object type they hold.
Type extensionType(std::string_view name) {
  if (name == "KHR_texture_transform") return TextureTransform;
  if (name == "KHR_materials_emissive_strength") return EmissiveStrength;
  return Opaque;
}

// Every number the importer reads becomes a float (a factor, a transform, a graph
// literal), so a number beyond float's range is refused here, not by the next compile.
constexpr std::string_view kFloatNumber = "a number within float range (at most 3.4e38 in size)";

bool isFloatNumber(const nlohmann::json& j) {
  return j.is_number() && std::abs(j.get<double>()) <= std::numeric_limits<float>::max();
}

// tinygltf stores indices, counts and enums in int; larger values would wrap.
bool isIndex(const nlohmann::json& j) {
  constexpr std::int64_t kLargest = std::numeric_limits<std::int32_t>::max();
  if (j.is_number_unsigned()) return j.get<std::uint64_t>() <= std::uint64_t(kLargest);
  return j.is_number_integer() && j.get<std::int64_t>() >= 0 && j.get<std::int64_t>() <= kLargest;
}

std::string oneOf(std::span<const std::int64_t> values) {
  std::string out = "one of";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : " ") + std::to_string(values[i]);
  return out;
}

std::string expected(const Rule& r) {
  switch (r.kind) {
    case K::Index: return r.allowed.empty() ? "an integer from 0 to 2147483647" : oneOf(r.allowed);
    case K::Number: return std::string(kFloatNumber);
    case K::String: return "a string";
    case K::Bool: return "true or false";
    case K::Object: return "an object";
    case K::IndexArray: return "an array of integers from 0 to 2147483647";
    case K::NumberArray: return "an array of numbers within float range (at most 3.4e38 in size)";
    case K::StringArray: return "an array of strings";
    case K::ObjectArray: return r.minItems ? "an array of at least " + std::to_string(r.minItems) + " object(s)" : "an array of objects";
    case K::IndexMap: return "an object of integers from 0 to 2147483647";
  }
  return "";
}

bool allOf(const nlohmann::json& j, bool (*pred)(const nlohmann::json&)) {
  if (!j.is_array()) return false;
  for (const auto& e : j)
    if (!pred(e)) return false;
  return true;
}

bool hasKind(const nlohmann::json& j, const Rule& r) {
  switch (r.kind) {
    case K::Index:
      return isIndex(j) && (r.allowed.empty() || std::find(r.allowed.begin(), r.allowed.end(), j.get<std::int64_t>()) != r.allowed.end());
    case K::Number: return isFloatNumber(j);
    case K::String: return j.is_string();
    case K::Bool: return j.is_boolean();
    case K::Object: return j.is_object();
    case K::IndexArray: return allOf(j, isIndex);
    case K::NumberArray:
      return allOf(j, isFloatNumber) && (r.length == 0 || j.size() == static_cast<std::size_t>(r.length));
    case K::StringArray: return allOf(j, [](const nlohmann::json& e) { return e.is_string(); });
    case K::ObjectArray: return allOf(j, [](const nlohmann::json& e) { return e.is_object(); }) && j.size() >= r.minItems;
    case K::IndexMap:
      if (!j.is_object()) return false;
      for (const auto& [k, v] : j.items())
        if (!isIndex(v)) return false;
      return true;
  }
  return false;
}

class SchemaChecker {
 public:
  SchemaChecker(const JsonDocument& doc, DiagnosticList& diags) : doc_(doc), diags_(diags) {}

  bool run() {
    if (!doc_.root().is_object()) {
      diags_.report(DiagCode::GltfSchema, doc_.locate(""), {"the document", "an object", describeJsonKind(doc_.root())});
      return false;
    }
    // Checked first: a glTF 1.0 file breaks a dozen rules of 2.0, and the version says why.
    if (!checkVersion()) return false;
    checkObject(doc_.root(), Root, "");
    return ok_;
  }

 private:
  void checkObject(const nlohmann::json& j, Type type, const std::string& pointer) {
    for (const Rule& r : kRules) {
      if (r.owner != type) continue;
      std::string at = appendPointer(pointer, r.key);
      auto it = j.find(std::string(r.key));
      if (it == j.end()) {
        if (r.required) fail(DiagCode::GltfSchema, pointer, {"'" + std::string(r.key) + "' at " + shownPointer(pointer), expected(r), "missing"});
        continue;
      }
      if (!hasKind(*it, r)) {
        std::string shape = r.length ? expected(r) + " of length " + std::to_string(r.length) : expected(r);
        std::string where = at;
        std::string got = actual(*it, where);
        if (where != at) shape = kFloatNumber;  // one element of the array
        fail(DiagCode::GltfSchema, where, {shown(where), shape, got});
        continue;
      }
      checkReferences(*it, r, at);
      checkChildren(*it, r, at);
    }
    checkName(j, type, pointer);
    checkExtensions(j, pointer);
  }

  // glTF 1.0 and any later major version differ in layout; only 2.x ("2.0", "2.1") is read.
  // A missing asset or version is left to the schema rules.
  bool checkVersion() {
    const nlohmann::json& root = doc_.root();
    auto asset = root.find("asset");
    if (asset == root.end() || !asset->is_object() || !asset->contains("version")) return true;
    const nlohmann::json& version = (*asset)["version"];
    std::string text = version.is_string() ? version.get<std::string>() : version.dump();
    const bool digitsAfter = text.size() > 2 && std::all_of(text.begin() + 2, text.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (version.is_string() && text.starts_with("2.") && digitsAfter) return true;
    const bool gltf1 = text == "1" || text.starts_with("1.");  // glTF 1.0 wrote "1.0"; early exporters the number 1
    std::string shown = version.is_string() ? "'" + quoteUserText(text, 40) + "'" : quoteUserText(text, 40);
    fail(DiagCode::GltfContainer, "/asset/version",
         {"'/asset/version' is " + shown + (gltf1 ? ": a glTF 1.0 model" : ""),
          gltf1 ? "convert it to glTF 2.0 (re-export it, or run it through a glTF 1.0 to 2.0 converter such as gltf-pipeline)"
                : "re-export the model as glTF 2.0"});
    return false;
  }

  // Every glTF object but the root may carry a user-facing name.
  void checkName(const nlohmann::json& j, Type type, const std::string& pointer) {
    auto it = j.find("name");
    if (type == Root || it == j.end() || it->is_string()) return;
    std::string at = appendPointer(pointer, "name");
    fail(DiagCode::GltfSchema, at, {shown(at), "a string", describeJsonKind(*it)});
  }

  void checkChildren(const nlohmann::json& j, const Rule& r, const std::string& at) {
    if (r.child == Opaque) return;
    if (r.kind == K::Object) checkObject(j, r.child, at);
    if (r.kind == K::ObjectArray)
      for (std::size_t i = 0; i < j.size(); ++i) checkObject(j[i], r.child, appendPointer(at, i));
  }

  void checkExtensions(const nlohmann::json& j, const std::string& pointer) {
    auto it = j.find("extensions");
    if (it == j.end()) return;
    std::string at = appendPointer(pointer, "extensions");
    if (!it->is_object()) return fail(DiagCode::GltfSchema, at, {shown(at), "an object", describeJsonKind(*it)});
    for (const auto& [name, value] : it->items()) {
      std::string inner = appendPointer(at, name);
      if (!value.is_object()) {
        fail(DiagCode::GltfSchema, inner, {shown(inner), "an object", describeJsonKind(value)});
        continue;
      }
      if (Type t = extensionType(name); t != Opaque) checkObject(value, t, inner);
    }
  }

  void checkReferences(const nlohmann::json& j, const Rule& r, const std::string& at) {
    if (r.refersTo.empty()) return;
    if (r.kind == K::Index) return checkIndex(j, r.refersTo, at);
    if (r.kind == K::IndexArray)
      for (std::size_t i = 0; i < j.size(); ++i) checkIndex(j[i], r.refersTo, appendPointer(at, i));
    if (r.kind == K::IndexMap)
      for (const auto& [k, v] : j.items()) checkIndex(v, r.refersTo, appendPointer(at, k));
  }

  void checkIndex(const nlohmann::json& index, std::string_view collection, const std::string& at) {
    std::size_t size = 0;
    if (auto it = doc_.root().find(std::string(collection)); it != doc_.root().end() && it->is_array()) size = it->size();
    auto value = index.get<std::uint64_t>();
    if (value < size) return;
    fail(DiagCode::GltfBadReference, at,
         {shown(at) + " is " + std::to_string(value) + ", but the file has " + std::to_string(size) + " '" + std::string(collection) + "'",
          size ? "use an index from 0 to " + std::to_string(size - 1) + ", or re-export the model"
               : "the file has no '" + std::string(collection) + "'; remove the reference or re-export the model"});
  }

  // What the file holds, for the message; an array of numbers points `at` its first
  // number beyond float range, if that is what is wrong with it.
  static std::string actual(const nlohmann::json& j, std::string& at) {
    if (j.is_number()) return j.dump();
    if (!j.is_array()) return describeJsonKind(j);
    if (j.empty()) return "an empty array";
    for (std::size_t i = 0; i < j.size(); ++i)
      if (j[i].is_number() && !isFloatNumber(j[i])) {
        at = appendPointer(at, i);
        return j[i].dump();
      }
    return describeJsonKind(j);
  }

  static std::string shown(const std::string& pointer) { return quoteUserText(pointer, 200); }
  static std::string shownPointer(const std::string& pointer) { return pointer.empty() ? "the top level" : shown(pointer); }

  void fail(DiagCode code, const std::string& pointer, std::initializer_list<std::string_view> args) {
    ok_ = false;
    diags_.report(code, doc_.locate(pointer), args);
  }

  const JsonDocument& doc_;
  DiagnosticList& diags_;
  bool ok_ = true;
};

}  // namespace

bool checkSchema(const JsonDocument& document, DiagnosticList& diagnostics) {
  return SchemaChecker(document, diagnostics).run();
}

}  // namespace wg::gltf
