#include "topocut/io/option_file.h"

#include <optional>
#include <set>

#include <yaml-cpp/yaml.h>

#include "topocut/core/input_file.h"

namespace topocut {
namespace {

// What the keys and values of one file may add up to once its aliases are expanded: an alias is a
// reference in the YAML tree but a copy in the entries, so a small file could otherwise ask for
// gigabytes (one anchor aliased 146,894 times asked for 63 GiB).
class ValueBudget {
 public:
  explicit ValueBudget(const std::string& path) : path_(path) {}

  const std::string& take(const std::string& value) {
    if (value.size() >= left_)
      throw OptionFileError("config file '" + path_ + "': its values add up to more than " + byte_size_text(kMaxConfigYamlBytes) +
                            " (an anchor repeated by aliases?); give each value once");
    left_ -= value.size() + 1;
    return value;
  }

 private:
  const std::string& path_;
  std::size_t left_ = kMaxConfigYamlBytes;
};

std::string line_of(const YAML::Node& key, const std::string& path) {
  return "config file '" + path + "', line " + std::to_string(key.Mark().line + 1);
}

OptionFileEntry entry_of(const YAML::Node& key, const YAML::Node& value, const std::string& path, ValueBudget& budget) {
  if (!key.IsScalar()) throw OptionFileError(line_of(key, path) + ": a key must be an option name, not a list or mapping");
  if (key.Scalar().empty()) throw OptionFileError(line_of(key, path) + ": an empty key is no option name");
  OptionFileEntry entry;
  entry.key = budget.take(key.Scalar());
  entry.name = dashed_option_name(entry.key);
  entry.where = "'" + entry.key + "' in config file '" + path + "'";
  if (value.IsSequence()) {
    entry.is_list = true;
    for (const YAML::Node& item : value) {
      if (!item.IsScalar()) throw OptionFileError(entry.where + " must be a value or a list of values");
      entry.values.push_back(budget.take(item.Scalar()));
    }
  } else if (value.IsScalar()) {
    entry.values.push_back(budget.take(value.Scalar()));
  } else {
    throw OptionFileError(entry.where + " must be a value or a list of values");
  }
  return entry;
}

}  // namespace

bool OptionFileEntry::switch_value() const {
  if (is_list || values.size() != 1) throw OptionFileError(where + " is a switch: give true or false, not a list");
  const std::optional<bool> on = parse_switch_value(values.front());
  if (!on) throw OptionFileError(switch_value_error(where, values.front()));
  return *on;
}

double OptionFileEntry::number_value() const {
  if (is_list || values.size() != 1) throw OptionFileError(where + " takes one number, not a list");
  try {
    return parse_option_number(values.front(), where);
  } catch (const Error& e) {
    throw OptionFileError(e.what());
  }
}

std::vector<OptionFileEntry> read_option_file(const std::string& path) {
  const std::string text = read_input_file(path, "config file", kMaxConfigYamlBytes);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw Error("config file '" + path + "' is not valid YAML: " + e.msg);
  }
  std::vector<OptionFileEntry> entries;
  if (root.IsNull()) return entries;
  if (!root.IsMap()) throw OptionFileError("config file '" + path + "' must be a mapping of option names to values");
  ValueBudget budget(path);
  std::set<std::string> seen;
  for (const auto& item : root) {
    entries.push_back(entry_of(item.first, item.second, path, budget));
    // The command line refuses an option given twice; so does the file, whatever the value's kind
    // (a switch given false twice would otherwise pass where a number would not), and under either
    // spelling (robot_radius and robot-radius are one option).
    if (!seen.insert(entries.back().name).second)
      throw OptionFileError(given_twice_error(entries.back().where) + " (line " + std::to_string(item.first.Mark().line + 1) + ")");
  }
  return entries;
}

std::string unknown_option_message(const OptionFileEntry& entry, const std::vector<std::string>& known,
                                   const std::string& what) {
  const std::string meant = closest_option_name(entry.name, known);
  return entry.where + " is not " + what + (meant.empty() ? "" : " (did you mean '" + meant + "'?)");
}

}  // namespace topocut
