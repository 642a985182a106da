#include "cli/option_table.hpp"

#include <algorithm>
#include <optional>

#include "compiler/diagnostic.hpp"
#include "compiler/literal.hpp"

namespace wg {

namespace {

bool takesValue(const Option& o) { return !o.valueName.empty(); }

bool isOperand(const OptionTable& table, const CommandLine& args) {
  const std::string& arg = args.peek();
  return args.endOfOptions() || arg.empty() || arg[0] != '-' || (arg == "-" && table.dashIsOperand);
}

// The row an argument names exactly ("--output", "-o"), or null.
const Option* exactRow(const OptionTable& table, const std::string& arg) {
  for (const auto& o : table.options)
    if (o.set && (arg == o.name || (!o.alias.empty() && arg == o.alias))) return &o;
  return nullptr;
}

// "unknown option 'X'", with a did-you-mean among the long names when one is close.
std::string unknownOption(const OptionTable& table, const std::string& arg) {
  std::string message = "unknown option '" + quoteUserText(arg) + "'";
  std::vector<std::string_view> names;
  for (const auto& o : table.options)
    for (std::string_view n : {o.name, o.alias})
      if (o.set && n.starts_with("--")) names.push_back(n);
  std::string hint;
  if (arg.starts_with("--")) hint = unknownNameHintOr(arg.substr(0, arg.find('=')), names, "");
  return message + (hint.empty() ? std::string(table.unknownSuffix) : "; " + hint);
}

// The value of the row `only` (or of any row taking one) spelt by the front argument:
// "--x v", "--x=v", "-xV". Sets `row`, or `error` when the value is missing.
std::optional<std::string> readValue(const OptionTable& table, CommandLine& args, const Option* only,
                                     const Option*& row, std::string& error) {
  for (const auto& o : table.options) {
    if (!o.set || !takesValue(o) || (only && only != &o)) continue;
    for (std::string_view n : {o.name, o.alias}) {
      if (n.empty()) continue;
      auto value = args.valueFor(std::string(n), error);
      if (value) row = &o;
      if (value || !error.empty()) return value;
    }
  }
  return std::nullopt;
}

// Reads the option at the front of `args` into its row. Exact names come first, so a
// flag such as -O0 never reads as -O with the value 0.
OptionParseResult readOption(const OptionTable& table, CommandLine& args) {
  const Option* row = exactRow(table, args.peek());
  std::optional<std::string> value;
  std::string error;
  if (row && !takesValue(*row)) {
    args.next();
    value = "";
  } else {
    value = readValue(table, args, row, row, error);
  }
  if (!error.empty()) return {OptionParse::Failed, error};
  if (!value) return {OptionParse::Failed, unknownOption(table, args.peek())};
  if (std::string e = row->set(*value); !e.empty()) return {OptionParse::Failed, e};
  return {row->stops ? OptionParse::Stopped : OptionParse::Finished, ""};
}

}  // namespace

OptionParseResult parseOptions(const OptionTable& table, CommandLine& args) {
  while (!args.done()) {
    if (table.operand && !args.endOfOptions() && args.peek() == "--") {
      args.next();
      args.markEndOfOptions();
      continue;
    }
    if (table.operand && isOperand(table, args)) {
      if (std::string e = table.operand(args.next()); !e.empty()) return {OptionParse::Failed, e};
      continue;
    }
    if (OptionParseResult r = readOption(table, args); r.status != OptionParse::Finished) return r;
  }
  return {};
}

OptionParseResult parseOptions(const OptionTable& table, int argc, char** argv, int first) {
  CommandLine args(argc, argv, first);
  return parseOptions(table, args);
}

OptionSetter storeValue(std::string& target) {
  return [&target](const std::string& value) {
    target = value;
    return std::string();
  };
}

OptionSetter storeFlag(bool& target, bool value) {
  return [&target, value](const std::string&) {
    target = value;
    return std::string();
  };
}

OptionSetter storeChecked(std::optional<std::string>& target, std::string (*check)(const std::string&)) {
  return [&target, check](const std::string& value) {
    std::string error = check(value);
    if (error.empty()) target = value;
    return error;
  };
}

std::string formatOptionList(const OptionTable& table) {
  std::string out;
  for (const auto& o : table.options) {
    if (o.help.empty()) continue;
    const std::string value = takesValue(o) ? " " + std::string(o.valueName) : "";
    std::string left = (o.alias.empty() ? "" : std::string(o.alias) + value + ", ") + std::string(o.name) + value;
    std::string_view help = o.help;
    while (true) {
      const std::size_t end = help.find('\n');
      left.resize(std::max<std::size_t>(left.size() + 1, static_cast<std::size_t>(table.helpColumn)), ' ');
      out += "  " + left + std::string(help.substr(0, end)) + "\n";
      if (end == std::string_view::npos) break;
      help.remove_prefix(end + 1);
      left.clear();
    }
  }
  return out;
}

}  // namespace wg
