// Build-time compiler of the shipped merge model: reads its text with the library's own parser
// (which checks it) and writes it as C++ arrays (src/segmentation/merging/shipped_merge_model.h),
// so that programs start without parsing it. Numbers are written in the shortest form that reads
// back to the same double, so the arrays hold exactly what parse_merge_model() gives.
//
//   compile_merge_model MODEL.txt OUT.cpp
#include <charconv>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "topocut/core/input_file.h"
#include "topocut/io/atomic_file.h"
#include "topocut/segmentation/merge_model.h"

namespace {

std::string number(double value) {
  char buffer[64];
  const std::to_chars_result end = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end.ptr);
}

template <class T, class Format>
void write_array(std::ostream& out, const char* type, const char* name, const std::vector<T>& values, Format format) {
  out << "const " << type << " " << name << "[] = {";
  for (std::size_t i = 0; i < values.size(); ++i) out << (i % 8 == 0 ? "\n    " : " ") << format(values[i]) << ",";
  if (values.empty()) out << "0";  // no zero-length arrays
  out << "};\n";
}

std::string source(const topocut::MergeModel& model) {
  std::vector<topocut::MergeTreeNode> nodes;
  std::vector<int> sizes;
  for (const auto& tree : model.trees) {
    nodes.insert(nodes.end(), tree.begin(), tree.end());
    sizes.push_back(static_cast<int>(tree.size()));
  }
  std::ostringstream out;
  out << "// Generated at build time by tools/compile_merge_model.cpp from src/segmentation/merging/merge_model.txt;\n"
         "// do not edit.\n#include \"segmentation/merging/shipped_merge_model.h\"\n\nnamespace topocut::shipped {\n\nnamespace {\n\n";
  write_array(out, "int", "kFeatures", model.features, [](int v) { return std::to_string(v); });
  write_array(out, "double", "kMean", model.mean, number);
  write_array(out, "double", "kScale", model.scale, number);
  write_array(out, "double", "kWeight", model.weight, number);
  write_array(out, "int", "kTreeSizes", sizes, [](int v) { return std::to_string(v); });
  write_array(out, "MergeTreeNode", "kNodes", nodes, [](const topocut::MergeTreeNode& n) {
    std::ostringstream node;  // a stream, not string sums: GCC 12 warns wrongly (-Wrestrict) on those
    node << '{' << n.feature << ", " << number(n.threshold) << ", " << n.yes << ", " << n.no << ", " << number(n.value) << '}';
    return node.str();
  });
  out << "\n}  // namespace\n\nconst MergeModelArrays kMergeModel{kFeatures, kMean, kScale, kWeight, " << model.features.size()
      << ", kNodes, kTreeSizes, " << model.trees.size() << ", " << number(model.bias) << ", " << number(model.threshold)
      << "};\n\n}  // namespace topocut::shipped\n";
  return out.str();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: compile_merge_model MODEL.txt OUT.cpp\n";
    return 2;
  }
  try {
    const std::string text = topocut::read_input_file(argv[1], "merge model", topocut::kMaxMergeModelBytes);
    // Written whole and renamed over the target, so that a stopped build leaves no half file.
    topocut::write_file_atomically(argv[2], source(topocut::parse_merge_model(text)));
  } catch (const std::exception& e) {
    std::cerr << "compile_merge_model: " << argv[1] << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}
