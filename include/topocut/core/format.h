#pragma once
// printf-style formatting into a std::string: the one helper the reports, tables and progress lines
// use for numbers with a fixed count of decimals.
#include <string>

namespace topocut {

// The text std::printf would print for pattern and its arguments, of any length. The compiler checks
// the arguments against the pattern.
std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

// value with exactly decimals digits after the point, as "%.*f" prints it.
std::string fixed(double value, int decimals);

// A name (a file's, a map's: anyone's text) fit to print on a terminal: control characters (C0,
// DEL, C1: escape sequences, CR, LF, ...) become \xHH, everything else stays as it is.
std::string terminal_text(const std::string& name);

// text as one CSV cell: quoted when it holds a comma, a quote or a line break, and, when it starts
// with '=', '+', '-', '@', a tab or CR (what a spreadsheet would run as a formula), led by a ' and
// quoted, so that it is read as the text it is.
std::string csv_cell(const std::string& text);

}  // namespace topocut
