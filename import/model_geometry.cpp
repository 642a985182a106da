#include "import/model_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <span>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "import/material_graph_writer.hpp"

namespace wg::gltf {

namespace {

constexpr int kPoints = 0, kTriangles = 4, kTriangleStrip = 5, kTriangleFan = 6;

// How an attribute may be stored (glTF 2.0, 3.7.2.1; KHR_mesh_quantization widens it).
struct StorageForm {
  int componentType;
  bool normalized;
};
constexpr StorageForm kF{5126, false}, kB{5120, false}, kBN{5120, true}, kUB{5121, false}, kUBN{5121, true}, kS{5122, false},
    kSN{5122, true}, kUS{5123, false}, kUSN{5123, true}, kUI{5125, false};
constexpr StorageForm kFloatOnly[] = {kF}, kColourForms[] = {kF, kUBN, kUSN}, kIndexForms[] = {kUB, kUS, kUI},
                      kQuantizedPositions[] = {kF, kB, kBN, kUB, kUBN, kS, kSN, kUS, kUSN},
                      kQuantizedDirections[] = {kF, kBN, kSN}, kQuantizedTexcoords[] = {kF, kB, kBN, kUB, kUBN, kS, kSN, kUS, kUSN};

struct AttributeFormat {
  int minComponents, maxComponents;
  std::span<const StorageForm> core, quantized;
};
constexpr AttributeFormat kPositionFormat{3, 3, kFloatOnly, kQuantizedPositions}, kNormalFormat{3, 3, kFloatOnly, kQuantizedDirections},
    kTangentFormat{4, 4, kFloatOnly, kQuantizedDirections}, kTexcoordFormat{2, 2, kColourForms, kQuantizedTexcoords},
    kColourFormat{3, 4, kColourForms, kColourForms}, kIndexFormat{1, 1, kIndexForms, kIndexForms};

int componentCount(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return 1;
    case TINYGLTF_TYPE_VEC2: return 2;
    case TINYGLTF_TYPE_VEC3: return 3;
    case TINYGLTF_TYPE_VEC4: return 4;
    default: return 0;
  }
}

int componentBytes(int componentType) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
  }
}

// One component as float; normalized integers map to [0, 1] or [-1, 1] (glTF 3.11).
float readComponent(const std::uint8_t* p, int componentType, bool normalized) {
  switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: { float v; std::memcpy(&v, p, 4); return v; }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t v; std::memcpy(&v, p, 4); return float(v); }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.f : float(p[0]);
    case TINYGLTF_COMPONENT_TYPE_BYTE: { auto v = static_cast<std::int8_t>(p[0]); return normalized ? std::max(v / 127.f, -1.f) : float(v); }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t v; std::memcpy(&v, p, 2); return normalized ? v / 65535.f : float(v); }
    case TINYGLTF_COMPONENT_TYPE_SHORT: { std::int16_t v; std::memcpy(&v, p, 2); return normalized ? std::max(v / 32767.f, -1.f) : float(v); }
    default: return 0.f;
  }
}

class GeometryReader {
 public:
  GeometryReader(const Asset& asset, DiagnosticList& diags)
      : asset_(asset), m_(asset.model), diags_(diags),
        quantized_(std::find(m_.extensionsUsed.begin(), m_.extensionsUsed.end(), "KHR_mesh_quantization") != m_.extensionsUsed.end()) {}

  std::optional<ModelGeometry> run() {
    warnIgnoredFeatures();
    for (int root : sceneRoots()) visitTree(root);
    if (failed_) return std::nullopt;
    return std::move(geometry_);
  }

 private:
  std::vector<int> sceneRoots() const {
    int scene = m_.defaultScene >= 0 ? m_.defaultScene : m_.scenes.empty() ? -1 : 0;
    if (scene >= 0) return m_.scenes[scene].nodes;
    std::vector<bool> child(m_.nodes.size(), false);
    for (const auto& n : m_.nodes)
      for (int c : n.children) child[c] = true;
    std::vector<int> roots;
    for (std::size_t i = 0; i < m_.nodes.size(); ++i)
      if (!child[i]) roots.push_back(static_cast<int>(i));
    return roots;
  }

  // The hierarchy is a checked forest (node_hierarchy.hpp), so this ends and visits
  // each node once; an explicit stack, because a file may chain millions of nodes.
  void visitTree(int root) {
    std::vector<std::pair<int, glm::mat4>> pending{{root, glm::mat4(1.f)}};
    while (!pending.empty() && !failed_) {
      auto [index, parent] = pending.back();
      pending.pop_back();
      glm::mat4 world = parent * localTransform(index);
      if (!finite(world)) {
        fail(DiagCode::GltfInvalidData, "/nodes/" + std::to_string(index),
             "node " + std::to_string(index) + "'s world transform overflows (its ancestors' scales multiply past float range)",
             "re-export the model with sensible scales");
        return;
      }
      const auto& node = m_.nodes[index];
      if (node.mesh >= 0) addMesh(node.mesh, world);
      for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) pending.push_back({*child, world});
    }
  }

  glm::mat4 localTransform(int index) {
    const auto& n = m_.nodes[index];
    glm::mat4 m(1.f);
    if (n.matrix.size() == 16) {
      for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = static_cast<float>(n.matrix[i]);
    } else {
      glm::vec3 t = n.translation.size() == 3 ? glm::vec3(n.translation[0], n.translation[1], n.translation[2]) : glm::vec3(0.f);
      glm::quat r = n.rotation.size() == 4 ? glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]))
                                           : glm::quat(1.f, 0.f, 0.f, 0.f);
      glm::vec3 s = n.scale.size() == 3 ? glm::vec3(n.scale[0], n.scale[1], n.scale[2]) : glm::vec3(1.f);
      m = glm::translate(glm::mat4(1.f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.f), s);
    }
    if (!finite(m)) {
      fail(DiagCode::GltfInvalidData, "/nodes/" + std::to_string(index), "node " + std::to_string(index) + " has a non-finite transform",
           "re-export the model; every translation, rotation, scale and matrix value must be a finite number");
      return glm::mat4(1.f);
    }
    return m;
  }

  static bool finite(const glm::mat4& m) {
    for (int i = 0; i < 16; ++i)
      if (!std::isfinite(glm::value_ptr(m)[i])) return false;
    return true;
  }

  void addMesh(int meshIndex, const glm::mat4& world) {
    const auto& mesh = m_.meshes[meshIndex];
    for (std::size_t p = 0; p < mesh.primitives.size() && !failed_; ++p) {
      std::string pointer = "/meshes/" + std::to_string(meshIndex) + "/primitives/" + std::to_string(p);
      const auto& prim = mesh.primitives[p];
      if (prim.mode >= kPoints && prim.mode < kTriangles) continue;  // warned about once, in warnIgnoredFeatures
      if (geometry_.primitives.size() == kMaxPrimitiveInstances) {
        fail(DiagCode::ResourceLimit, pointer, "the number of primitive instances in the scene", "more than " +
             std::to_string(kMaxPrimitiveInstances), std::to_string(kMaxPrimitiveInstances));
        return;
      }
      // Each primitive is read once however many nodes instance it; instances copy it.
      auto [cached, fresh] = read_.try_emplace({meshIndex, p});
      if (fresh) {
        ModelPrimitive& out = cached->second;
        out.name = (mesh.name.empty() ? "mesh" + std::to_string(meshIndex) : mesh.name) + "/" + std::to_string(p);
        out.material = prim.material;
        if (!readPrimitive(prim, pointer, out)) return;
      }
      ModelPrimitive instance = cached->second;
      instance.transform = world;
      addPrimitive(std::move(instance), pointer);
    }
  }

  bool readPrimitive(const tinygltf::Primitive& prim, const std::string& pointer, ModelPrimitive& out) {
    auto position = prim.attributes.find("POSITION");
    if (position == prim.attributes.end()) {
      fail(DiagCode::GltfSchema, pointer + "/attributes", "'POSITION' at " + pointer + "/attributes", "an accessor index", "missing");
      return false;
    }
    std::string at = pointer + "/attributes/";
    if (!readSized<glm::vec3>(position->second, at + "POSITION", kPositionFormat, out.positions, 0)) return false;
    std::size_t count = out.positions.size();
    auto optional = [&](const char* name, auto& dst, AttributeFormat format, auto reader) {
      auto it = prim.attributes.find(name);
      return it == prim.attributes.end() || (this->*reader)(it->second, at + name, format, dst, count);
    };
    if (!optional("NORMAL", out.normals, kNormalFormat, &GeometryReader::readSized<glm::vec3>) ||
        !optional("TANGENT", out.tangents, kTangentFormat, &GeometryReader::readSized<glm::vec4>) ||
        !optional("TEXCOORD_0", out.texcoords0, kTexcoordFormat, &GeometryReader::readSized<glm::vec2>) ||
        !optional("TEXCOORD_1", out.texcoords1, kTexcoordFormat, &GeometryReader::readSized<glm::vec2>) ||
        !optional("COLOR_0", out.colors, kColourFormat, &GeometryReader::readSized<glm::vec4>))
      return false;
    return checkTexCoordSets(prim, pointer, out) && readIndices(prim, pointer, out);
  }

  // A texture coordinate set the material samples must exist (glTF 3.7.2.1).
  bool checkTexCoordSets(const tinygltf::Primitive& prim, const std::string& pointer, const ModelPrimitive& out) {
    unsigned sets = texCoordSetsUsed(m_, prim.material);
    for (int set = 0; set < 2; ++set) {
      bool present = set == 0 ? !out.texcoords0.empty() : !out.texcoords1.empty();
      if (!(sets & (1u << set)) || present) continue;
      fail(DiagCode::GltfBadReference, pointer + "/attributes",
           "primitive " + pointer + " has no TEXCOORD_" + std::to_string(set) + ", which its material " +
               std::to_string(prim.material) + " samples",
           "add the texture coordinates to the mesh, or point the material's textures at a set the mesh has");
      return false;
    }
    return true;
  }

  bool readIndices(const tinygltf::Primitive& prim, const std::string& pointer, ModelPrimitive& out) {
    std::size_t count = out.positions.size();
    std::vector<std::uint32_t> raw;
    if (prim.indices < 0) {
      raw.resize(count);
      for (std::size_t i = 0; i < count; ++i) raw[i] = static_cast<std::uint32_t>(i);
    } else {
      std::vector<glm::vec4> values;
      if (!readAccessor(prim.indices, pointer + "/indices", kIndexFormat, values)) return false;
      raw.reserve(values.size());
      for (std::size_t i = 0; i < values.size(); ++i) {
        auto v = static_cast<std::uint64_t>(values[i].x);
        if (v >= count) {
          fail(DiagCode::GltfInvalidData, pointer + "/indices",
               "index " + std::to_string(i) + " of " + pointer + " is " + std::to_string(v) + ", but the primitive has " +
                   std::to_string(count) + " vertices",
               "re-export the model; its index buffer names vertices that do not exist");
          return false;
        }
        raw.push_back(static_cast<std::uint32_t>(v));
      }
    }
    out.indices = triangleList(raw, prim.mode);
    return true;
  }

  static std::vector<std::uint32_t> triangleList(const std::vector<std::uint32_t>& v, int mode) {
    std::vector<std::uint32_t> out;
    if (mode == kTriangleStrip || mode == kTriangleFan) {
      for (std::size_t i = 2; i < v.size(); ++i) {
        bool odd = i % 2 == 1;
        if (mode == kTriangleFan) out.insert(out.end(), {v[0], v[i - 1], v[i]});
        else if (odd) out.insert(out.end(), {v[i - 1], v[i - 2], v[i]});  // keep the winding of even triangles
        else out.insert(out.end(), {v[i - 2], v[i - 1], v[i]});
      }
      return out;
    }
    out.assign(v.begin(), v.end() - static_cast<std::ptrdiff_t>(v.size() % 3));
    return out;
  }

  void addPrimitive(ModelPrimitive p, const std::string& pointer) {
    geometry_.triangleCount += p.indices.size() / 3;
    vertexCount_ += p.positions.size();
    if (geometry_.triangleCount > kMaxModelTriangles) {
      fail(DiagCode::ResourceLimit, pointer, "the triangle count of the scene", std::to_string(geometry_.triangleCount),
           std::to_string(kMaxModelTriangles));
      return;
    }
    if (vertexCount_ > kMaxModelVertices) {
      fail(DiagCode::ResourceLimit, pointer, "the vertex count of the scene (instances counted)", std::to_string(vertexCount_),
           std::to_string(kMaxModelVertices));
      return;
    }
    geometry_.primitives.push_back(std::move(p));
  }

  // Reads an accessor into vectors of N components; `count` (when not 0) must match.
  template <typename Vec>
  bool readSized(int accessor, const std::string& pointer, AttributeFormat format, std::vector<Vec>& out, std::size_t count) {
    std::vector<glm::vec4> values;
    if (!readAccessor(accessor, pointer, format, values)) return false;
    if (count && values.size() != count) {
      fail(DiagCode::GltfInvalidData, pointer,
           pointer + " has " + std::to_string(values.size()) + " elements, but POSITION has " + std::to_string(count),
           "every attribute of a primitive must have one element per vertex");
      return false;
    }
    out.resize(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = Vec(values[i]);
    return true;
  }

  // Every element as a vec4 (missing components: 0, alpha 1), bounds and types checked.
  bool readAccessor(int index, const std::string& pointer, AttributeFormat format, std::vector<glm::vec4>& out) {
    const auto& a = m_.accessors[index];
    std::string at = "/accessors/" + std::to_string(index);
    int components = componentCount(a.type), bytes = componentBytes(a.componentType);
    auto forms = quantized_ ? format.quantized : format.core;
    bool stored = std::any_of(forms.begin(), forms.end(), [&](StorageForm f) {
      return f.componentType == a.componentType && f.normalized == a.normalized;
    });
    if (components < format.minComponents || components > format.maxComponents || bytes == 0 || !stored) {
      fail(DiagCode::GltfSchema, at, "accessor " + std::to_string(index) + " (used by " + pointer + ")",
           std::string("stored as glTF 2.0 allows there") + (quantized_ ? " with KHR_mesh_quantization" : ""), describeAccessor(a));
      return false;
    }
    if (a.sparse.isSparse) {
      fail(DiagCode::GltfInvalidData, at, "accessor " + std::to_string(index) + " is sparse, which the importer does not read for mesh data",
           "re-export the model with plain accessors");
      return false;
    }
    if (a.count > kMaxModelVertices) {
      fail(DiagCode::ResourceLimit, at, "the element count of accessor " + std::to_string(index), std::to_string(a.count),
           std::to_string(kMaxModelVertices));
      return false;
    }
    const tinygltf::BufferView* view = a.bufferView >= 0 ? &m_.bufferViews[a.bufferView] : nullptr;
    if (view && a.count > view->byteLength) {  // cannot fit, and would overflow the range check below
      fail(DiagCode::GltfInvalidData, at,
           "accessor " + std::to_string(index) + " claims " + std::to_string(a.count) + " elements in a buffer view of " +
               std::to_string(view->byteLength) + " bytes",
           "re-export the model; the accessor does not fit its buffer view");
      return false;
    }
    out.assign(a.count, glm::vec4(0.f, 0.f, 0.f, 1.f));
    if (!view) return true;  // glTF: all zeros
    return readElements(*view, a, index, at, components, bytes, out);
  }

  bool readElements(const tinygltf::BufferView& view, const tinygltf::Accessor& a, int index, const std::string& at, int components,
                    int bytes, std::vector<glm::vec4>& out) {
    std::size_t element = std::size_t(components) * bytes, stride = view.byteStride ? view.byteStride : element;
    constexpr std::size_t kMaxStride = 252;  // glTF 2.0, bufferView.byteStride
    bool sane = a.byteOffset <= view.byteLength && stride <= kMaxStride;  // so the sum below cannot overflow
    std::uint64_t end = a.count ? std::uint64_t(a.byteOffset) + std::uint64_t(stride) * (a.count - 1) + element : 0;
    if (!sane || stride < element || end > view.byteLength) {
      fail(DiagCode::GltfInvalidData, at,
           "accessor " + std::to_string(index) + " reads " + std::to_string(end) + " bytes of buffer view " +
               std::to_string(a.bufferView) + ", which has " + std::to_string(view.byteLength),
           "re-export the model; the accessor does not fit its buffer view");
      return false;
    }
    const std::uint8_t* base = m_.buffers[view.buffer].data.data() + view.byteOffset + a.byteOffset;
    for (std::size_t i = 0; i < a.count; ++i)
      for (int c = 0; c < components; ++c) {
        float v = readComponent(base + i * stride + std::size_t(c) * bytes, a.componentType, a.normalized);
        if (!std::isfinite(v)) {
          fail(DiagCode::GltfInvalidData, at,
               "accessor " + std::to_string(index) + " holds a non-finite value at element " + std::to_string(i),
               "re-export the model; vertex data must be finite numbers");
          return false;
        }
        out[i][c] = v;
      }
    return true;
  }

  static std::string describeAccessor(const tinygltf::Accessor& a) {
    return std::to_string(componentCount(a.type)) + " component(s) of componentType " + std::to_string(a.componentType) +
           (a.normalized ? ", normalized" : "");
  }

  void warnIgnoredFeatures() {
    bool skins = !m_.skins.empty(), morphs = false, nonTriangles = false;
    for (const auto& mesh : m_.meshes)
      for (const auto& p : mesh.primitives) {
        morphs = morphs || !p.targets.empty();
        nonTriangles = nonTriangles || (p.mode >= kPoints && p.mode < kTriangles);
      }
    if (skins || morphs)
      diags_.report(DiagCode::GltfFeatureIgnored, asset_.locate(skins ? "/skins" : "/meshes"),
                    {"skins and morph targets are ignored: the model is drawn in its bind pose",
                     "weathergen previews materials on static geometry"});
    if (nonTriangles)
      diags_.report(DiagCode::GltfFeatureIgnored, asset_.locate("/meshes"),
                    {"points and lines are not drawn; only triangle primitives are", "weather applies to surfaces"});
  }

  void fail(DiagCode code, const std::string& pointer, std::initializer_list<std::string_view> args) {
    failed_ = true;
    diags_.report(code, asset_.locate(pointer), args);
  }
  template <typename... Args>
  void fail(DiagCode code, const std::string& pointer, const Args&... args) {
    fail(code, pointer, {std::string_view(args)...});
  }

  const Asset& asset_;
  const tinygltf::Model& m_;
  DiagnosticList& diags_;
  ModelGeometry geometry_;
  std::map<std::pair<int, std::size_t>, ModelPrimitive> read_;  // (mesh, primitive) -> as read
  std::size_t vertexCount_ = 0;
  bool quantized_;  // KHR_mesh_quantization: integer positions, normals, tangents and texcoords
  bool failed_ = false;
};

}  // namespace

std::optional<ModelGeometry> readModelGeometry(const Asset& asset, DiagnosticList& diagnostics) {
  return GeometryReader(asset, diagnostics).run();
}

}  // namespace wg::gltf
