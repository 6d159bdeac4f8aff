#pragma once
// Options whose value is text a struct keeps: the files a command reads and writes, a name, a point.
// The rows of option_table.h for text, so that a path is declared once next to the struct that holds
// it (name, help, whether it is read or written) and every front end adds, reads and checks it alike:
// an empty file name is refused by name, a required one is asked for by name.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "topocut/core/error.h"
#include "topocut/core/geometry.h"

namespace topocut {

// What the text is: a file or folder read, a file or folder written, or other text (a name, a
// point X,Y) that the row's set function reads.
enum class TextKind { kInput, kOutput, kText };

template <typename Target>
struct TextRow {
  std::string name;        // long name without dashes, e.g. "out-json"
  std::string value_name;  // shown in the help, e.g. "FILE"
  std::string help;        // one line
  TextKind kind = TextKind::kText;
  bool required = false;    // the command cannot run without it (an operand such as MAP)
  bool repeatable = false;  // given more than once, each value is set in turn
  std::function<void(Target&, const std::string&)> set;  // stores the text; may throw Error
  std::string letter;       // the command line's one-letter name ("o" for -o), if any

  bool is_path() const { return kind != TextKind::kText; }
};

// A row for a path held in a string field of Target; letter: its one-letter name, if any.
template <typename Target>
TextRow<Target> path_row(std::string name, std::string value_name, TextKind kind, std::string Target::*field,
                         std::string help, bool required = false, std::string letter = "") {
  return {std::move(name), std::move(value_name), std::move(help), kind, required, false,
          [field](Target& t, const std::string& text) { t.*field = text; }, std::move(letter)};
}

// A row for other text: set reads it into target (throwing Error on a bad value).
template <typename Target>
TextRow<Target> text_row(std::string name, std::string value_name, std::function<void(Target&, const std::string&)> set,
                         std::string help, bool repeatable = false) {
  return {std::move(name), std::move(value_name), std::move(help), TextKind::kText, false, repeatable, std::move(set), ""};
}

// "X,Y" as two decimal numbers read by parse_option_number(), both finite: the one reader of a point
// given as text (segment --at, explore --start). Error "<shown> needs a point X,Y in metres, not
// '<text>'" for text that is no such pair.
Point2 parse_option_point(const std::string& text, const std::string& shown);

// Checks text for row (a path must not be empty: "--out-json was given an empty file name"), then
// sets it; shown names the option in errors.
template <typename Target>
void set_text_option(const TextRow<Target>& row, Target& target, const std::string& text, const std::string& shown) {
  if (row.is_path() && text.empty()) throw Error(shown + " was given an empty file name");
  row.set(target, text);
}

}  // namespace topocut
