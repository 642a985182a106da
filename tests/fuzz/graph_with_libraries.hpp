// One fuzz input as a graph and the graph libraries it may include: the text before
// the first kLibrarySeparator is the graph, each later part a library written to
// lib1.json, lib2.json, ... next to it, so `"include": {"a": "lib1.json"}` (and a
// library including "lib2.json") reads them from disk as the CLI would. The graph fuzz
// target and tests/unit/fuzz_regression_test.cpp both compile through here.
#pragma once
#include <stdlib.h>  // mkdtemp

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include "driver/material_compiler.hpp"

namespace wg::fuzz {

// Never inside valid JSON (a raw newline cannot be in a string), so every old graph
// input still reads as a graph alone.
inline constexpr std::string_view kLibrarySeparator = "\n---\n";
// More would only multiply file writes per input; four already allow nesting and cycles.
inline constexpr std::size_t kMaxLibraries = 4;

struct GraphWithLibraries {
  std::string graph;
  std::vector<std::string> libraries;  // at most kMaxLibraries; the rest is ignored
};

inline GraphWithLibraries splitGraphInput(std::string_view input) {
  GraphWithLibraries out;
  std::size_t at = input.find(kLibrarySeparator);
  out.graph = std::string(input.substr(0, at));
  while (at != std::string_view::npos && out.libraries.size() < kMaxLibraries) {
    const std::size_t begin = at + kLibrarySeparator.size();
    at = input.find(kLibrarySeparator, begin);
    out.libraries.emplace_back(input.substr(begin, at == std::string_view::npos ? at : at - begin));
  }
  return out;
}

inline std::string libraryFileName(std::size_t index) { return "lib" + std::to_string(index + 1) + ".json"; }

// Writes the libraries into `dir` (removing those of an earlier input that this one
// lacks) and compiles the graph as `dir`/graph.json. SPIR-V stays off: glslang only
// ever sees text we generated.
inline CompileResult compileGraphWithLibraries(std::string_view input, const std::filesystem::path& dir) {
  GraphWithLibraries parts = splitGraphInput(input);
  for (std::size_t i = 0; i < kMaxLibraries; ++i) {
    const std::filesystem::path file = dir / libraryFileName(i);
    if (i < parts.libraries.size()) {
      std::ofstream(file, std::ios::binary | std::ios::trunc) << parts.libraries[i];
    } else {
      std::error_code ec;
      std::filesystem::remove(file, ec);
    }
  }
  CompileOptions options;
  options.emitSpirv = false;
  return compileMaterialText((dir / "graph.json").string(), std::move(parts.graph), options);
}

// A fresh directory under TMPDIR (or /tmp) for one process's library files.
inline std::filesystem::path makeFuzzDirectory() {
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/wg-fuzz-XXXXXX";
  if (!mkdtemp(pattern.data())) std::abort();
  return pattern;
}

}  // namespace wg::fuzz
