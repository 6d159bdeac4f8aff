#include "cli/config_file.h"

#include <yaml-cpp/yaml.h>

#include "topocut/core/error.h"
#include "topocut/core/input_file.h"
#include "topocut/core/option_names.h"

namespace topocut::cli {
namespace {

// The tokens one YAML value stands for; empty for a switch left off.
std::vector<std::string> tokens(const YAML::Node& value, const po::option_description& option, const std::string& where) {
  if (value.IsSequence()) {
    std::vector<std::string> out;
    for (const YAML::Node& item : value) {
      if (!item.IsScalar()) throw UsageError(where + " must be a value or a list of values");
      out.push_back(item.Scalar());
    }
    return out;
  }
  if (!value.IsScalar()) throw UsageError(where + " must be a value or a list of values");
  if (option.semantic()->max_tokens() == 0) {  // a switch
    bool on = false;
    if (!YAML::convert<bool>::decode(value, on)) throw UsageError(where + " is a switch: give true or false");
    return on ? std::vector<std::string>{"true"} : std::vector<std::string>{};
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
  for (const auto& entry : root) {
    if (!entry.first.IsScalar())
      throw UsageError("config file '" + path + "', line " + std::to_string(entry.first.Mark().line + 1) +
                       ": a key must be an option name, not a list or mapping");
    const std::string key = dashed_option_name(entry.first.Scalar());  // robot_radius or robot-radius
    const std::string where = "'" + entry.first.Scalar() + "' in config file '" + path + "'";
    const po::option_description* option = options.find_nothrow(key, false);
    if (!option || key == "config" || key == "help") {
      const std::string meant = closest_option_name(key, option_names(options));
      throw UsageError(where + " is not an option of this command" + (meant.empty() ? "" : " (did you mean '" + meant + "'?)"));
    }
    po::option parsed_option;
    parsed_option.string_key = key;
    parsed_option.value = tokens(entry.second, *option, where);
    if (option->semantic()->max_tokens() == 0 && parsed_option.value.empty()) continue;
    parsed.options.push_back(parsed_option);
  }
  return parsed;
}

}  // namespace topocut::cli
