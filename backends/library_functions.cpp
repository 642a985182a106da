#include "backends/library_functions.hpp"

#include <array>
#include <unordered_map>

#include "backends/derived_hlsl.hpp"
#include "nodes/op_registry.hpp"

namespace wg {

namespace {

// Copies of the text without its comments keep the scan simple; only the split
// positions refer back to the original.
std::string withoutComments(std::string_view text) {
  std::string code(text);
  for (std::size_t i = 0; i + 1 < code.size(); ++i) {
    if (code[i] == '/' && code[i + 1] == '/') {
      while (i < code.size() && code[i] != '\n') code[i++] = ' ';
    } else if (code[i] == '/' && code[i + 1] == '*') {
      std::size_t end = code.find("*/", i + 2);
      end = end == std::string::npos ? code.size() : end + 2;
      for (; i < end; ++i)
        if (code[i] != '\n') code[i] = ' ';
    }
  }
  return code;
}

LibraryPiece pieceOf(std::string_view text, std::string_view code) {
  LibraryPiece piece{text, {}, {}};
  std::size_t open = code.find('{');
  forEachLibraryCall(code, [&](std::string_view name) {
    std::size_t at = static_cast<std::size_t>(name.data() - code.data());
    if (piece.function.empty() && at < open) piece.function = text.substr(at, name.size());
    else piece.calls.push_back(text.substr(at, name.size()));
  });
  return piece;
}

// Every registered library's pieces in one language; functions by number, with the
// numbers of the functions each calls.
constexpr std::size_t kAlwaysKept = static_cast<std::size_t>(-1);

struct EmittedPiece {
  std::string_view text;
  std::size_t function;   // kAlwaysKept: loose text
  std::string_view name;  // the function's
};

struct LanguageIndex {
  std::unordered_map<const char*, std::vector<LibraryPiece>> piecesByText;  // by the library text's address
  std::unordered_map<std::string_view, std::size_t> functionIds;
  std::vector<std::vector<std::size_t>> callsOf;
  std::unordered_map<const char*, std::vector<EmittedPiece>> emittedByText;

  void add(std::string_view text) {
    if (piecesByText.contains(text.data())) return;
    for (const auto& piece : piecesByText[text.data()] = splitLibrary(text))
      if (!piece.function.empty()) functionIds.emplace(piece.function, functionIds.size());
  }
  void linkCalls() {
    callsOf.resize(functionIds.size());
    for (const auto& [text, pieces] : piecesByText) {
      auto& emitted = emittedByText[text];
      for (const auto& piece : pieces) {
        std::size_t id = piece.function.empty() ? kAlwaysKept : functionIds.at(piece.function);
        emitted.push_back({piece.text, id, piece.function});
        if (id == kAlwaysKept) continue;
        for (std::string_view call : piece.calls)
          if (auto callee = functionIds.find(call); callee != functionIds.end()) callsOf[id].push_back(callee->second);
      }
    }
  }
};

struct LibraryIndex {
  std::array<LanguageIndex, 2> byLanguage;
  LibraryIndex() {
    for (const ShaderLibrary* library : allShaderLibraries()) {
      byLanguage[0].add(library->glsl);
      byLanguage[1].add(derivedHlsl(*library));
    }
    for (auto& language : byLanguage) language.linkCalls();
  }
};

const LanguageIndex& indexFor(ShaderLanguage language) {
  static const LibraryIndex index;
  return index.byLanguage[language == ShaderLanguage::Glsl ? 0 : 1];
}

}  // namespace

std::vector<LibraryPiece> splitLibrary(std::string_view text) {
  const std::string code = withoutComments(text);
  std::vector<LibraryPiece> pieces;
  std::size_t start = 0;
  int depth = 0;
  for (std::size_t i = 0; i < code.size(); ++i) {
    if (code[i] == '{') ++depth;
    bool closesFunction = code[i] == '}' && --depth == 0;
    bool endsDeclaration = code[i] == ';' && depth == 0;  // a global: kept, whatever calls it
    if (!closesFunction && !endsDeclaration) continue;
    std::size_t end = code.find('\n', i);
    end = end == std::string::npos ? code.size() : end + 1;
    std::string_view pieceText = text.substr(start, end - start);
    if (closesFunction) pieces.push_back(pieceOf(pieceText, std::string_view(code).substr(start, end - start)));
    else pieces.push_back({pieceText, {}, {}});
    start = end;
    i = end - 1;
  }
  if (start < text.size()) pieces.push_back({text.substr(start), {}, {}});
  return pieces;
}

std::vector<ReachedPiece> reachedLibraryPieces(const ShaderSyntax& syntax,
                                               const std::vector<const ShaderLibrary*>& libraries,
                                               const std::vector<std::string_view>& roots) {
  const LanguageIndex& index = indexFor(syntax.language());
  std::vector<bool> reached(index.callsOf.size(), false);
  std::vector<std::size_t> pending;
  for (std::string_view root : roots)
    if (auto id = index.functionIds.find(root); id != index.functionIds.end()) pending.push_back(id->second);
  while (!pending.empty()) {
    std::size_t id = pending.back();
    pending.pop_back();
    if (reached[id]) continue;
    reached[id] = true;
    pending.insert(pending.end(), index.callsOf[id].begin(), index.callsOf[id].end());
  }
  std::vector<ReachedPiece> out;
  for (const ShaderLibrary* library : libraries) {
    std::string_view text = syntax.libraryCode(*library);
    auto pieces = index.emittedByText.find(text.data());
    if (pieces == index.emittedByText.end()) {
      out.push_back({text, {}, library, 0, true, false});
      continue;
    }
    bool libraryReached = false;
    for (const EmittedPiece& piece : pieces->second)
      libraryReached = libraryReached || (piece.function != kAlwaysKept && reached[piece.function]);
    for (std::size_t i = 0; i < pieces->second.size(); ++i) {
      const EmittedPiece& piece = pieces->second[i];
      if (piece.function == kAlwaysKept) out.push_back({piece.text, {}, library, i, libraryReached});
      else if (reached[piece.function]) out.push_back({piece.text, piece.name, library, i, true});
    }
  }
  return out;
}

}  // namespace wg
