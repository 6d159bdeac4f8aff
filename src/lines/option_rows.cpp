// The lines module's option table (extract.h): each tuning option's name, unit, range and help once,
// with the methods that take it; defaults are each method's own (from the literature).
#include <cstddef>
#include <numbers>
#include <utility>
#include <vector>

#include "topocut/lines/extract.h"

namespace topocut {
namespace {

using M = LineMethod;
using O = LineExtractionOptions;

LineOptionRow row(const char* name, const char* value_name, OptionRange range, const char* help, std::vector<LineMethod> methods,
                  double (*get)(const O&), void (*set)(O&, double)) {
  return {{name, value_name, help, range, get, set}, std::move(methods)};
}

}  // namespace

const std::vector<LineOptionRow>& line_option_rows() {
  static const std::vector<LineOptionRow> rows = {
      row("d-max", "M", OptionRange::kPositive, "SEF, LT: gap between consecutive points that ends a line (m)",
          {M::kSef, M::kLt}, [](const O& o) { return o.sef.d_max; }, [](O& o, double v) { o.sef.d_max = o.lt.d_max = v; }),
      row("t-max", "M", OptionRange::kPositive, "SEF, LT, IEPF: distance threshold T_max (m)", {M::kSef, M::kLt, M::kIepf},
          [](const O& o) { return o.sef.t_max; }, [](O& o, double v) { o.sef.t_max = o.lt.t_max = o.iepf.t_max = v; }),
      row("sigma-max", "M", OptionRange::kPositive, "SMF: dispersion threshold sigma_max (m)", {M::kSmf},
          [](const O& o) { return o.smf.sigma_max; }, [](O& o, double v) { o.smf.sigma_max = v; }),
      row("fuzzifier", "F", OptionRange::kPositive, "SMF: fuzzifier m (> 1)", {M::kSmf},
          [](const O& o) { return o.smf.fuzzifier; }, [](O& o, double v) { o.smf.fuzzifier = v; }),
      row("rmse-min", "M", OptionRange::kPositive, "ALE: lower RMSE threshold (m, before noise scaling)", {M::kAle},
          [](const O& o) { return o.ale.rmse_min; }, [](O& o, double v) { o.ale.rmse_min = v; }),
      row("rmse-max", "M", OptionRange::kPositive, "ALE: upper RMSE threshold (m, before noise scaling)", {M::kAle},
          [](const O& o) { return o.ale.rmse_max; }, [](O& o, double v) { o.ale.rmse_max = v; }),
      row("gradient-max", "G", OptionRange::kPositive, "ALE: relative RMSE gradient that marks a corner", {M::kAle},
          [](const O& o) { return o.ale.gradient_max; }, [](O& o, double v) { o.ale.gradient_max = v; }),
      row("reference-noise", "M", OptionRange::kNonNegative, "ALE: range noise for which the RMSE band holds unscaled (m; 0: never scale)",
          {M::kAle}, [](const O& o) { return o.ale.reference_noise; }, [](O& o, double v) { o.ale.reference_noise = v; }),
      row("smoothing-neighbours", "N", OptionRange::kCount, "ALE: lowess neighbourhood in beams", {M::kAle},
          [](const O& o) { return static_cast<double>(o.ale.smoothing.neighbours); },
          [](O& o, double v) { o.ale.smoothing.neighbours = static_cast<std::size_t>(v); }),
      row("lambda-deg", "DEG", OptionRange::kPositive, "IEPF, SMF, ALE: breakpoint angle lambda (degrees)", {M::kIepf, M::kSmf, M::kAle},
          [](const O& o) { return o.iepf.breakpoints.lambda * 180.0 / std::numbers::pi; },
          [](O& o, double v) {
            o.iepf.breakpoints.lambda = o.smf.breakpoints.lambda = o.ale.breakpoints.lambda = v * std::numbers::pi / 180.0;
          }),
      row("sigma-r", "M", OptionRange::kNonNegative, "IEPF, SMF, ALE: range noise for breakpoints (m; 0: estimate from the scan)",
          {M::kIepf, M::kSmf, M::kAle}, [](const O& o) { return o.iepf.breakpoints.sigma_r; },
          [](O& o, double v) { o.iepf.breakpoints.sigma_r = o.smf.breakpoints.sigma_r = o.ale.breakpoints.sigma_r = v; }),
      row("min-points", "N", OptionRange::kCount, "all: fewest beams a reported line may have",
          {M::kSef, M::kLt, M::kIepf, M::kSmf, M::kAle}, [](const O& o) { return static_cast<double>(o.sef.min_points); },
          [](O& o, double v) {
            const auto n = static_cast<std::size_t>(v);
            o.sef.min_points = o.lt.min_points = o.iepf.min_points = o.smf.min_points = o.ale.min_points = n;
          }),
  };
  return rows;
}

}  // namespace topocut

namespace topocut {

const std::vector<ChoiceRow<LineExtractionOptions>>& line_choice_rows() {
  static const std::vector<ChoiceRow<O>> rows = {
      choice_row<O, M>("method", &O::method,
                       {{"sef", M::kSef}, {"lt", M::kLt}, {"iepf", M::kIepf}, {"smf", M::kSmf}, {"ale", M::kAle}},
                       "line extractor (each with its defaults from the literature)"),
  };
  return rows;
}

}  // namespace topocut
