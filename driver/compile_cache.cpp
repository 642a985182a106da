#include "driver/compile_cache.hpp"

#include <dlfcn.h>
#include <elf.h>
#include <fcntl.h>
#include <link.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <thread>
#include <vector>

#include "compiler/graph_loader.hpp"
#include "compiler/literal.hpp"
#include "nodes/regular_file.hpp"

namespace wg {

namespace {

constexpr std::string_view kEntryMagic = "weathergen compile cache entry 1\n";
constexpr std::string_view kEntrySuffix = ".entry";
constexpr std::string_view kTemporaryPrefix = "tmp.";
// Graph libraries and images are hashed whole; larger than any input the loader accepts.
constexpr std::uintmax_t kMaxInputBytes = 1ull << 30;
constexpr std::uint64_t kMaxInputFiles = 1u << 16;
constexpr std::uintmax_t kMaxEntryBytes = 1ull << 30;

// A 128-bit digest: two independent 64-bit lanes over 8-byte words, fast enough to hash
// an image at memory speed. It is no defence against crafted collisions; the cache
// trusts its inputs as the compiler does.
class ContentDigest {
 public:
  void add(std::string_view bytes) {
    addWord(bytes.size());
    const char* at = bytes.data();
    std::size_t left = bytes.size();
    if (left >= kBlockBytes) {
      // Whole blocks go through four independent accumulators (xxHash's round): the
      // multiplications of one wait on each other, those of different ones do not, so
      // a warm run's 4.5 MB of entries are hashed in 0.5 ms instead of 1.75.
      std::uint64_t accumulators[4] = {0x452821E638D01377ull, 0xBE5466CF34E90C6Cull, 0xC0AC29B7C97C50DDull,
                                       0x3F84D5B5B5470917ull};
      for (; left >= kBlockBytes; at += kBlockBytes, left -= kBlockBytes)
        for (int k = 0; k < 4; ++k) accumulators[k] = round(accumulators[k], load(at + 8 * k));
      for (std::uint64_t accumulator : accumulators) addWord(accumulator);
    }
    for (; left >= 8; at += 8, left -= 8) addWord(load(at));
    std::uint64_t tail = 0;
    if (left > 0) std::memcpy(&tail, at, left);  // an empty view's data() may be null
    addWord(tail);
  }
  void addWord(std::uint64_t word) {
    a_ = rotate((a_ ^ word) * 0x9E3779B97F4A7C15ull, 31) * 0xBF58476D1CE4E5B9ull;
    b_ = rotate((b_ + word) * 0xC2B2AE3D27D4EB4Full, 27) * 0x94D049BB133111EBull + 0x165667B19E3779F9ull;
  }
  std::string hex() const {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string out;
    for (std::uint64_t lane : {finish(a_), finish(b_ ^ a_)})
      for (int shift = 60; shift >= 0; shift -= 4) out += kDigits[(lane >> shift) & 0xF];
    return out;
  }

 private:
  static constexpr std::size_t kBlockBytes = 32;
  static std::uint64_t load(const char* at) {
    std::uint64_t word;
    std::memcpy(&word, at, 8);
    return word;
  }
  static std::uint64_t round(std::uint64_t accumulator, std::uint64_t word) {
    return rotate(accumulator + word * 0xC2B2AE3D27D4EB4Full, 31) * 0x9E3779B185EBCA87ull;
  }
  static std::uint64_t rotate(std::uint64_t x, int by) { return (x << by) | (x >> (64 - by)); }
  static std::uint64_t finish(std::uint64_t x) {
    x ^= x >> 33;
    x *= 0xFF51AFD7ED558CCDull;
    x ^= x >> 33;
    x *= 0xC4CEB9FE1A85EC53ull;
    return x ^ (x >> 33);
  }
  std::uint64_t a_ = 0x243F6A8885A308D3ull, b_ = 0x13198A2E03707344ull;
};

// The GNU build id of the object holding this code (the CLI or libweathergen.so), so
// that any rebuilt compiler misses every entry an older one wrote.
int findBuildId(dl_phdr_info* info, std::size_t, void* data) {
  auto& id = *static_cast<std::string*>(data);
  const auto code = reinterpret_cast<ElfW(Addr)>(&findBuildId);
  bool holdsCode = false;
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& segment = info->dlpi_phdr[i];
    const ElfW(Addr) start = info->dlpi_addr + segment.p_vaddr;
    holdsCode = holdsCode || (segment.p_type == PT_LOAD && code >= start && code < start + segment.p_memsz);
  }
  if (!holdsCode) return 0;
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& segment = info->dlpi_phdr[i];
    if (segment.p_type != PT_NOTE) continue;
    const char* at = reinterpret_cast<const char*>(info->dlpi_addr + segment.p_vaddr);
    const char* end = at + segment.p_memsz;
    while (at + sizeof(ElfW(Nhdr)) <= end) {
      const auto* note = reinterpret_cast<const ElfW(Nhdr)*>(at);
      const char* name = at + sizeof(ElfW(Nhdr));
      const char* desc = name + ((note->n_namesz + 3) & ~3u);
      if (note->n_type == NT_GNU_BUILD_ID && note->n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0) {
        id.assign(desc, note->n_descsz);
        return 1;
      }
      at = desc + ((note->n_descsz + 3) & ~3u);
    }
  }
  return 1;
}

// Without a build id (a linker that writes none), the object file's size and time stand in.
std::string objectFileStamp() {
  Dl_info info{};
  struct stat status {};
  if (!dladdr(reinterpret_cast<void*>(&findBuildId), &info) || !info.dli_fname || ::stat(info.dli_fname, &status) != 0)
    return "";
  return std::to_string(status.st_size) + ":" + std::to_string(status.st_mtim.tv_sec) + "." +
         std::to_string(status.st_mtim.tv_nsec);
}

const std::string& compilerBuildIdentity() {
  static const std::string identity = [] {
    std::string id;
    dl_iterate_phdr(findBuildId, &id);
    return std::string(WEATHERGEN_VERSION) + "\n" + (id.empty() ? objectFileStamp() : id);
  }();
  return identity;
}

// Whether it is set, then its text: no text stands for "unset", since the engine API
// passes any string, "\0" included, as a preset or tier to be refused.
void addOptional(ContentDigest& digest, const std::optional<std::string>& value) {
  digest.addWord(value.has_value());
  if (value) digest.add(*value);
}

// Every option that changes what a compile returns, each field length-prefixed.
void addOptions(ContentDigest& digest, const CompileOptions& o) {
  const bool flags[] = {o.emitSpirv, o.emitDisassembly, o.optimize,    o.emitReflection, o.emitHlsl,
                        o.emitCppHeader, o.emitMsl,     o.emitGlslEs,  o.emitSurface,    o.emitFilament,
                        o.hashKeyedFileStem};
  for (bool flag : flags) digest.addWord(flag);
  addOptional(digest, o.weatherPreset);
  digest.addWord(o.weatherEffects.size());
  for (const auto& [name, on] : o.weatherEffects) {
    digest.add(name);
    digest.addWord(on);
  }
  addOptional(digest, o.quality.requested);
  digest.add(o.quality.fallback);
  digest.addWord(o.switches.size());
  for (const auto& [name, value] : o.switches) {
    digest.add(name);
    digest.add(value);
  }
}

std::optional<std::string> fileDigest(const std::string& path) {
  std::string bytes;
  if (readRegularFile(path, kMaxInputBytes, bytes).status != FileReadStatus::Ok) return std::nullopt;
  ContentDigest digest;
  digest.add(bytes);
  return digest.hex();
}

std::int64_t nowNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::int64_t stampNs(const timespec& t) { return std::int64_t(t.tv_sec) * 1'000'000'000 + t.tv_nsec; }

// A file changed after the compile began may not be what the compile read. Its change
// time counts too: a file renamed into place (rsync, or `cp -p` then `mv`) keeps an old
// modification time, and no one can set the change time back.
bool modifiedSince(const std::string& path, std::int64_t ns) {
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) return true;
  return std::max(stampNs(status.st_mtim), stampNs(status.st_ctim)) >= ns;
}

// Length-prefixed fields, read back in the order written.
class EntryWriter {
 public:
  void word(std::uint64_t value) { bytes_.append(reinterpret_cast<const char*>(&value), sizeof value); }
  void text(std::string_view value) {
    word(value.size());
    bytes_.append(value);
  }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

class EntryReader {
 public:
  explicit EntryReader(std::string_view bytes) : rest_(bytes) {}
  bool word(std::uint64_t& value) {
    if (rest_.size() < sizeof value) return false;
    std::memcpy(&value, rest_.data(), sizeof value);
    rest_.remove_prefix(sizeof value);
    return true;
  }
  bool view(std::string_view& value) {
    std::uint64_t size = 0;
    if (!word(size) || size > rest_.size()) return false;
    value = rest_.substr(0, size);
    rest_.remove_prefix(size);
    return true;
  }
  bool text(std::string& value) {
    std::string_view bytes;
    if (!view(bytes)) return false;
    value.assign(bytes);
    return true;
  }
  bool finished() const { return rest_.empty(); }

 private:
  std::string_view rest_;
};

void writeStage(EntryWriter& out, const CompiledStage& s) {
  out.word(static_cast<std::uint64_t>(s.language));
  out.word(static_cast<std::uint64_t>(s.stage));
  out.text(s.source);
  out.text({reinterpret_cast<const char*>(s.spirv.data()), s.spirv.size() * sizeof(std::uint32_t)});
  out.text(s.disassembly);
  out.text(s.msl);
  out.text(s.glslEs);
}

bool readStage(EntryReader& in, CompiledStage& s) {
  std::uint64_t language = 0, stage = 0;
  std::string_view spirv;
  if (!in.word(language) || !in.word(stage) || !in.text(s.source) || !in.view(spirv) || !in.text(s.disassembly) ||
      !in.text(s.msl) || !in.text(s.glslEs) || spirv.size() % sizeof(std::uint32_t) != 0)
    return false;
  s.language = static_cast<ShaderLanguage>(language);
  s.stage = static_cast<ShaderStage>(stage);
  s.spirv.resize(spirv.size() / sizeof(std::uint32_t));
  if (!spirv.empty()) std::memcpy(s.spirv.data(), spirv.data(), spirv.size());  // an empty vector's data() may be null
  return true;
}

void writeMaterial(EntryWriter& out, const CompiledMaterial& m) {
  for (const std::string* text : {&m.name, &m.fileStem, &m.contentHash, &m.reflectionJson, &m.cppHeader,
                                  &m.filamentMaterial})
    out.text(*text);
  out.word(m.stages.size());
  for (const auto& stage : m.stages) writeStage(out, stage);
  out.word(m.surfaces.size());
  for (const auto& surface : m.surfaces) out.text(surface);
}

bool readMaterial(EntryReader& in, CompiledMaterial& m) {
  for (std::string* text : {&m.name, &m.fileStem, &m.contentHash, &m.reflectionJson, &m.cppHeader,
                            &m.filamentMaterial})
    if (!in.text(*text)) return false;
  std::uint64_t count = 0;
  if (!in.word(count) || count > 16) return false;
  m.stages.resize(count);
  for (auto& stage : m.stages)
    if (!readStage(in, stage)) return false;
  if (!in.word(count) || count > 16) return false;
  m.surfaces.resize(count);
  for (auto& surface : m.surfaces)
    if (!in.text(surface)) return false;
  return true;
}

// The input files and their digests; false when one changed or is gone.
bool inputsUnchanged(EntryReader& in, std::vector<std::string>& files) {
  std::uint64_t count = 0;
  if (!in.word(count) || count > kMaxInputFiles) return false;
  for (std::uint64_t i = 0; i < count; ++i) {
    std::string path, digest;
    if (!in.text(path) || !in.text(digest) || fileDigest(path) != digest) return false;
    files.push_back(std::move(path));
  }
  return true;
}

// The entry's body, when it is whole: the magic, the body, then the body's digest.
std::optional<std::string_view> entryBody(std::string_view bytes) {
  constexpr std::size_t kDigestChars = 32;
  if (bytes.size() < kEntryMagic.size() + kDigestChars || bytes.substr(0, kEntryMagic.size()) != kEntryMagic)
    return std::nullopt;
  std::string_view body = bytes.substr(kEntryMagic.size(), bytes.size() - kEntryMagic.size() - kDigestChars);
  ContentDigest digest;
  digest.add(body);
  if (digest.hex() != bytes.substr(bytes.size() - kDigestChars)) return std::nullopt;
  return body;
}

// A name no other writer, thread or process, uses at the same time.
std::string temporaryName() {
  static std::atomic<std::uint64_t> counter{0};
  return std::string(kTemporaryPrefix) + std::to_string(::getpid()) + "." +
         std::to_string(std::hash<std::thread::id>{}(std::this_thread::get_id())) + "." + std::to_string(counter++);
}

enum class NewFile { NotCreated, Unwritten, Written };

// Creates `path`, which must not exist, and writes `bytes` to it. A file this call did
// not create is another writer's (one with our pid in another pid namespace), and is
// not ours to remove.
NewFile writeNewFile(const std::filesystem::path& path, std::string_view bytes) {
  int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return NewFile::NotCreated;
  bool ok = true;
  for (std::size_t done = 0; ok && done < bytes.size();) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    ok = n > 0;
    if (ok) done += static_cast<std::size_t>(n);
  }
  return ::close(fd) == 0 && ok ? NewFile::Written : NewFile::Unwritten;
}

// The material an entry holds, when it is whole and every file it read is unchanged.
// `buffer` is kept by each thread from one entry to the next, so that a warm run does
// not fault in fresh pages for every entry it reads.
std::optional<CompiledMaterial> readEntryFile(const std::filesystem::path& path, std::string& buffer) {
  if (readRegularFile(path.string(), kMaxEntryBytes, buffer).status != FileReadStatus::Ok) return std::nullopt;
  auto body = entryBody(buffer);
  if (!body) return std::nullopt;
  EntryReader in(*body);
  CompiledMaterial material;
  if (!inputsUnchanged(in, material.inputFiles) || !readMaterial(in, material) || !in.finished()) return std::nullopt;
  return material;
}

// Only names the cache writes are trimmed: a directory named with --cache may hold the
// user's own files (a tmp.log, a notes.entry), which are not the cache's to remove.
bool isEntryName(std::string_view name) {
  constexpr std::size_t kKeyChars = 32;
  return name.size() == kKeyChars + kEntrySuffix.size() && name.substr(kKeyChars) == kEntrySuffix &&
         name.substr(0, kKeyChars).find_first_not_of("0123456789abcdef") == std::string_view::npos;
}

// tmp.PID.THREAD.N, as temporaryName() writes it.
bool isTemporaryName(std::string_view name) {
  if (name.substr(0, kTemporaryPrefix.size()) != kTemporaryPrefix) return false;
  const std::string_view rest = name.substr(kTemporaryPrefix.size());
  return !rest.empty() && rest.find_first_not_of("0123456789.") == std::string_view::npos &&
         std::count(rest.begin(), rest.end(), '.') == 2;
}

struct EntryFile {
  std::filesystem::path path;
  std::uintmax_t size;
  std::filesystem::file_time_type used;
};

}  // namespace

std::string compileCacheKey(const std::string& path, std::string_view text, const CompileOptions& options) {
  ContentDigest digest;
  digest.add(compilerBuildIdentity());
  addOptions(digest, options);
  digest.add(path);
  // A library included by absolute path records its textures relative to the graph's
  // folder, so the same relative path from another working directory is another compile.
  std::error_code ec;
  digest.add(std::filesystem::absolute(path, ec).string());
  digest.add(text);
  return digest.hex();
}

CompileCache::CompileCache(std::filesystem::path directory, std::uintmax_t maxBytes)
    : directory_(std::move(directory)), maxBytes_(maxBytes) {}

std::string CompileCache::prepare() const {
  std::error_code ec;
  std::filesystem::create_directories(directory_, ec);
  if (!std::filesystem::is_directory(directory_, ec))
    return "'" + quoteUserText(directory_.string()) + "' is not a directory and cannot be created; name another";
  if (::access(directory_.c_str(), W_OK | X_OK) != 0)
    return "'" + quoteUserText(directory_.string()) + "' is not writable; name another";
  return "";
}

std::filesystem::path CompileCache::entryPath(const std::string& key) const {
  return directory_ / (key + std::string(kEntrySuffix));
}

std::optional<CompiledMaterial> CompileCache::find(const std::string& key) const {
  const std::filesystem::path path = entryPath(key);
  // Kept up to a bound; a library's long-lived threads do not hold more for ever.
  constexpr std::size_t kKeptBufferBytes = 16u << 20;
  thread_local std::string buffer;
  std::optional<CompiledMaterial> material = readEntryFile(path, buffer);
  if (buffer.size() > kKeptBufferBytes) std::string().swap(buffer);
  if (material) ::utimensat(AT_FDCWD, path.c_str(), nullptr, 0);  // the entry's time is when it was last used
  return material;
}

void CompileCache::store(const std::string& key, const CompiledMaterial& material, std::int64_t compileStartNs) const {
  EntryWriter out;
  out.bytes() = kEntryMagic;
  out.word(material.inputFiles.size());
  for (const auto& file : material.inputFiles) {
    auto digest = fileDigest(file);
    if (!digest || modifiedSince(file, compileStartNs)) return;
    out.text(file);
    out.text(*digest);
  }
  writeMaterial(out, material);
  ContentDigest digest;
  digest.add(std::string_view(out.bytes()).substr(kEntryMagic.size()));
  out.bytes() += digest.hex();
  const std::filesystem::path temporary = directory_ / temporaryName();
  const NewFile written = writeNewFile(temporary, out.bytes());
  if (written == NewFile::NotCreated) return;  // a removed directory, or another writer's name
  std::error_code ec;
  if (written == NewFile::Unwritten || (std::filesystem::rename(temporary, entryPath(key), ec), ec)) {
    std::filesystem::remove(temporary, ec);  // a full disk: the cache is only a cache
    return;
  }
  ++stored_;
}

CompileResult CompileCache::compileFile(const std::string& path, const CompileOptions& options) const {
  CompileResult result;
  auto text = readGraphFile(path, result.diagnostics);
  if (!text) return result;
  return compileText(path, std::move(*text), options);
}

CompileResult CompileCache::compileText(const std::string& file, std::string text, const CompileOptions& options) const {
  const std::string key = compileCacheKey(file, text, options);
  CompileResult result;
  if (auto material = find(key)) {
    result.material = std::move(*material);
    return result;
  }
  const std::int64_t start = nowNs();
  result = compileMaterialText(file, std::move(text), options);
  if (result.material && result.diagnostics.items().empty()) store(key, *result.material, start);
  return result;
}

void CompileCache::trim() const {
  if (stored_ == 0) return;  // nothing grew: a warm run does not list the directory
  constexpr auto kAbandoned = std::chrono::hours(1);
  const auto now = std::filesystem::file_time_type::clock::now();
  std::vector<EntryFile> entries;
  std::uintmax_t total = 0;
  std::error_code ec;
  for (const auto& item : std::filesystem::directory_iterator(directory_, ec)) {
    const std::string name = item.path().filename().string();
    std::error_code itemError;
    const auto used = item.last_write_time(itemError);
    const auto size = item.file_size(itemError);
    if (itemError) continue;  // removed by another process meanwhile
    if (isTemporaryName(name) && now - used > kAbandoned) std::filesystem::remove(item.path(), itemError);
    if (!isEntryName(name)) continue;
    entries.push_back({item.path(), size, used});
    total += size;
  }
  if (total <= maxBytes_) return;
  std::sort(entries.begin(), entries.end(), [](const EntryFile& a, const EntryFile& b) { return a.used < b.used; });
  for (const auto& entry : entries) {
    if (total <= maxBytes_ / 4 * 3) break;
    std::error_code removeError;
    std::filesystem::remove(entry.path, removeError);
    total -= entry.size;
  }
}

}  // namespace wg
