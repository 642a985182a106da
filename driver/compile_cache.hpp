// A persistent, content-addressed cache of compiled materials, shared by processes
// (weathergen compile --cache DIR; docs/build-integration.md, "The compile cache").
//
// An entry is keyed by a digest of the compiler's build, the options, the graph's path
// (as given and made absolute) and its text. It records every other file the compile read (graph libraries, images)
// with the digest of its content; a lookup whose files no longer match misses. Entries
// are written to a temporary file and renamed into place, so a reader sees a whole
// entry or none, and each carries a digest of itself, so a torn one is a miss too.
// Only compiles without diagnostics are stored, so a warning is printed on every run.
#pragma once
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "driver/material_compiler.hpp"

namespace wg {

// The default bound on the bytes a cache directory holds; trim() evicts the least
// recently used entries beyond it.
inline constexpr std::uintmax_t kDefaultCompileCacheBytes = 1024ull * 1024 * 1024;

class CompileCache {
 public:
  explicit CompileCache(std::filesystem::path directory, std::uintmax_t maxBytes = kDefaultCompileCacheBytes);

  // Creates the directory; "" or what is wrong with it, naming it.
  std::string prepare() const;

  // The graph file compiled with `options`: from an entry whose inputs are unchanged, or
  // compiled and then stored. A material from an entry has an empty IR.
  CompileResult compileFile(const std::string& path, const CompileOptions& options) const;
  // The same for a graph's text already in memory; `file` names it as compileMaterialText's does.
  CompileResult compileText(const std::string& file, std::string text, const CompileOptions& options) const;

  // After a run that stored entries: once the directory holds more than its bound,
  // evicts the least recently used entries down to three quarters of it, and removes
  // temporary files that writers left over an hour ago. Thread-safe with compileFile
  // and compileText.
  void trim() const;

  const std::filesystem::path& directory() const { return directory_; }

 private:
  std::optional<CompiledMaterial> find(const std::string& key) const;
  void store(const std::string& key, const CompiledMaterial& material, std::int64_t compileStartNs) const;
  std::filesystem::path entryPath(const std::string& key) const;

  std::filesystem::path directory_;
  std::uintmax_t maxBytes_;
  mutable std::atomic<std::size_t> stored_{0};
};

// The cache key of one compile: hex digest of the compiler build, options, path (as
// given and absolute) and text.
std::string compileCacheKey(const std::string& path, std::string_view text, const CompileOptions& options);

}  // namespace wg
