#include "topocut/walls/posed_scan.h"

#include <limits>

namespace topocut {

std::vector<PosedScan> posed_scans(const CarmenLog& log) {
  std::vector<PosedScan> out;
  out.reserve(log.scans.size());
  for (const CarmenLaserScan& laser : log.scans) {
    PosedScan posed;
    const std::size_t n = laser.ranges.size();
    posed.scan.angles.resize(n);
    posed.scan.ranges.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      posed.scan.angles[i] = laser.start_angle + static_cast<double>(i) * laser.angle_step;
      const double r = laser.ranges[i];
      posed.scan.ranges[i] = r >= log.max_range ? std::numeric_limits<double>::infinity() : r;
    }
    posed.scan.range_max = log.max_range;
    posed.pose = {laser.pose.x, laser.pose.y, laser.pose.theta};
    out.push_back(std::move(posed));
  }
  return out;
}

}  // namespace topocut
