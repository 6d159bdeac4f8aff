#include "cli/config_file.h"

#include "topocut/io/option_file.h"

namespace topocut::cli {

po::parsed_options config_file_options(const std::string& path, const po::options_description& options) {
  std::vector<OptionFileEntry> entries;
  try {
    entries = read_option_file(path);
  } catch (const OptionFileError& e) {  // YAML, but not options: wrong use, like a bad flag
    throw UsageError(e.what());
  }
  po::parsed_options parsed(&options);
  for (const OptionFileEntry& entry : entries) {
    const po::option_description* option = options.find_nothrow(entry.name, false);
    if (!option || entry.name == "config" || entry.name == "help")
      throw UsageError(unknown_option_message(entry, option_names(options)));
    po::option parsed_option;
    parsed_option.string_key = entry.name;
    if (option->semantic()->max_tokens() == 0) {  // a switch: true turns it on, false leaves it off
      bool on = false;
      check_usage([&] { on = entry.switch_value(); });
      if (!on) continue;
      parsed_option.value = {"true"};
    } else {
      parsed_option.value = entry.values;
    }
    parsed.options.push_back(parsed_option);
  }
  return parsed;
}

}  // namespace topocut::cli
