// A command's options as one table: each row names an option, says whether it takes a
// value, documents it and sets it. One parser reads every command's arguments with the
// grammar of command_line.hpp, and the option listing of --help is made from the same rows.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cli/command_line.hpp"

namespace wg {

// Takes the option's value ("" for a flag) or an operand; returns "" or the usage message.
using OptionSetter = std::function<std::string(const std::string&)>;

struct Option {
  std::string_view name;       // "--output", or a short option with no long name ("-j", "-O0")
  std::string_view alias;      // a short spelling of `name` ("-o"), or ""
  std::string_view valueName;  // "DIR" in "--output DIR"; "" for a flag, which takes none
  std::string_view help;       // its lines, '\n' between; "" leaves it out of the listing
  OptionSetter set;            // null: another form of the row above, listed only
  bool stops = false;          // nothing after it is read (a --help that prints at once)
};

struct OptionTable {
  std::vector<Option> options;
  // What an argument that is no option is given to. Null: the command takes none, and
  // every argument, "--" included, is read as an option.
  OptionSetter operand;
  bool dashIsOperand = true;       // "-" alone: an operand, or else an unknown option
  std::string_view unknownSuffix;  // after "unknown option 'X'" when no option name is close
  int helpColumn = 27;             // where the listing's descriptions start
};

enum class OptionParse { Finished, Stopped, Failed };

struct OptionParseResult {
  OptionParse status = OptionParse::Finished;
  std::string error;  // the usage message when Failed
};

// Reads every argument in order; the first setter to fail ends the parse.
OptionParseResult parseOptions(const OptionTable& table, CommandLine& args);
OptionParseResult parseOptions(const OptionTable& table, int argc, char** argv, int first);

// Setters for the common rows: store the value; set a flag to `value`.
OptionSetter storeValue(std::string& target);
OptionSetter storeFlag(bool& target, bool value = true);
// Stores the value when `check` returns "" for it (a weather preset, an IR pass name).
OptionSetter storeChecked(std::optional<std::string>& target, std::string (*check)(const std::string&));

// The listed rows as help lines: "  -o DIR, --output DIR       output directory\n".
std::string formatOptionList(const OptionTable& table);

}  // namespace wg
