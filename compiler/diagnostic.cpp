#include "compiler/diagnostic.hpp"

#include "compiler/json_text.hpp"
#include "compiler/literal.hpp"

#include <algorithm>
#include <stdexcept>
#include <nlohmann/json.hpp>

namespace wg {

std::string fillTemplate(std::string_view pattern, std::initializer_list<std::string_view> args,
                         std::string_view arguments) {
  // The index of a named placeholder among the space-separated argument names.
  auto indexOf = [&](std::string_view name) {
    std::size_t index = 0, start = 0;
    while (start < arguments.size()) {
      std::size_t end = std::min(arguments.find(' ', start), arguments.size());
      if (arguments.substr(start, end - start) == name) return index;
      ++index;
      start = end + 1;
    }
    return args.size();  // unknown: filled with nothing (the table check forbids it)
  };
  std::string out;
  out.reserve(pattern.size() + 32);
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    std::size_t end = pattern[i] == '{' ? pattern.find('}', i) : std::string_view::npos;
    if (end == std::string_view::npos || end == i + 1) {
      out += pattern[i];
      continue;
    }
    std::string_view name = pattern.substr(i + 1, end - i - 1);
    std::size_t index = name.size() == 1 && name[0] >= '0' && name[0] <= '9' ? static_cast<std::size_t>(name[0] - '0')
                                                                             : indexOf(name);
    if (index < args.size()) out += *(args.begin() + index);
    i = end;
  }
  return out;
}

Diagnostic& DiagnosticList::report(DiagCode code, SourceLocation location,
                                   std::initializer_list<std::string_view> args) {
  const auto& info = diagnosticInfo(code);
#ifndef NDEBUG
  if (!info.arguments.empty() && args.size() != diagnosticArgumentCount(info))
    throw std::logic_error(std::string(info.id) + " takes " + std::to_string(diagnosticArgumentCount(info)) +
                           " values (" + std::string(info.arguments) + "), not " + std::to_string(args.size()));
#endif
  items_.push_back({code, std::move(location), fillTemplate(info.messageTemplate, args, info.arguments),
                    fillTemplate(info.hintTemplate, args, info.arguments)});
  return items_.back();
}

void DiagnosticList::append(const DiagnosticList& other) {
  items_.insert(items_.end(), other.items_.begin(), other.items_.end());
}

bool DiagnosticList::hasErrors() const {
  return std::any_of(items_.begin(), items_.end(),
                     [](const Diagnostic& d) { return d.info().severity == Severity::Error; });
}

bool DiagnosticList::contains(DiagCode code) const {
  return std::any_of(items_.begin(), items_.end(),
                     [code](const Diagnostic& d) { return d.code == code; });
}

std::string_view severityName(Severity s) { return s == Severity::Error ? "error" : "warning"; }

// The file name and the pointer come from user text (paths, JSON keys): control
// characters in them never reach the terminal raw.
namespace {
// A last defence for the terminal: callers quote user text, but a message or hint must
// never carry a control character whatever path built it. Newlines stay: compiler logs
// in internal diagnostics span lines.
std::string withoutControls(const std::string& text) {
  std::string out;
  std::size_t start = 0;
  for (std::size_t nl = text.find('\n'); ; nl = text.find('\n', start)) {
    const std::size_t end = nl == std::string::npos ? text.size() : nl;
    out += quoteUserText(std::string_view(text).substr(start, end - start), std::string::npos);
    if (nl == std::string::npos) return out;
    out += '\n';
    start = nl + 1;
  }
}
}  // namespace

std::string formatDiagnosticText(const Diagnostic& d) {
  constexpr std::size_t kShown = 1024;
  std::string out = d.location.file.empty() ? std::string("weathergen") : quoteUserText(d.location.file, kShown);
  if (d.location.line > 0)
    out += ":" + std::to_string(d.location.line) + ":" + std::to_string(d.location.column);
  out += ": ";
  out += severityName(d.info().severity);
  out += " ";
  out += d.info().id;
  out += ": " + withoutControls(d.message);
  if (!d.location.file.empty()) out += " [" + (d.location.pointer.empty() ? "/" : quoteUserText(d.location.pointer, kShown)) + "]";
  out += "\n";
  if (!d.hint.empty()) out += "  hint: " + withoutControls(d.hint) + "\n";
  return out;
}

std::string formatDiagnosticsJson(const std::vector<Diagnostic>& list) {
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const auto& d : list) {
    array.push_back({{"code", d.info().id},
                     {"severity", severityName(d.info().severity)},
                     {"name", d.info().name},
                     {"file", d.location.file},
                     {"line", d.location.line},
                     {"column", d.location.column},
                     {"pointer", d.location.pointer},
                     {"message", d.message},
                     {"hint", d.hint}});
  }
  // Replace invalid UTF-8 from hostile input rather than throwing.
  return jsonText(array, 2) + "\n";
}

namespace {
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}
}  // namespace

std::string listNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string suggestClosest(std::string_view word, const std::vector<std::string_view>& candidates) {
  if (word.size() > 64) return "";
  std::string_view best;
  std::size_t bestDistance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (auto c : candidates) {
    std::size_t d = editDistance(word, c);
    if (d < bestDistance) {
      bestDistance = d;
      best = c;
    }
  }
  return best.empty() ? std::string() : "did you mean '" + quoteUserText(best) + "'?";
}

std::string unknownNameHint(std::string_view word, const std::vector<std::string_view>& candidates,
                            std::string_view label) {
  if (std::string hint = suggestClosest(word, candidates); !hint.empty()) return hint;
  std::string hint = std::string(label) + ":";
  for (auto c : candidates) hint += " " + quoteUserText(c);
  if (candidates.empty()) hint += " none";
  return hint;
}

std::string unknownNameHintOr(std::string_view word, const std::vector<std::string_view>& candidates,
                              std::string_view otherwise) {
  std::string hint = suggestClosest(word, candidates);
  return hint.empty() ? std::string(otherwise) : hint;
}

}  // namespace wg
