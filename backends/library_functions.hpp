// A stage emits only the library functions it reaches. Each library's text is split
// once into its top-level functions (each with the comments above it and the library
// functions it calls); a stage's roots are the calls of its ops' templates and of its
// frame, both known once; the functions reached from those are emitted in library
// order. glslang drops uncalled functions from the SPIR-V anyway, so the modules are
// unchanged, but it must still parse them: the weather library was a third of a
// weathered vertex stage's text.
#pragma once
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

#include "backends/shader_syntax.hpp"

namespace wg {

// Calls each library function named in text: every library function is named wg_...,
// so these are the wg_ names followed by "(". Comments are not told apart.
template <typename OnCall>
void forEachLibraryCall(std::string_view text, OnCall&& onCall) {
  auto identifierChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t at = text.find("wg_"); at != std::string_view::npos; at = text.find("wg_", at)) {
    std::size_t end = at + 3;
    while (end < text.size() && identifierChar(text[end])) ++end;
    bool starts = at == 0 || !identifierChar(text[at - 1]);
    std::size_t next = end;
    while (next < text.size() && text[next] == ' ') ++next;
    if (starts && next < text.size() && text[next] == '(') onCall(text.substr(at, end - at));
    at = end;
  }
}

// The library pieces a stage's roots reach, directly or through others, in library
// order, for callers to print each their own way (a surface guards each, so that
// several surfaces can share one shader). A library outside the op registry (tests
// make some) is one piece, whole.
struct ReachedPiece {
  std::string_view text;      // in the syntax's language
  std::string_view function;  // empty: loose text of its library (comments, globals)
  const ShaderLibrary* library;
  std::size_t index;          // the piece's place in its library
  bool libraryReached;        // some function of its library is reached
  bool registered = true;     // of a library in the op registry: its text lives as long as the program
};
std::vector<ReachedPiece> reachedLibraryPieces(const ShaderSyntax& syntax,
                                               const std::vector<const ShaderLibrary*>& libraries,
                                               const std::vector<std::string_view>& roots);

// The top-level pieces of a library text: a function with the comments above it and
// the rest of its closing line, or loose text (comments, globals) with no name.
struct LibraryPiece {
  std::string_view text;
  std::string_view function;  // empty: not a function, always kept
  std::vector<std::string_view> calls;
};
std::vector<LibraryPiece> splitLibrary(std::string_view text);

}  // namespace wg
