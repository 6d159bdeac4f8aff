#include "topocut/segmentation/merge_model.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>
#include <sstream>
#include <string_view>

#include "topocut/core/error.h"
#include "topocut/core/input_file.h"
#include "topocut/segmentation/merge_features.h"

namespace topocut {

namespace {

// A line read word by word without the stream: words separated by spaces and tabs, each word taken
// whole (what follows it is a space, a tab or the line's end) or not at all.
class PlainWords {
 public:
  explicit PlainWords(std::string_view line) : at_(line.data()), end_(line.data() + line.size()) {}

  // Whether the next word is word; takes it if so.
  bool take(std::string_view word) {
    skip_blanks();
    if (static_cast<std::size_t>(end_ - at_) < word.size() || std::string_view(at_, word.size()) != word) return false;
    return taken(at_ + word.size());
  }

  // The next word, up to a space or the line's end (perhaps empty): a name, which ends at a space in
  // every model written (a name followed by a tab is no feature's, and its line goes to the stream).
  std::string_view name() {
    skip_blanks();
    const char* start = at_;
    const void* space = std::memchr(start, ' ', static_cast<std::size_t>(end_ - start));
    at_ = space ? static_cast<const char*>(space) : end_;
    return {start, static_cast<std::size_t>(at_ - start)};
  }

  // Whether the next word is a decimal number of a finite double as std::from_chars reads it
  // ([-]digits[.digits][(e|E)[+|-]digits], either digits of the mantissa perhaps missing), converted
  // into value: the stream reads such a word whole, to the same double (both round correctly).
  // Anything else from_chars reads (infinity, NaN) is not finite.
  bool decimal(double& value) {
    skip_blanks();
    const auto [stop, error] = std::from_chars(at_, end_, value);
    return error == std::errc() && std::isfinite(value) && taken(stop);
  }

  // Whether the next word is [-]digits of an int (as the stream reads it whole: std::from_chars reads
  // the same form), converted into value.
  bool index(int& value) {
    skip_blanks();
    const auto [stop, error] = std::from_chars(at_, end_, value);
    return error == std::errc() && taken(stop);
  }

  // Whether nothing but spaces and tabs is left.
  bool done() {
    skip_blanks();
    return at_ == end_;
  }

 private:
  static bool blank(char c) { return c == ' ' || c == '\t'; }
  void skip_blanks() {
    while (at_ != end_ && blank(*at_)) ++at_;
  }
  // Whether a word ends at word_end (a space, a tab or the line's end follows); takes it if so.
  bool taken(const char* word_end) {
    if (word_end != end_ && !blank(*word_end)) return false;
    at_ = word_end;
    return true;
  }

  const char* at_;
  const char* end_;
};

// Whether token is a decimal (PlainWords::decimal()) of a finite double, converted into value.
bool read_decimal(std::string_view token, double& value) {
  PlainWords words(token);
  return words.decimal(value) && words.done();
}

double finite_number(std::istringstream& in, int line, const std::string& what) {
  double value = 0.0;
  // The shipped model's numbers are plain decimals: read as a word and converted with
  // std::from_chars, several times cheaper than the stream's number parsing. Anything else (and a
  // value out of range) is read again by the stream from the same place, as it always was.
  const std::istringstream::pos_type start = in.tellg();
  std::string token;
  if (in >> token && read_decimal(token, value)) return value;
  in.clear();
  in.seekg(start);
  value = 0.0;
  if (!(in >> value) || !std::isfinite(value))
    throw Error("merge model, line " + std::to_string(line) + ": " + what + " must be a finite number");
  return value;
}

void expect_end(std::istringstream& in, int line) {
  std::string extra;
  if (in >> extra) throw Error("merge model, line " + std::to_string(line) + ": unexpected '" + extra + "'");
}

Error line_error(int line, const std::string& what) { return Error("merge model, line " + std::to_string(line) + ": " + what); }

int feature_named(const std::string& name, int line) {
  const int index = merge_feature_index(name);
  if (index < 0) throw line_error(line, "unknown feature '" + name + "'");
  return index;
}

// One node line of a tree ("split NAME THRESHOLD YES NO" or "leaf VALUE").
MergeTreeNode tree_node(const std::string& key, std::istringstream& in, int line) {
  MergeTreeNode node;
  if (key == "leaf") {
    node.value = finite_number(in, line, "a leaf's value");
  } else if (key == "split") {
    std::string name;
    in >> name;
    node.feature = feature_named(name, line);
    node.threshold = finite_number(in, line, "a split's threshold");
    if (!(in >> node.yes >> node.no)) throw line_error(line, "a split needs its two next nodes");
  } else {
    throw line_error(line, "expected 'split', 'leaf' or 'end' in a tree, not '" + key + "'");
  }
  expect_end(in, line);
  return node;
}

// A tree's node line in its plain form, read without the stream: "leaf VALUE" or "split NAME
// THRESHOLD YES NO", words separated by spaces and tabs, the numbers read whole by std::from_chars,
// NAME a known feature. nullopt for any other line (a comment, other whitespace or bytes, a sign, an unknown name, a word
// too many or too few), which tree_node() reads with the stream as before, or refuses.
std::optional<MergeTreeNode> plain_tree_node(std::string_view line) {
  PlainWords words(line);
  MergeTreeNode node;
  if (words.take("leaf")) return words.decimal(node.value) && words.done() ? std::optional<MergeTreeNode>(node) : std::nullopt;
  if (!words.take("split")) return std::nullopt;
  node.feature = merge_feature_index(words.name());
  if (node.feature < 0 || !words.decimal(node.threshold) || !words.index(node.yes) || !words.index(node.no) || !words.done())
    return std::nullopt;
  return node;
}

// Why tree is no tree of a model, or "" when it is one: every split points forwards to a node of its
// own tree (so evaluation ends at a leaf), on a known feature, and no path is deeper than the limit.
std::string tree_fault(const std::vector<MergeTreeNode>& tree) {
  if (tree.empty()) return "a tree without nodes";
  const int size = static_cast<int>(tree.size());
  const int features = static_cast<int>(merge_feature_names().size());
  std::vector<int> depth(tree.size(), 0);  // splits below each node; children come later, so back to front
  for (int i = size - 1; i >= 0; --i) {
    const MergeTreeNode& n = tree[static_cast<std::size_t>(i)];
    if (n.feature < 0) {
      if (!std::isfinite(n.value)) return "a leaf's value must be a finite number";
      continue;
    }
    if (n.feature >= features) return "node " + std::to_string(i) + " splits on no known feature";
    if (!std::isfinite(n.threshold)) return "a split's threshold must be a finite number";
    if (n.yes <= i || n.no <= i || n.yes >= size || n.no >= size)
      return "node " + std::to_string(i) + " of the tree points outside it or backwards";
    depth[static_cast<std::size_t>(i)] = 1 + std::max(depth[static_cast<std::size_t>(n.yes)], depth[static_cast<std::size_t>(n.no)]);
    if (depth[static_cast<std::size_t>(i)] > kMaxMergeTreeDepth)
      return "a tree deeper than " + std::to_string(kMaxMergeTreeDepth) + " splits (the limit)";
  }
  return "";
}

void check_tree(const std::vector<MergeTreeNode>& tree, int line) {
  const std::string fault = tree_fault(tree);
  if (!fault.empty()) throw line_error(line, fault);
}

Error too_many(const std::string& what, std::size_t limit) {
  return Error("merge model: more than " + std::to_string(limit) + " " + what + " (the limit)");
}

}  // namespace

MergeModel parse_merge_model(const std::string& text) {
  if (text.size() > kMaxMergeModelBytes)
    throw Error("merge model: " + std::to_string(text.size()) + " bytes, more than the limit of " + byte_size_text(kMaxMergeModelBytes));
  MergeModel model;
  std::size_t nodes = 0;
  model.text = text;
  int number = 0;
  bool header = false, in_tree = false;
  // One stream for every line: making a stream per line (its locale and buffers) was most of the
  // cost of reading the shipped model's nine thousand lines, paid once by every `topocut` run.
  std::istringstream in;
  // The tree being read: its nodes are copied into the model once, at its end, rather than the
  // model's tree grown node by node.
  std::vector<MergeTreeNode> tree;
  // The lines as std::getline splits them (at each '\n', none after a last '\n'), without copying.
  for (std::size_t at = 0; at < text.size();) {
    const std::size_t newline = std::min(text.find('\n', at), text.size());
    const std::string_view raw = std::string_view(text).substr(at, newline - at);
    at = newline + 1;
    ++number;
    // Nine in ten lines are plain tree nodes: read without the stream, which was most of the cost.
    if (in_tree) {
      if (const std::optional<MergeTreeNode> node = plain_tree_node(raw)) {
        if (++nodes > kMaxMergeModelNodes) throw too_many("tree nodes", kMaxMergeModelNodes);
        tree.push_back(*node);
        continue;
      }
    }
    in.clear();
    in.str(std::string(raw.substr(0, raw.find('#'))));
    std::string key;
    if (!(in >> key)) continue;
    if (in_tree) {
      if (key == "end") {
        expect_end(in, number);
        check_tree(tree, number);
        model.trees.push_back(tree);
        tree.clear();
        in_tree = false;
      } else {
        if (++nodes > kMaxMergeModelNodes) throw too_many("tree nodes", kMaxMergeModelNodes);
        tree.push_back(tree_node(key, in, number));
      }
    } else if (!header) {
      int version = 0;
      if (key != "topocut-merge-model" || !(in >> version) || version != 1)
        throw Error("merge model, line " + std::to_string(number) + ": expected 'topocut-merge-model 1'");
      expect_end(in, number);
      header = true;
    } else if (key == "threshold") {
      model.threshold = finite_number(in, number, "the threshold");
      expect_end(in, number);
    } else if (key == "bias") {
      model.bias = finite_number(in, number, "the bias");
      expect_end(in, number);
    } else if (key == "tree") {
      expect_end(in, number);
      if (model.trees.size() == kMaxMergeTrees) throw too_many("trees", kMaxMergeTrees);
      in_tree = true;
    } else {
      const int index = feature_named(key, number);
      for (const int f : model.features)
        if (f == index) throw Error("merge model, line " + std::to_string(number) + ": feature '" + key + "' given twice");
      model.features.push_back(index);
      model.mean.push_back(finite_number(in, number, "the mean"));
      const double scale = finite_number(in, number, "the scale");
      if (scale <= 0.0) throw Error("merge model, line " + std::to_string(number) + ": the scale must be positive");
      model.scale.push_back(scale);
      model.weight.push_back(finite_number(in, number, "the weight"));
      expect_end(in, number);
    }
  }
  if (!header) throw Error("merge model: no 'topocut-merge-model 1' line");
  if (in_tree) throw Error("merge model: the last tree has no 'end'");
  return model;
}

void validate(const MergeModel& model) {
  const std::size_t n = model.features.size();
  if (model.mean.size() != n || model.scale.size() != n || model.weight.size() != n)
    throw Error("merge model: every linear feature needs a mean, a scale and a weight");
  const int features = static_cast<int>(merge_feature_names().size());
  for (std::size_t i = 0; i < n; ++i) {
    if (model.features[i] < 0 || model.features[i] >= features) throw Error("merge model: a linear term on no known feature");
    for (std::size_t j = 0; j < i; ++j)
      if (model.features[j] == model.features[i]) throw Error("merge model: a feature given twice");
    if (!std::isfinite(model.mean[i]) || !std::isfinite(model.weight[i]) || !(model.scale[i] > 0.0) || !std::isfinite(model.scale[i]))
      throw Error("merge model: a linear term's mean and weight must be finite and its scale positive");
  }
  if (!std::isfinite(model.bias) || !std::isfinite(model.threshold)) throw Error("merge model: the bias and threshold must be finite");
  if (model.trees.size() > kMaxMergeTrees) throw too_many("trees", kMaxMergeTrees);
  std::size_t nodes = 0;
  for (const std::vector<MergeTreeNode>& tree : model.trees) {
    nodes += tree.size();
    if (nodes > kMaxMergeModelNodes) throw too_many("tree nodes", kMaxMergeModelNodes);
    const std::string fault = tree_fault(tree);
    if (!fault.empty()) throw Error("merge model: " + fault);
  }
}

double merge_probability(const MergeModel& model, const std::vector<double>& features) {
  double z = model.bias;
  for (std::size_t i = 0; i < model.features.size(); ++i) {
    const double x = features[static_cast<std::size_t>(model.features[i])];
    z += model.weight[i] * (x - model.mean[i]) / model.scale[i];
  }
  for (const std::vector<MergeTreeNode>& tree : model.trees) {
    std::size_t at = 0;
    while (tree[at].feature >= 0) {
      const MergeTreeNode& n = tree[at];
      at = static_cast<std::size_t>(features[static_cast<std::size_t>(n.feature)] <= n.threshold ? n.yes : n.no);
    }
    z += tree[at].value;
  }
  return 1.0 / (1.0 + std::exp(-z));
}

}  // namespace topocut
