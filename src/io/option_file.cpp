#include "topocut/io/option_file.h"

#include <yaml-cpp/yaml.h>

#include "topocut/core/input_file.h"

namespace topocut {
namespace {

OptionFileEntry entry_of(const YAML::Node& key, const YAML::Node& value, const std::string& path) {
  if (!key.IsScalar())
    throw OptionFileError("config file '" + path + "', line " + std::to_string(key.Mark().line + 1) +
                          ": a key must be an option name, not a list or mapping");
  OptionFileEntry entry;
  entry.key = key.Scalar();
  entry.name = dashed_option_name(entry.key);
  entry.where = "'" + entry.key + "' in config file '" + path + "'";
  if (value.IsSequence()) {
    entry.is_list = true;
    for (const YAML::Node& item : value) {
      if (!item.IsScalar()) throw OptionFileError(entry.where + " must be a value or a list of values");
      entry.values.push_back(item.Scalar());
    }
  } else if (value.IsScalar()) {
    entry.values.push_back(value.Scalar());
  } else {
    throw OptionFileError(entry.where + " must be a value or a list of values");
  }
  return entry;
}

}  // namespace

bool OptionFileEntry::switch_value() const {
  bool on = false;
  if (is_list || values.size() != 1 || !YAML::convert<bool>::decode(YAML::Node(values.front()), on))
    throw OptionFileError(where + " is a switch: give true or false");
  return on;
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
  for (const auto& item : root) entries.push_back(entry_of(item.first, item.second, path));
  return entries;
}

std::string unknown_option_message(const OptionFileEntry& entry, const std::vector<std::string>& known,
                                   const std::string& what) {
  const std::string meant = closest_option_name(entry.name, known);
  return entry.where + " is not " + what + (meant.empty() ? "" : " (did you mean '" + meant + "'?)");
}

}  // namespace topocut
