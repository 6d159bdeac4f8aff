#include "support/benchmark_main.h"

#include <stdlib.h>

#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>
#include <thread>

#include "benchmark_machine.h"
#include "cli/allocator.h"
#include "topocut/core/error.h"
#include "topocut/core/format.h"
#include "topocut/core/option_table.h"

namespace topocut::benchmarks {

namespace {

const Option* find(const std::vector<Option>& options, const std::string& name) {
  for (const Option& option : options)
    if (option.name == name) return &option;
  return nullptr;
}

void print_usage(const Program& program) {
  std::cout << "Usage: " << program.name << " [options]" << (program.operands.empty() ? "" : " " + program.operands)
            << "\n\n"
            << program.about << "\nOptions:\n";
  for (const Option& option : program.options) std::cout << option_help_line(option.name, option.value_name, option.help);
  std::cout << option_help_line("help", "", "print this text and exit");
  if (program.dataset != nullptr) {
    std::cout << "\nDataset, segmentation and map options (as topocut evaluate; without --dataset: " TOPOCUT_SHARED_DIR
                 "/datasets/bormann):\n"
              << dataset_options_help();
  }
  std::cout << "\nExit codes: " << kDone << " tables printed, " << kFailed << " a case failed, " << kBadUsage
            << " bad command line, " << kSkipped << " the shared data it measures is absent.\n";
}

// Sets the program's options from args; the options it does not know go to the dataset arguments
// when it takes them. Returns false after printing the usage (--help).
bool parse(const std::vector<std::string>& args, const Program& program) {
  std::vector<std::string> forwarded;  // `topocut evaluate`'s options and their values
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      print_usage(program);
      return false;
    }
    if (program.passed_on != nullptr && !program.pass_on_prefix.empty() && arg.rfind(program.pass_on_prefix, 0) == 0) {
      program.passed_on->push_back(arg);
      continue;
    }
    const bool is_option = arg.rfind("--", 0) == 0 && arg.size() > 2;
    const std::size_t eq = arg.find('=');
    const Option* option = is_option ? find(program.options, arg.substr(2, eq == std::string::npos ? eq : eq - 2)) : nullptr;
    if (option == nullptr) {
      if (program.dataset != nullptr && (is_option || !forwarded.empty())) {
        forwarded.push_back(arg);
      } else if (!is_option && program.operand) {
        program.operand(arg);
      } else {
        throw Error(is_option ? "unknown option '" + arg + "'" : "unexpected argument '" + arg + "'");
      }
      continue;
    }
    const std::string shown = "--" + option->name;
    if (option->value_name.empty()) {
      if (eq != std::string::npos) throw Error(shown + " takes no value");
      option->set("");
    } else if (eq != std::string::npos) {
      option->set(arg.substr(eq + 1));
    } else {
      if (i + 1 == args.size() || args[i + 1].rfind("--", 0) == 0) throw Error(shown + " needs a value");
      option->set(args[++i]);
      while (option->repeatable && i + 1 < args.size() && args[i + 1].rfind("--", 0) != 0) option->set(args[++i]);
    }
  }
  if (program.dataset != nullptr) {
    *program.dataset = parse_dataset_arguments(forwarded);
    if (program.dataset->dataset == DatasetArguments{}.dataset) program.dataset->dataset = TOPOCUT_SHARED_DIR "/datasets/bormann";
  }
  return true;
}

// The whole of value as a number.
double parsed_number(const std::string& name, const std::string& value) {
  const double v = parse_option_number(value, "--" + name);
  if (!std::isfinite(v)) throw Error("--" + name + " needs a finite number, not '" + value + "'");
  return v;
}

}  // namespace

Option flag(const std::string& name, bool& target, const std::string& help) {
  return {name, "", help, [&target](const std::string&) { target = true; }};
}

int whole_number(const std::string& what, const std::string& value, int least, int most) {
  const double v = parse_option_number(value, what);
  if (!(v == std::floor(v) && v >= least && v <= most))
    throw Error(what + " needs a whole number in " + std::to_string(least) + ".." + std::to_string(most) + ", not '" + value + "'");
  return static_cast<int>(v);
}

Option count(const std::string& name, int& target, int least, const std::string& help) {
  return {name, "N", help, [&target, name, least](const std::string& value) {
            target = whole_number("--" + name, value, least, 1'000'000'000);
          }};
}

Option number(const std::string& name, double& target, const std::string& help) {
  return {name, "X", help, [&target, name](const std::string& value) { target = parsed_number(name, value); }};
}

Option on_off(const std::string& name, bool& target, const std::string& help) {
  return {name, "on|off", help, [&target, name](const std::string& value) {
            if (value != "on" && value != "off") throw Error("--" + name + " needs on or off, not '" + value + "'");
            target = value == "on";
          }};
}

Option text(const std::string& name, const std::string& value_name, std::string& target, const std::string& help) {
  return {name, value_name, help, [&target, name](const std::string& value) {
            if (value.empty()) throw Error("--" + name + " needs a value");
            target = value;
          }};
}

Option texts(const std::string& name, const std::string& value_name, std::vector<std::string>& target,
             const std::string& help) {
  return {name, value_name, help,
          [&target, name](const std::string& value) {
            if (value.empty()) throw Error("--" + name + " needs a value");
            target.push_back(value);
          },
          true};
}

std::vector<Option> joined(std::vector<Option> a, const std::vector<Option>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

void require_folder(const std::string& folder) {
  if (!std::filesystem::is_directory(folder)) throw Skipped(folder + " is absent");
}

std::string machine_line() {
  double load[3] = {0, 0, 0};
  getloadavg(load, 3);
#ifdef NDEBUG
  const char* build = "optimised build (NDEBUG)";
#else
  const char* build = "assertions on (not a release build: times are not representative)";
#endif
  return format("machine: %s, %u hardware threads, load average %.1f; %s; compiler %s", cpu_model().c_str(),
                std::thread::hardware_concurrency(), load[0], build, __VERSION__);
}

int benchmark_main(int argc, char** argv, const Program& program, const std::function<int()>& run) {
  if (program.tune_allocator) keep_freed_memory_for_reuse();
  const std::string name = program.name;
  try {
    if (!parse(std::vector<std::string>(argv + 1, argv + argc), program)) return kDone;
  } catch (const Skipped& e) {
    std::cout << name << ": skipped: " << e.what() << "\n";
    return kSkipped;
  } catch (const std::exception& e) {
    std::cerr << name << ": error: " << e.what() << " (see --help)\n";
    return kBadUsage;
  }
  std::cout << "# " << program.title << "\n\n" << machine_line() << "\n\n" << std::flush;
  try {
    return run();
  } catch (const Skipped& e) {
    std::cout << name << ": skipped: " << e.what() << "\n";
    return kSkipped;
  } catch (const Error& e) {
    std::cerr << name << ": error: " << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << name << ": error: internal failure: " << e.what() << "\n";
  }
  return kFailed;
}

}  // namespace topocut::benchmarks
