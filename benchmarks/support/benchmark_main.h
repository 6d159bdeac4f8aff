#pragma once
// The main of every benchmark program: one argument parser (the program's own options, and
// `topocut evaluate`'s from the library's tables when it takes them), --help, the machine line above
// the tables, and the same exit codes everywhere.
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "topocut/core/error.h"
#include "topocut/core/option_table.h"
#include "topocut/evaluation/dataset_options.h"

namespace topocut::benchmarks {

// Exit codes of every benchmark program.
constexpr int kDone = 0;      // the tables are printed
constexpr int kFailed = 1;    // a case failed, or the run stopped on an error
constexpr int kBadUsage = 2;  // the command line is wrong (one line says why)
constexpr int kSkipped = 77;  // the shared data it measures is absent (ctest's code for a skipped test)

// Thrown when the data a benchmark measures is absent: the main prints the reason and exits kSkipped.
struct Skipped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One option: --name, --name VALUE or --name=VALUE.
struct Option {
  std::string name;        // without dashes
  std::string value_name;  // shown in the help ("N", "DIR"); empty for a switch
  std::string help;        // one line, with the default
  std::function<void(const std::string&)> set;  // gets the value ("" for a switch); throws Error on a bad one
  bool repeatable = false;                      // takes one or more values (--map a b), given any number of times
};

// value as a whole number in [least, most]; Error naming what (an option or operand) otherwise.
int whole_number(const std::string& what, const std::string& value, int least, int most);

// Options bound to a variable (its value before parsing is the default). count: a whole number >=
// least; number: a finite number; texts: one or more values, appended.
Option flag(const std::string& name, bool& target, const std::string& help);
Option count(const std::string& name, int& target, int least, const std::string& help);
Option number(const std::string& name, double& target, const std::string& help);
Option on_off(const std::string& name, bool& target, const std::string& help);  // --name on|off
Option text(const std::string& name, const std::string& value_name, std::string& target, const std::string& help);
Option texts(const std::string& name, const std::string& value_name, std::vector<std::string>& target,
             const std::string& help);

// Sets row in target from value as every front end reads it (option_table.h): a switch given bare is
// on, one given a value takes true or false (on|off); a number is read and checked by its range.
template <typename Target>
void set_table_option(const OptionRow<Target>& row, Target& target, const std::string& value) {
  const std::string shown = "--" + row.name;
  double v = 1.0;
  if (row.is_switch() && !value.empty()) {
    const std::optional<bool> on = parse_switch_value(value);
    if (!on) throw Error(switch_value_error(shown, value));
    v = *on ? 1.0 : 0.0;
  } else if (!row.is_switch()) {
    v = parse_option_number(value, shown);
  }
  set_option(row, target, v, shown);
}

// The rows of a library table as options setting target, with the table's names, help and checks,
// target's values (the program's defaults) shown. A switch its struct has on takes true or false, as
// on the command line (--neighbours-across-doors false).
template <typename Target>
std::vector<Option> table_options(const std::vector<OptionRow<Target>>& rows, Target& target) {
  static const Target struct_defaults{};  // made once: option structs may hold the merge model
  std::vector<Option> out;
  for (const OptionRow<Target>& row : rows) {
    const bool takes_value = !row.is_switch() || row.get(struct_defaults) != 0.0;
    const double value = row.get(target);
    const std::string shown_default = row.is_switch() ? (value != 0.0 ? "true" : "false") : shortest_number(value);
    out.push_back({row.name, row.is_switch() ? (takes_value ? "true|false" : "") : row.value_name,
                   row.help + (takes_value ? " (default " + shown_default + ")" : ""),
                   [&row, &target](const std::string& given) { set_table_option(row, target, given); }});
  }
  return out;
}

// a's options, then b's.
std::vector<Option> joined(std::vector<Option> a, const std::vector<Option>& b);

struct Program {
  std::string name{};   // the program's file name
  std::string title{};  // printed as a Markdown heading above the machine line
  std::string about{};  // what it measures, for --help (lines ending in '\n')
  std::vector<Option> options{};
  std::string operands{};                             // the usage of its operands ("[LOG ...]"); empty: none
  std::function<void(const std::string&)> operand{};  // takes each operand; throws Error on a bad one
  // Takes `topocut evaluate`'s options (dataset, segmentation, map loading) into *dataset; without
  // --dataset, dataset->dataset is the Bormann set of the shared folder.
  DatasetArguments* dataset = nullptr;
  // Options starting with this prefix go to *passed_on untouched (Google Benchmark's --benchmark_*).
  std::string pass_on_prefix{};
  std::vector<std::string>* passed_on = nullptr;
  bool tune_allocator = false;  // glibc's allocator tuned as the topocut command tunes it
};

// Throws Skipped unless folder (the data a benchmark measures) exists.
void require_folder(const std::string& folder);

// Parses the command line into program's options (--help: the usage, kDone), prints the title and
// the machine line, then returns run()'s exit code. A bad command line is one line and kBadUsage;
// Skipped gives kSkipped; any other exception one line and kFailed.
int benchmark_main(int argc, char** argv, const Program& program, const std::function<int()>& run);

// "machine: <CPU>, <n> hardware threads, load average <1 min>; <build>; <compiler>".
std::string machine_line();

}  // namespace topocut::benchmarks
