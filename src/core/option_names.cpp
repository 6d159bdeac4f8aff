#include "topocut/core/option_names.h"

#include <algorithm>

namespace topocut {

namespace {

// Levenshtein distance: insertions, deletions and substitutions, one row at a time.
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1] ? 1u : 0u)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string dashed_option_name(std::string name) {
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

std::string underscored_option_name(std::string name) {
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

std::string closest_option_name(const std::string& name, const std::vector<std::string>& known) {
  const std::string dashed = dashed_option_name(name);
  std::string best;
  std::size_t best_distance = 3;  // a typo: one or two letters wrong, missing or extra
  for (const std::string& candidate : known) {
    // Lengths further apart than a typo cannot be one: a 1 MB name costs nothing.
    const std::size_t a = dashed.size(), b = candidate.size();
    if ((a > b ? a - b : b - a) >= best_distance) continue;
    const std::size_t d = edit_distance(dashed, dashed_option_name(candidate));
    if (d < best_distance) best = candidate, best_distance = d;
  }
  return best;
}

}  // namespace topocut
