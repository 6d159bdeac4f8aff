// libFuzzer target: merge model texts. Any text must parse into a model within the limits (trees,
// depth, nodes: validate() agrees) whose probability is a number in [0, 1] after visiting at most
// trees x (depth + 1) nodes, or be refused with a topocut::Error; never a crash, hang or other
// exception.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "topocut/core/error.h"
#include "topocut/segmentation/merge_features.h"
#include "topocut/segmentation/merge_model.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topocut;
  const std::string text(reinterpret_cast<const char*>(data), size);
  MergeModel model;
  try {
    model = parse_merge_model(text);
  } catch (const Error&) {
    return 0;
  }
  try {
    validate(model);
  } catch (const Error& e) {
    fuzz::fail(std::string("parsed a model validate() refuses: ") + e.what());
  }
  if (model.trees.size() > kMaxMergeTrees) fuzz::fail("more trees than the limit");
  std::vector<double> features(merge_feature_names().size());
  for (std::size_t i = 0; i < features.size(); ++i) features[i] = i < size ? static_cast<double>(data[i]) / 25.0 - 3.0 : 0.5;
  const double p = merge_probability(model, features);
  if (!(p >= 0.0 && p <= 1.0)) fuzz::fail("a probability outside [0, 1]");
  return 0;
}
