#include "cli/command.h"
#include "cli/config_file.h"

#include <iostream>

#include "topocut/core/format.h"
#include "topocut/core/option_names.h"
#include "topocut/core/option_table.h"

namespace topocut::cli {

namespace {
std::map<std::string, Command>& table() {
  static std::map<std::string, Command> instance;
  return instance;
}
}  // namespace

bool register_command(Command command) {
  const std::string name = command.name;
  table()[name] = std::move(command);
  return true;
}

const std::map<std::string, Command>& commands() { return table(); }

namespace {

// `--out-json --trivial` would write a file named "--trivial" and run without --trivial: a value
// that spells one of the command's own options is a missing value.
void reject_options_taken_as_values(const po::variables_map& vm, const po::options_description& all) {
  auto check = [&](const std::string& name, const std::string& value) {
    if (value.size() > 2 && value.compare(0, 2, "--") == 0 && all.find_nothrow(value.substr(2), false) != nullptr)
      throw UsageError("--" + name + " needs a value, not the option '" + value + "'");
  };
  for (const auto& [name, entry] : vm) {
    if (const auto* text = boost::any_cast<std::string>(&entry.value())) {
      check(name, *text);
    } else if (const auto* texts = boost::any_cast<std::vector<std::string>>(&entry.value())) {
      for (const std::string& t : *texts) check(name, t);
    }
  }
}

// args with every option's name written with '-' for '_' (--robot_radius is --robot-radius); values,
// operands and what follows "--" stay as given.
std::vector<std::string> dashed_names(std::vector<std::string> args) {
  for (std::string& arg : args) {
    if (arg == "--") break;
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) continue;
    const std::size_t end = std::min(arg.find('='), arg.size());
    arg = "--" + dashed_option_name(arg.substr(2, end - 2)) + arg.substr(end);
  }
  return args;
}

// "the option '--map' is required" says nothing of how to give it: an operand is named as the usage
// line names it (MAP), with that line.
std::string missing_option_message(const std::string& option, const po::positional_options_description& positional,
                                   const std::string& usage) {
  const std::string name = option.compare(0, 2, "--") == 0 ? option.substr(2) : option;
  for (unsigned position = 0; position < positional.max_total_count() && position < 16; ++position) {
    if (positional.name_for_position(position) != name) continue;
    std::string operand = name;
    for (char& c : operand) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return "no " + operand + " given: " + usage;
  }
  return "the option '--" + name + "' is required: " + usage;
}

}  // namespace

std::vector<std::string> option_names(const po::options_description& options) {
  std::vector<std::string> names;
  for (const auto& option : options.options()) names.push_back(option->long_name());
  return names;
}

std::optional<po::variables_map> parse_options(const std::string& usage, const std::string& description,
                                               const po::options_description& options,
                                               const po::positional_options_description& positional,
                                               const std::vector<std::string>& args) {
  po::options_description all("Options");
  all.add_options()("help,h", "show this help and exit");
  all.add_options()("config", po::value<std::string>()->value_name("FILE"),
                    "read options from this YAML file (keys: long option names; the command line wins)");
  all.add(options);
  po::variables_map vm;
  try {
    // No guessing of abbreviated names: an option is spelled one way, and a prefix that names one option
    // today (decompose's old --concavity for --concavity-measure) would silently name another tomorrow.
    const int style = po::command_line_style::default_style & ~po::command_line_style::allow_guessing;
    po::store(po::command_line_parser(dashed_names(args)).options(all).positional(positional).style(style).run(), vm);
    if (vm.count("help")) {
      std::cout << "Usage: " << usage << "\n\n" << description << "\n\n" << all << std::flush;
      return std::nullopt;
    }
    // Stored second, so every option the command line gave keeps its value.
    if (vm.count("config")) po::store(config_file_options(vm["config"].as<std::string>(), all), vm);
    po::notify(vm);
  } catch (const po::unknown_option& e) {
    const std::string name = e.get_option_name();
    const std::string meant = name.compare(0, 2, "--") == 0 ? closest_option_name(name.substr(2), option_names(all)) : "";
    throw UsageError(std::string(e.what()) + (meant.empty() ? "" : " (did you mean '--" + meant + "'?)"));
  } catch (const po::required_option& e) {
    throw UsageError(missing_option_message(e.get_option_name(), positional, usage));
  } catch (const po::multiple_occurrences& e) {  // the message every front end gives
    throw UsageError(given_twice_error(e.get_option_name()));
  } catch (const po::error& e) {
    throw UsageError(e.what());
  }
  reject_options_taken_as_values(vm, all);
  return vm;
}

// A progress line names maps by their file names: escaped, so that none can move the cursor or
// rewrite the terminal.
void progress(const std::string& message) { std::cerr << terminal_text(message) << std::endl; }

}  // namespace topocut::cli
