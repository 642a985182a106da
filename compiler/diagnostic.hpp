// Diagnostics as values: a code from the table, a rendered message and hint, and a
// source span (file, line, column, JSON pointer).
#pragma once
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/diagnostic_codes.hpp"

namespace wg {

struct SourceLocation {
  std::string file;     // as the user named it
  std::string pointer;  // RFC 6901 JSON pointer, "" for the whole document
  int line = 0;         // 1-based; 0 when unknown
  int column = 0;
};

struct Diagnostic {
  DiagCode code;
  SourceLocation location;
  std::string message;
  std::string hint;

  const DiagnosticInfo& info() const { return diagnosticInfo(code); }
};

// Fills a template from args: "{0}".."{9}" by position, and "{name}" by the name's
// position in `arguments` (a table row's space-separated argument names).
std::string fillTemplate(std::string_view pattern, std::initializer_list<std::string_view> args,
                         std::string_view arguments = {});

class DiagnosticList {
 public:
  // Renders message and hint from the table; args fill both templates, in the order of
  // the row's named arguments (diagnostic_codes.cpp). A debug build throws
  // std::logic_error when a row with named arguments gets a different number of values.
  Diagnostic& report(DiagCode code, SourceLocation location,
                     std::initializer_list<std::string_view> args = {});
  void append(const DiagnosticList& other);
  bool hasErrors() const;
  bool contains(DiagCode code) const;
  const std::vector<Diagnostic>& items() const { return items_; }
  std::vector<Diagnostic>& items() { return items_; }
  bool empty() const { return items_.empty(); }

 private:
  std::vector<Diagnostic> items_;
};

// "error" or "warning", as the text and JSON forms spell it.
std::string_view severityName(Severity s);
// "file:line:col: error WG2001: message [/json/pointer]\n  hint: ...\n"
std::string formatDiagnosticText(const Diagnostic& d);
// A JSON array of {code, severity, name, file, line, column, pointer, message, hint}.
std::string formatDiagnosticsJson(const std::vector<Diagnostic>& list);

// "did you mean 'x'?" from candidates by edit distance, or "" when none is close.
std::string suggestClosest(std::string_view word, const std::vector<std::string_view>& candidates);

// The one hint for an unknown name: "did you mean 'x'?" when a candidate is close;
// otherwise `label` and every candidate ("known fields: id op inputs"), or `otherwise`
// when listing them would not help (hundreds of ops, a graph's node ids).
std::string unknownNameHint(std::string_view word, const std::vector<std::string_view>& candidates,
                            std::string_view label);
std::string unknownNameHintOr(std::string_view word, const std::vector<std::string_view>& candidates,
                              std::string_view otherwise);

// "a, b, c": names listed in a hint.
std::string listNames(const std::vector<std::string>& names);

}  // namespace wg
