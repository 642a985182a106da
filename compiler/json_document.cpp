#include "compiler/json_document.hpp"

#include <algorithm>
#include <vector>

#include "compiler/json_reader.hpp"
#include "nodes/regular_file.hpp"

namespace wg {

std::string appendPointer(const std::string& pointer, std::string_view token) {
  std::string out = pointer;
  out += '/';
  for (char c : token) {
    if (c == '~') out += "~0";
    else if (c == '/') out += "~1";
    else out += c;
  }
  return out;
}

std::string appendPointer(const std::string& pointer, std::size_t index) {
  return pointer + "/" + std::to_string(index);
}

namespace {

// Walks already-validated JSON text with an explicit stack (no recursion, so hostile
// nesting cannot overflow), calling onValue(pointer, line, col) for every value and
// onDuplicate(pointer, line, col, key) for repeated keys.
struct TextScanner {
  const std::string& text;
  std::size_t pos = 0;
  int line = 1;
  int column = 1;

  char peek() const { return pos < text.size() ? text[pos] : '\0'; }
  void advance() {
    if (text[pos] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[pos]) & 0xC0) != 0x80) {
      ++column;  // count UTF-8 code points, not bytes
    }
    ++pos;
  }
  void skipSpace() {
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t' || text[pos] == '\n' ||
                                 text[pos] == '\r'))
      advance();
  }
  static void appendUtf8(std::string& out, unsigned cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }
  unsigned hex4() {
    unsigned v = 0;
    for (int i = 0; i < 4; ++i) {
      char c = peek();
      advance();
      v <<= 4;
      if (c >= '0' && c <= '9') v |= static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f') v |= static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F') v |= static_cast<unsigned>(c - 'A' + 10);
    }
    return v;
  }
  std::string readString() {  // at the opening quote
    advance();
    // Fast path: most keys have no escapes. Raw JSON strings hold no newlines, so only
    // the column moves.
    std::size_t end = pos;
    while (end < text.size() && text[end] != '"' && text[end] != '\\') ++end;
    if (end < text.size() && text[end] == '"') {
      std::string out = text.substr(pos, end - pos);
      for (; pos < end; ++pos)
        if ((static_cast<unsigned char>(text[pos]) & 0xC0) != 0x80) ++column;
      advance();
      return out;
    }
    std::string out;
    while (pos < text.size() && text[pos] != '"') {
      if (text[pos] == '\\') {
        advance();
        char e = peek();
        advance();
        switch (e) {
          case 'n': out += '\n'; break;
          case 't': out += '\t'; break;
          case 'r': out += '\r'; break;
          case 'b': out += '\b'; break;
          case 'f': out += '\f'; break;
          case 'u': {
            unsigned cp = hex4();
            if (cp >= 0xD800 && cp < 0xDC00 && peek() == '\\') {
              advance();
              advance();
              unsigned low = hex4();
              cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
            }
            appendUtf8(out, cp);
            break;
          }
          default: out += e;
        }
      } else {
        out += text[pos];
        advance();
      }
    }
    if (pos < text.size()) advance();
    return out;
  }
  void skipScalar() {
    while (pos < text.size()) {
      char c = text[pos];
      if (c == ',' || c == ']' || c == '}' || c == ' ' || c == '\n' || c == '\r' || c == '\t') break;
      advance();
    }
  }

  // trackPointers: build every value's pointer (for the location index); without it
  // only the keys are compared, and a pointer is built for a duplicate alone.
  template <typename OnValue, typename OnKey, typename OnDuplicate>
  void scan(OnValue&& onValue, OnKey&& onKey, OnDuplicate&& onDuplicate, bool trackPointers = true) {
    struct Frame {
      bool isObject;
      std::string pointer;
      std::size_t index = 0;
      std::vector<std::string> keys;
    };
    auto pointerOf = [](const std::vector<Frame>& frames) {
      std::string p;
      for (const auto& f : frames)
        p = f.isObject ? appendPointer(p, f.keys.empty() ? std::string() : f.keys.back()) : appendPointer(p, f.index - 1);
      return p;
    };
    std::vector<Frame> stack;
    std::string currentPointer;
    skipSpace();
    while (true) {
      // At the start of a value whose pointer is currentPointer.
      skipSpace();
      if (trackPointers) onValue(currentPointer, line, column);
      char c = peek();
      if (c == '{' || c == '[') {
        advance();
        stack.push_back({c == '{', trackPointers ? currentPointer : std::string(), 0, {}});
      } else if (c == '"') {
        readString();
      } else {
        skipScalar();
      }
      // Find the next value, closing containers as we go.
      bool haveNext = false;
      while (!stack.empty() && !haveNext) {
        skipSpace();
        Frame& top = stack.back();
        char d = peek();
        if (d == ',') {
          advance();
          skipSpace();
          d = peek();
        } else if (d == '}' || d == ']') {
          advance();
          stack.pop_back();
          continue;
        } else if (d == '\0') {
          return;
        }
        if (top.isObject) {
          if (d == '}') {
            advance();
            stack.pop_back();
            continue;
          }
          int keyLine = line, keyColumn = column;
          std::string key = readString();
          skipSpace();
          if (peek() == ':') advance();
          bool duplicate = std::find(top.keys.begin(), top.keys.end(), key) != top.keys.end();
          if (trackPointers) {
            std::string pointer = appendPointer(top.pointer, key);
            onKey(pointer, keyLine, keyColumn);
            if (duplicate) onDuplicate(pointer, keyLine, keyColumn, key);
            currentPointer = std::move(pointer);
          } else if (duplicate) {
            std::string pointer = appendPointer(pointerOf({stack.begin(), stack.end() - 1}), key);
            onDuplicate(pointer, keyLine, keyColumn, key);
          }
          // Keep the key last: pointerOf reads each object's current key from the back.
          auto seen = std::find(top.keys.begin(), top.keys.end(), key);
          if (seen != top.keys.end()) top.keys.erase(seen);
          top.keys.push_back(std::move(key));
        } else {
          if (d == ']') {
            advance();
            stack.pop_back();
            continue;
          }
          ++top.index;
          if (trackPointers) currentPointer = appendPointer(top.pointer, top.index - 1);
        }
        haveNext = true;
      }
      if (!haveNext) return;
    }
  }
};

int nestingDepth(const std::string& text) {
  int depth = 0, maxDepth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      maxDepth = std::max(maxDepth, ++depth);
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
  return maxDepth;
}

// nlohmann reports a byte offset; convert it to line:col for the diagnostic.
std::pair<int, int> lineColumnOfByte(const std::string& text, std::size_t byte) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++column;
    }
  }
  return {line, column};
}

// nlohmann's message without its "[json.exception...] " prefix and the position we
// already print as line:col.
std::string plainParseMessage(std::string what) {
  if (auto cut = what.find("] "); cut != std::string::npos) what = what.substr(cut + 2);
  if (what.starts_with("parse error at line ")) {
    if (auto colon = what.find(": "); colon != std::string::npos) what = "parse error: " + what.substr(colon + 2);
  }
  return what;
}

// The DOM by RapidJSON's reader when it can; false leaves root null for nlohmann's.
bool readFast(const std::string& text, nlohmann::json& root, std::size_t& keysRead, int maxDepth) {
  JsonDomBuilder builder(root);
  if (!readJsonEvents(text, builder, maxDepth)) {
    root = nlohmann::json();
    return false;
  }
  keysRead = builder.keysRead();
  return true;
}

// Members of every object in the document, walked with an explicit stack.
std::size_t memberCount(const nlohmann::json& root) {
  std::size_t members = 0;
  std::vector<const nlohmann::json*> pending{&root};
  while (!pending.empty()) {
    const nlohmann::json* value = pending.back();
    pending.pop_back();
    if (value->is_object()) members += value->size();
    if (value->is_structured())
      for (const auto& child : *value)
        if (child.is_structured()) pending.push_back(&child);
  }
  return members;
}

}  // namespace

JsonDocument::JsonDocument(std::string file, std::string text, nlohmann::json root)
    : file_(std::move(file)), text_(std::move(text)), root_(std::move(root)) {}

void JsonDocument::buildIndex() const {
  if (values_) return;
  values_ = std::make_unique<PositionIndex>();
  keys_ = std::make_unique<PositionIndex>();
  TextScanner scanner{text_};
  scanner.scan([&](const std::string& p, int l, int c) { values_->emplace(p, std::make_pair(l, c)); },
               [&](const std::string& p, int l, int c) { keys_->emplace(p, std::make_pair(l, c)); },
               [](const std::string&, int, int, const std::string&) {});
}

void JsonDocument::mount(std::string prefix, std::shared_ptr<const JsonDocument> document) {
  mounts_.emplace_back(std::move(prefix), std::move(document));
}

const JsonDocument* JsonDocument::mountedAt(const std::string& pointer, std::string& inner) const {
  for (const auto& [prefix, document] : mounts_)
    if (pointer.compare(0, prefix.size(), prefix) == 0 && (pointer.size() == prefix.size() || pointer[prefix.size()] == '/')) {
      inner = pointer.substr(prefix.size());
      return document.get();
    }
  return nullptr;
}

SourceLocation JsonDocument::locateKey(const std::string& pointer) const {
  std::string inner;
  if (const JsonDocument* mounted = mountedAt(pointer, inner)) return mounted->locateKey(inner);
  buildIndex();
  auto it = keys_->find(pointer);
  if (it == keys_->end()) return locate(pointer);
  return {file_, pointer, it->second.first, it->second.second};
}

SourceLocation JsonDocument::locate(const std::string& pointer) const {
  std::string inner;
  if (const JsonDocument* mounted = mountedAt(pointer, inner)) return mounted->locate(inner);
  buildIndex();
  std::string p = pointer;
  while (true) {
    auto it = values_->find(p);
    if (it != values_->end()) return {file_, pointer, it->second.first, it->second.second};
    auto slash = p.rfind('/');
    if (slash == std::string::npos) return {file_, pointer, 1, 1};
    p.resize(slash);
  }
}

SourceLocation locateInJsonFile(const std::string& path, const std::string& pointer) {
  std::string text;
  if (readRegularFile(path, JsonLimits{}.maxBytes, text).status != FileReadStatus::Ok) return {path, pointer, 0, 0};
  DiagnosticList ignored;
  auto document = parseJsonDocument(path, std::move(text), ignored);
  return document ? document->locate(pointer) : SourceLocation{path, pointer, 0, 0};
}

// The pointer of the value that starts at line:column ("" for none): the text is
// well-formed JSON up to there, as its parser has read that far.
std::string pointerOfValueAt(const std::string& text, int line, int column) {
  std::string found;
  TextScanner scanner{text};
  scanner.scan(
      [&](const std::string& pointer, int l, int c) {
        if (l == line && c == column && found.empty()) found = pointer;
      },
      [](const std::string&, int, int) {}, [](const std::string&, int, int, const std::string&) {});
  return found;
}

// The raw text's limits: nesting depth, and no NUL.
bool withinRawLimits(const std::string& file, const std::string& text, DiagnosticList& diagnostics,
                     const JsonLimits& limits) {
  if (int depth = nestingDepth(text); depth > limits.maxDepth) {
    diagnostics.report(DiagCode::ResourceLimit, {file, "", 1, 1},
                       {"the JSON nesting depth", std::to_string(depth), std::to_string(limits.maxDepth)});
    return false;
  }
  // nlohmann's lexer reads a NUL as the end of input, so whatever follows one would be
  // ignored silently: a binary or truncated file. JSON text never holds one raw.
  if (std::size_t nul = text.find('\0'); nul != std::string::npos) {
    auto [line, column] = lineColumnOfByte(text, nul);
    diagnostics.report(DiagCode::JsonSyntax, {file, "", line, column},
                       {"a NUL byte; JSON text cannot hold one (is the file binary or cut short?)"});
    return false;
  }
  return true;
}

// The raw text's limits, then nlohmann's parser, whose errors the diagnostics quote.
bool readSlowly(const std::string& file, const std::string& text, nlohmann::json& root, std::size_t& keysRead,
                DiagnosticList& diagnostics, const JsonLimits& limits) {
  if (!withinRawLimits(file, text, diagnostics, limits)) return false;
  JsonDomBuilder builder(root);
  try {
    nlohmann::json::sax_parse(text, &builder);
    keysRead = builder.keysRead();
  } catch (const nlohmann::json::parse_error& e) {
    auto [line, column] = lineColumnOfByte(text, e.byte > 0 ? e.byte - 1 : 0);
    diagnostics.report(DiagCode::JsonSyntax, {file, "", line, column}, {plainParseMessage(e.what())});
    return false;
  } catch (const nlohmann::json::out_of_range&) {
    // A number too large for a double ("1e999"): point at it and call it non-finite.
    auto [line, column] = lineColumnOfByte(text, builder.errorTokenStart());
    diagnostics.report(DiagCode::LiteralNotFinite, {file, pointerOfValueAt(text, line, column), line, column},
                       {"the number " + builder.errorToken()});
    return false;
  } catch (const std::exception& e) {
    diagnostics.report(DiagCode::JsonSyntax, {file, "", 1, 1}, {plainParseMessage(e.what())});
    return false;
  }
  return true;
}

std::optional<JsonDocument> parseJsonDocument(std::string file, std::string text,
                                              DiagnosticList& diagnostics, const JsonLimits& limits) {
  if (text.size() > limits.maxBytes) {
    diagnostics.report(DiagCode::ResourceLimit, {file, "", 1, 1},
                       {"the file size", std::to_string(text.size()) + " bytes",
                        std::to_string(limits.maxBytes) + " bytes"});
    return std::nullopt;
  }
  nlohmann::json root;
  std::size_t keysRead = 0;
  // The fast reader checks the depth as it goes; the checks of readSlowly run only
  // when it hands the text back, in their order.
  if (text.find('\0') != std::string::npos || !readFast(text, root, keysRead, limits.maxDepth))
    if (!readSlowly(file, text, root, keysRead, diagnostics, limits)) return std::nullopt;
  if (memberCount(root) == keysRead) return JsonDocument(std::move(file), std::move(text), std::move(root));
  bool duplicate = false;
  TextScanner scanner{text};
  scanner.scan([](const std::string&, int, int) {}, [](const std::string&, int, int) {},
               [&](const std::string& pointer, int l, int c, const std::string& key) {
                 diagnostics.report(DiagCode::DuplicateKey, {file, pointer, l, c}, {key});
                 duplicate = true;
               },
               /*trackPointers=*/false);
  if (duplicate) return std::nullopt;
  return JsonDocument(std::move(file), std::move(text), std::move(root));
}

}  // namespace wg
