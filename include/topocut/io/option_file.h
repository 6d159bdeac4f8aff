#pragma once
// Options from a YAML file (a robot's parameters in one place): the parser behind every command's
// --config, the library's load_segment_options() (topocut.h) and Python's topocut.load_options(), so
// that a file means the same thing, and is refused with the same message, wherever it is read.
// Keys are the long option names (robot_radius or robot-radius); a scalar is the option's value,
// true/false a switch's, a list several values.
#include <string>
#include <vector>

#include "topocut/core/error.h"
#include "topocut/core/option_names.h"
#include "topocut/core/option_table.h"

namespace topocut {

// A file that is YAML but not a mapping of option names to values or lists of values (the
// command line answers it as a usage error).
class OptionFileError : public Error {
 public:
  using Error::Error;
};

// One key of an options file and its value as the command line would take it.
struct OptionFileEntry {
  std::string key;                  // as written (robot_radius or robot-radius)
  std::string name;                 // dashed_option_name(key): the command's long name
  std::vector<std::string> values;  // the scalar, or each item of a list
  bool is_list = false;
  std::string where;                // "'key' in config file 'path'", how messages name it

  // The value of a switch: YAML's true or false (yes/no, on/off too). Throws OptionFileError naming
  // the key otherwise.
  bool switch_value() const;
  // The value of a number option, the whole scalar as a number. Throws OptionFileError naming the
  // key for a list or anything but a number.
  double number_value() const;
};

// The entries of the YAML mapping at path, in the file's order; an empty file has none. Throws
// FileError if the file cannot be opened, Error if it is too large (kMaxConfigYamlBytes) or not YAML,
// OptionFileError for a key or value of the wrong shape.
std::vector<OptionFileEntry> read_option_file(const std::string& path);

// The message for an entry whose name no table of the caller knows, with the closest known name.
std::string unknown_option_message(const OptionFileEntry& entry, const std::vector<std::string>& known,
                                   const std::string& what = "an option of this command");

// Sets in target every entry of entries through its row of rows, with the row's check (the message
// names the entry as the file does); an entry no row knows is an OptionFileError with the closest
// known name. As on the command line, a switch set false leaves the row untouched.
template <typename Target>
void apply_option_file(const std::vector<OptionFileEntry>& entries, const std::vector<OptionRow<Target>>& rows,
                       Target& target, const std::string& what) {
  std::vector<std::string> known;
  for (const OptionRow<Target>& row : rows) known.push_back(row.name);
  for (const OptionFileEntry& entry : entries) {
    const OptionRow<Target>* row = find_option(rows, entry.name);
    if (row == nullptr) throw OptionFileError(unknown_option_message(entry, known, what));
    if (row->is_switch()) {
      if (entry.switch_value()) row->set(target, 1.0);
    } else {
      set_option(*row, target, entry.number_value(), entry.where);
    }
  }
}

}  // namespace topocut
