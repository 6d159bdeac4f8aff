#pragma once
// Options chosen by name (--selection greedy|reference), the rows of option_table.h for a field whose
// values have names: one row holds the option's name, its help, the names allowed and the value each
// sets, so that every front end lists the same names, shows the same default and refuses any other
// name with the same line.
#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "topocut/core/error.h"

namespace topocut {

template <typename Target>
struct ChoiceRow {
  std::string name;                 // long name without dashes, e.g. "selection"
  std::string help;                 // one line; front ends add the names and the default
  std::vector<std::string> names;   // the names allowed, in the order the help lists them
  std::function<std::string(const Target&)> get;          // the name of the value in target
  std::function<void(Target&, const std::string&)> set;   // sets the value named (one of names)

  // "greedy|reference", shown as the option's value in a help line.
  std::string value_name() const {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : "|") + n;
    return out;
  }
};

// A row for a field of Target whose values have names: choices pairs each name with its value.
template <typename Target, typename Value>
ChoiceRow<Target> choice_row(std::string name, Value Target::*field, std::vector<std::pair<std::string, Value>> choices,
                             std::string help) {
  std::vector<std::string> names;
  for (const auto& choice : choices) names.push_back(choice.first);
  return {std::move(name), std::move(help), std::move(names),
          [field, choices](const Target& t) {
            for (const auto& [n, value] : choices)
              if (t.*field == value) return n;
            return std::string();
          },
          [field, choices](Target& t, const std::string& text) {
            for (const auto& [n, value] : choices)
              if (n == text) t.*field = value;
          }};
}

// Sets in target the value that text names; throws Error "<shown> must be one of 'a', 'b', got 'x'"
// for any other text.
template <typename Target>
void set_choice(const ChoiceRow<Target>& row, Target& target, const std::string& text, const std::string& shown) {
  std::string listed;
  for (const std::string& n : row.names) {
    if (n == text) {
      row.set(target, text);
      return;
    }
    listed += (listed.empty() ? "'" : ", '") + n + "'";
  }
  throw Error(shown + " must be one of " + listed + ", got '" + text + "'");
}

}  // namespace topocut
