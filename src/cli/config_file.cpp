#include "cli/config_file.h"

#include <set>

#include <yaml-cpp/yaml.h>

#include "topocut/core/error.h"
#include "topocut/core/input_file.h"
#include "topocut/core/option_names.h"
#include "topocut/core/option_table.h"

namespace topocut::cli {
namespace {

// What the values of one file may add up to once its aliases are expanded: an alias is a reference
// in the YAML tree but a copy in the tokens, so a small file could otherwise ask for gigabytes.
struct ValueBudget {
  std::size_t left = kMaxConfigYamlBytes;
  const std::string& path;

  const std::string& take(const std::string& value) {
    if (value.size() >= left)
      throw UsageError("config file '" + path + "': its values add up to more than " + byte_size_text(kMaxConfigYamlBytes) +
                       " (an anchor repeated by aliases?); give each value once");
    left -= value.size() + 1;
    return value;
  }
};

// The tokens one YAML value stands for; empty for a switch left off.
std::vector<std::string> tokens(const YAML::Node& value, const po::option_description& option, const std::string& where,
                                ValueBudget& budget) {
  if (value.IsSequence()) {
    std::vector<std::string> out;
    for (const YAML::Node& item : value) {
      if (!item.IsScalar()) throw UsageError(where + " must be a value or a list of values");
      out.push_back(budget.take(item.Scalar()));
    }
    return out;
  }
  if (!value.IsScalar()) throw UsageError(where + " must be a value or a list of values");
  budget.take(value.Scalar());
  if (option.semantic()->max_tokens() == 0) {  // a switch
    const std::optional<bool> on = parse_switch_value(value.Scalar());
    if (!on) throw UsageError(switch_value_error(where, value.Scalar()));
    return *on ? std::vector<std::string>{"true"} : std::vector<std::string>{};
  }
  return {value.Scalar()};
}

}  // namespace

po::parsed_options config_file_options(const std::string& path, const po::options_description& options) {
  const std::string text = read_input_file(path, "config file", kMaxConfigYamlBytes);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw Error("config file '" + path + "' is not valid YAML: " + e.msg);
  }
  po::parsed_options parsed(&options);
  if (root.IsNull()) return parsed;
  if (!root.IsMap()) throw UsageError("config file '" + path + "' must be a mapping of option names to values");
  ValueBudget budget{kMaxConfigYamlBytes, path};
  std::set<std::string> seen;
  for (const auto& entry : root) {
    const std::string line = "config file '" + path + "', line " + std::to_string(entry.first.Mark().line + 1);
    if (!entry.first.IsScalar()) throw UsageError(line + ": a key must be an option name, not a list or mapping");
    if (entry.first.Scalar().empty()) throw UsageError(line + ": an empty key is no option name");
    const std::string key = dashed_option_name(entry.first.Scalar());  // robot_radius or robot-radius
    const std::string where = "'" + budget.take(entry.first.Scalar()) + "' in config file '" + path + "'";
    // The command line refuses an option given twice; so does the file, whatever the value's kind
    // (a switch given false twice would otherwise pass where a number would not).
    if (!seen.insert(key).second) throw UsageError(given_twice_error(where) + " (line " + std::to_string(entry.first.Mark().line + 1) + ")");
    const po::option_description* option = options.find_nothrow(key, false);
    if (!option || key == "config" || key == "help") {
      const std::string meant = closest_option_name(key, option_names(options));
      throw UsageError(where + " is not an option of this command" + (meant.empty() ? "" : " (did you mean '" + meant + "'?)"));
    }
    po::option parsed_option;
    parsed_option.string_key = key;
    parsed_option.value = tokens(entry.second, *option, where, budget);
    if (option->semantic()->max_tokens() == 0 && parsed_option.value.empty()) continue;
    parsed.options.push_back(parsed_option);
  }
  return parsed;
}

}  // namespace topocut::cli
