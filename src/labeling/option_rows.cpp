// The labeling module's option table (sparse_labeling.h): each field's name, unit, range and help
// once; defaults are the struct's own (or the caller's, such as the walls' coarser cells).
#include "topocut/core/error.h"
#include "topocut/labeling/sparse_labeling.h"

namespace topocut {

const std::vector<OptionRow<LabelingOptions>>& labeling_option_rows() {
  using L = LabelingOptions;
  static const std::vector<OptionRow<L>> rows = {
      field_row("cell", "M", OptionRange::kLength, &L::cell_size, "labeling: raster cell size in metres"),
      field_row("dilate", "N", OptionRange::kWholeNumber, &L::dilation,
                "labeling: dilation iterations of the 3x3 structuring element (at most 1000)"),
      {"connectivity", "4|8", "labeling: connected components by 4 or 8 neighbours", OptionRange::kAny,
       [](const L& l) { return static_cast<double>(l.connectivity); },
       [](L& l, double v) {
         if (v != 4.0 && v != 8.0) throw Error("--connectivity must be 4 or 8, got " + shortest_number(v));
         l.connectivity = static_cast<int>(v);
       }},
  };
  return rows;
}

const std::vector<ChoiceRow<LabelingOptions>>& labeling_choice_rows() {
  using L = LabelingOptions;
  static const std::vector<ChoiceRow<L>> rows = {
      choice_row<L, StructuringElement>("element", &L::element,
                                        {{"cross", StructuringElement::kCross}, {"square", StructuringElement::kSquare}},
                                        "labeling: structuring element, cross or square"),
  };
  return rows;
}

}  // namespace topocut
