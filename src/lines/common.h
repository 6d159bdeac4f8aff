#pragma once
// Internal pieces shared by the extractors.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lines/moments.h"
#include "topocut/lines/breakpoints.h"
#include "topocut/lines/line.h"
#include "topocut/scan/scan.h"

namespace topocut::detail {

// Validates the scan (sizes, limits, strictly increasing angles over the valid beams; throws Error)
// and returns its valid points in beam order.
std::vector<ScanPoint> prepared_points(const Scan& scan);

// Moments of points[run.first .. run.last].
Moments moments_of(const std::vector<ScanPoint>& points, const PointRun& run);

// Largest perpendicular distance of points[run] from the line.
double max_distance(const std::vector<ScanPoint>& points, const PointRun& run, const NormalForm& line);

// Sequential groups: consecutive runs in beam order; neighbours[i] says whether groups i and i+1
// touch (no breakpoint between them), so their common boundary may move. Moves boundary points to
// the neighbouring group while they lie closer to the neighbour's line than to their own (the split
// point of IEPF and the lag of SEF/LT are otherwise assigned arbitrarily). Groups keep >= 2 points.
void refine_boundaries(const std::vector<ScanPoint>& points, std::vector<PointRun>& groups,
                       const std::vector<bool>& neighbours);

// The line of support rows (increasing, valid) whose sensor-frame points are given (make_line
// without recomputing the points).
Line line_from_points(std::vector<std::size_t> support, const std::vector<Point2>& points);

// Line of the given positions (increasing) into the valid points.
Line line_from_positions(const std::vector<ScanPoint>& points, const std::vector<std::size_t>& positions);

// Drops the first point of a group that starts a run of touching groups and the last point of one
// that ends it while it lies more than 3 RMSE (of the rest of the group) off the rest's line: a lone
// point left over from the neighbouring surface (or a mixed measurement at a range jump) would
// otherwise be glued to the line, since no neighbour can take it. At most two points per end.
void trim_run_ends(const std::vector<ScanPoint>& points, std::vector<PointRun>& groups,
                   const std::vector<bool>& neighbours);

// Fuses touching groups whose common line has an RMSE of at most max(RMSE of each) + tolerance:
// the fused line explains both as well as either explains itself. Updates neighbours accordingly.
void merge_collinear(const std::vector<ScanPoint>& points, std::vector<PointRun>& groups, std::vector<bool>& neighbours,
                     double tolerance);

// Non-sequential version of refine_boundaries: labels[k] is the line of valid point k (-1: none) and
// joined[k] says whether points k and k+1 are scan neighbours (same breakpoint run). A point moves to
// the line of a scan neighbour while it lies closer to that line than to its own (lines keep >= 2
// points). Passes repeat until nothing moves (at most 50).
void refine_labels(const std::vector<ScanPoint>& points, const std::vector<bool>& joined, std::vector<int>& labels,
                   std::vector<Moments>& lines);

// Lines of the groups with at least min_points points, in order.
std::vector<Line> lines_from_runs(const Scan& scan, const std::vector<ScanPoint>& points,
                                  const std::vector<PointRun>& groups, std::size_t min_points);

// The point visits the recursive splits of IEPF and SMF may make on one scan, in all. A scan whose
// splits each peel one point off would need n^2 / 2 (hours at 4 million beams); a real scan needs
// a few per beam.
inline constexpr std::uint64_t kMaxSplitVisits = 2'000'000'000;

// Counts a split phase's visits; spend() throws Error naming the method past kMaxSplitVisits.
class SplitBudget {
 public:
  explicit SplitBudget(const char* method) : method_(method) {}
  void spend(std::size_t visits);
  std::uint64_t spent() const { return spent_; }

 private:
  const char* method_;
  std::uint64_t spent_ = 0;
};

// Throws Error unless value is finite and > 0 (name used in the message).
void require_positive(double value, const char* name);

}  // namespace topocut::detail
