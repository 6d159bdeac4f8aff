// Line-extraction benchmark after the protocol of Borges & Aldon (2004, Tables 1-2), in our own
// simulated environment: 15 numbered wall segments, a robot driving along a path A..F taking 200
// scans (270 degree field of view, 0.6 degree resolution = 451 beams, 5 cm Gaussian range noise).
// For every environment line and method it reports
//   N   extracted lines per scan in which the environment line is visible (>= min_hits beams),
//   eta share of those lines that are valid (|d rho| <= 0.5 m and |d alpha| <= 20 degrees),
//   e_rho, e_alpha  mean absolute errors of the valid lines,
// and the extraction time per scan. An extracted line belongs to the environment line, among those
// hit by its supporting beams, whose polar parameters (in the sensor frame) are most similar.
// Then every method runs over the CARMEN logs in ../shared/datasets/carmen (lines and time per scan).
// Options: --help.
#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "support/benchmark_main.h"
#include "topocut/io/carmen_log.h"
#include "topocut/lines/extract.h"
#include "topocut/lines/line_fit.h"
#include "topocut/scan/laser_simulator.h"
#include "topocut/scan/scan_csv.h"

namespace {

using namespace topocut;
constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

// The environment: an 10 m x 8 m hall with a chamfered corner, an alcove and two obstacles.
// Numbered 1..15 in the tables (index + 1).
std::vector<Segment2> environment() {
  return {
      {{0.0, 0.0}, {8.0, 0.0}},    // 1  south wall
      {{8.0, 0.0}, {8.0, 2.0}},    // 2  alcove side
      {{8.0, 2.0}, {10.0, 2.5}},   // 3  alcove back, slightly oblique
      {{10.0, 2.5}, {10.0, 7.0}},  // 4  east wall
      {{10.0, 7.0}, {6.0, 8.0}},   // 5  oblique north-east wall
      {{6.0, 8.0}, {2.0, 8.0}},    // 6  north wall
      {{2.0, 8.0}, {0.0, 6.0}},    // 7  45 degree chamfer
      {{0.0, 6.0}, {0.0, 0.0}},    // 8  west wall
      {{3.0, 3.0}, {5.0, 3.0}},    // 9  box, south face
      {{5.0, 3.0}, {5.0, 4.2}},    // 10 box, east face
      {{5.0, 4.2}, {3.0, 4.2}},    // 11 box, north face
      {{3.0, 4.2}, {3.0, 3.0}},    // 12 box, west face
      {{7.0, 4.4}, {8.3, 5.3}},    // 13 triangular pillar
      {{8.3, 5.3}, {6.9, 6.1}},    // 14
      {{6.9, 6.1}, {7.0, 4.4}},    // 15
  };
}

// The path A..F through the free space.
std::vector<Point2> path_waypoints() {
  return {{1.5, 1.5}, {6.5, 1.5}, {9.0, 3.8}, {8.8, 7.0}, {4.0, 6.5}, {1.5, 4.0}};
}

std::vector<Pose2> poses_along_path(std::size_t count) {
  const std::vector<Point2> w = path_waypoints();
  std::vector<double> cumulative{0.0};
  for (std::size_t i = 1; i < w.size(); ++i) cumulative.push_back(cumulative.back() + distance(w[i - 1], w[i]));
  std::vector<Pose2> poses;
  for (std::size_t k = 0; k < count; ++k) {
    const double s = cumulative.back() * static_cast<double>(k) / static_cast<double>(count - 1);
    std::size_t leg = 1;
    while (leg + 1 < w.size() && cumulative[leg] < s) ++leg;
    const double t = (s - cumulative[leg - 1]) / (cumulative[leg] - cumulative[leg - 1]);
    const Point2 a = w[leg - 1], b = w[leg];
    const Point2 d = b - a, at = a + t * d;
    poses.push_back({at.x, at.y, std::atan2(d.y, d.x)});
  }
  return poses;
}

struct PolarError {
  double rho = 0.0;
  double alpha = 0.0;
};

// Errors between an extracted line and a true one, over both equivalent polar forms of the truth.
PolarError polar_error(double rho, double alpha, double true_rho, double true_alpha) {
  const PolarError same{std::abs(rho - true_rho), angle_difference(alpha, true_alpha)};
  const PolarError flipped{std::abs(rho + true_rho), angle_difference(alpha, true_alpha + kPi)};
  auto score = [](const PolarError& e) { return e.rho / 0.5 + e.alpha / (20.0 * kDeg); };
  return score(same) <= score(flipped) ? same : flipped;
}

LineFit true_line(const Segment2& wall, const Pose2& pose) {
  const Point2 a = to_local(pose, wall.a), b = to_local(pose, wall.b);
  return polar_line(a, std::atan2(b.y - a.y, b.x - a.x) + kPi / 2);
}

struct Stats {
  double visible = 0;  // scans in which the line is visible
  double lines = 0;    // extracted lines assigned to it
  double valid = 0;
  double sum_rho = 0, sum_alpha = 0;
};

std::string fixed(double v, int digits) {
  if (!std::isfinite(v)) return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", digits, v);
  return buffer;
}

void print_table(const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width(rows[0].size(), 0);
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  for (std::size_t r = 0; r < rows.size(); ++r) {
    std::cout << "|";
    for (std::size_t c = 0; c < rows[r].size(); ++c)
      std::cout << " " << rows[r][c] << std::string(width[c] - rows[r][c].size(), ' ') << " |";
    std::cout << "\n";
    if (r == 0) {
      std::cout << "|";
      for (std::size_t c = 0; c < rows[r].size(); ++c) std::cout << std::string(width[c] + 1, '-') << (c == 0 ? "-|" : ":|");
      std::cout << "\n";
    }
  }
  std::cout << "\n";
}

// Thread CPU time: the machine is shared, and wall time would count other processes' slices.
double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// Median over `repeat` runs of the CPU time per scan (microseconds); the lines of the last run.
double time_method(const std::vector<Scan>& scans, const LineExtractionOptions& options, int repeat,
                   std::vector<std::vector<Line>>& lines) {
  std::vector<double> per_scan;
  for (int r = 0; r < repeat; ++r) {
    lines.assign(scans.size(), {});
    const double t0 = cpu_seconds();
    for (std::size_t k = 0; k < scans.size(); ++k) lines[k] = extract_lines(scans[k], options);
    per_scan.push_back((cpu_seconds() - t0) * 1e6 / static_cast<double>(scans.size()));
  }
  std::sort(per_scan.begin(), per_scan.end());
  return per_scan[per_scan.size() / 2];
}

const std::vector<LineMethod> kMethods{LineMethod::kSef, LineMethod::kLt, LineMethod::kIepf, LineMethod::kSmf,
                                       LineMethod::kAle};

std::string upper(LineMethod m) {
  std::string s = to_string(m);
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

void run_simulation(std::size_t scan_count, int repeat, const std::string& csv_dir) {
  const std::vector<Segment2> walls = environment();
  const std::vector<Pose2> poses = poses_along_path(scan_count);
  LaserSpec spec;
  spec.field_of_view = 270.0 * kDeg;
  spec.angular_resolution = 0.6 * kDeg;
  spec.range_max = 15.0;
  spec.noise_stddev = 0.05;
  std::vector<SimulatedScan> simulated;
  std::vector<Scan> scans;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    spec.seed = static_cast<std::uint32_t>(1000 + k);
    simulated.push_back(simulate_scan(walls, poses[k], spec));
    scans.push_back(simulated.back().scan);
  }
  if (!csv_dir.empty()) {
    std::filesystem::create_directories(csv_dir);
    for (std::size_t k = 0; k < scans.size(); k += 20) {
      std::ofstream(csv_dir + "/scan_" + std::to_string(k) + ".csv") << format_scan_csv(scans[k]);
    }
  }

  const std::size_t min_hits = 5;  // a wall counts as visible with at least this many beams on it
  std::vector<std::vector<Stats>> stats(kMethods.size(), std::vector<Stats>(walls.size()));
  std::vector<double> time_us(kMethods.size());
  std::vector<double> lines_per_scan(kMethods.size());
  std::vector<double> unassigned(kMethods.size());
  for (std::size_t m = 0; m < kMethods.size(); ++m) {
    LineExtractionOptions options;
    options.method = kMethods[m];
    std::vector<std::vector<Line>> lines;
    time_us[m] = time_method(scans, options, repeat, lines);
    double total_lines = 0;
    for (std::size_t k = 0; k < scans.size(); ++k) {
      const SimulatedScan& s = simulated[k];
      std::vector<std::size_t> hits(walls.size(), 0);
      for (std::size_t i = 0; i < s.hit.size(); ++i)
        if (s.hit[i] >= 0 && s.scan.is_valid(i)) ++hits[static_cast<std::size_t>(s.hit[i])];
      for (std::size_t w = 0; w < walls.size(); ++w)
        if (hits[w] >= min_hits) stats[m][w].visible += 1;
      for (const Line& line : lines[k]) {
        total_lines += 1;
        std::vector<int> candidates;
        for (const std::size_t row : line.support)
          if (s.hit[row] >= 0) candidates.push_back(s.hit[row]);
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        int best = -1;
        PolarError best_error;
        double best_score = std::numeric_limits<double>::infinity();
        for (const int w : candidates) {
          const LineFit truth = true_line(walls[static_cast<std::size_t>(w)], poses[k]);
          const PolarError e = polar_error(line.rho, line.alpha, truth.rho, truth.alpha);
          const double score = e.rho / 0.5 + e.alpha / (20.0 * kDeg);
          if (score < best_score) best_score = score, best = w, best_error = e;
        }
        if (best < 0) {
          unassigned[m] += 1;
          continue;
        }
        Stats& st = stats[m][static_cast<std::size_t>(best)];
        st.lines += 1;
        if (best_error.rho <= 0.5 && best_error.alpha <= 20.0 * kDeg) {
          st.valid += 1;
          st.sum_rho += best_error.rho;
          st.sum_alpha += best_error.alpha;
        }
      }
    }
    lines_per_scan[m] = total_lines / static_cast<double>(scans.size());
  }

  std::cout << "### Simulated environment (" << scans.size() << " scans, 451 beams, 270 deg, 0.6 deg, sigma 5 cm)\n\n";
  std::cout << "Table 1: N = extracted lines per scan in which the environment line is visible; eta = share "
               "of them that are valid (|d rho| <= 0.5 m, |d alpha| <= 20 deg).\n\n";
  std::vector<std::vector<std::string>> t1{{"line", "visible"}};
  for (const LineMethod m : kMethods) t1[0].push_back("N " + upper(m));
  for (const LineMethod m : kMethods) t1[0].push_back("eta " + upper(m));
  std::vector<double> mean_n(kMethods.size(), 0), mean_eta(kMethods.size(), 0), mean_er(kMethods.size(), 0),
      mean_ea(kMethods.size(), 0);
  std::vector<int> counted(kMethods.size(), 0);
  for (std::size_t w = 0; w < walls.size(); ++w) {
    std::vector<std::string> row{std::to_string(w + 1), fixed(stats[0][w].visible, 0)};
    for (std::size_t m = 0; m < kMethods.size(); ++m) {
      const Stats& st = stats[m][w];
      const double n = st.visible > 0 ? st.lines / st.visible : NAN;
      row.push_back(fixed(n, 2));
      mean_n[m] += std::isfinite(n) ? n : 0;
    }
    for (std::size_t m = 0; m < kMethods.size(); ++m) {
      const Stats& st = stats[m][w];
      const double eta = st.lines > 0 ? st.valid / st.lines : NAN;
      row.push_back(fixed(eta, 2));
      if (std::isfinite(eta)) mean_eta[m] += eta;
      if (st.valid > 0) {
        mean_er[m] += st.sum_rho / st.valid;
        mean_ea[m] += st.sum_alpha / st.valid;
        counted[m] += 1;
      }
    }
    t1.push_back(row);
  }
  {
    std::vector<std::string> row{"mean", ""};
    for (std::size_t m = 0; m < kMethods.size(); ++m) row.push_back(fixed(mean_n[m] / walls.size(), 2));
    for (std::size_t m = 0; m < kMethods.size(); ++m) row.push_back(fixed(mean_eta[m] / walls.size(), 2));
    t1.push_back(row);
  }
  print_table(t1);

  std::cout << "Table 2: mean absolute errors of the valid lines, e_rho in cm and e_alpha in degrees.\n\n";
  std::vector<std::vector<std::string>> t2{{"line"}};
  for (const LineMethod m : kMethods) t2[0].push_back("e_rho " + upper(m));
  for (const LineMethod m : kMethods) t2[0].push_back("e_alpha " + upper(m));
  for (std::size_t w = 0; w < walls.size(); ++w) {
    std::vector<std::string> row{std::to_string(w + 1)};
    for (std::size_t m = 0; m < kMethods.size(); ++m) {
      const Stats& st = stats[m][w];
      row.push_back(st.valid > 0 ? fixed(100.0 * st.sum_rho / st.valid, 2) : "-");
    }
    for (std::size_t m = 0; m < kMethods.size(); ++m) {
      const Stats& st = stats[m][w];
      row.push_back(st.valid > 0 ? fixed(st.sum_alpha / st.valid / kDeg, 2) : "-");
    }
    t2.push_back(row);
  }
  {
    std::vector<std::string> row{"mean"};
    for (std::size_t m = 0; m < kMethods.size(); ++m) row.push_back(fixed(100.0 * mean_er[m] / counted[m], 2));
    for (std::size_t m = 0; m < kMethods.size(); ++m) row.push_back(fixed(mean_ea[m] / counted[m] / kDeg, 2));
    t2.push_back(row);
  }
  print_table(t2);

  std::cout << "Table 3: speed and summary (median of " << repeat << " runs over all scans).\n\n";
  std::vector<std::vector<std::string>> t3{
      {"method", "us per scan", "lines per scan", "lines without a true wall", "mean N", "mean eta",
       "lines with N < IEPF's", "lines with N < LT's"}};
  for (std::size_t m = 0; m < kMethods.size(); ++m) {
    int below_iepf = 0, below_lt = 0;
    for (std::size_t w = 0; w < walls.size(); ++w) {
      auto n_of = [&](std::size_t mm) { return stats[mm][w].visible > 0 ? stats[mm][w].lines / stats[mm][w].visible : 0.0; };
      below_iepf += n_of(m) < n_of(2) ? 1 : 0;
      below_lt += n_of(m) < n_of(1) ? 1 : 0;
    }
    t3.push_back({upper(kMethods[m]), fixed(time_us[m], 1), fixed(lines_per_scan[m], 2),
                  fixed(unassigned[m], 0), fixed(mean_n[m] / walls.size(), 2), fixed(mean_eta[m] / walls.size(), 2),
                  std::to_string(below_iepf) + "/15", std::to_string(below_lt) + "/15"});
  }
  print_table(t3);
}

void run_carmen(int repeat) {
  const std::filesystem::path dir = std::filesystem::path(TOPOCUT_SHARED_DIR) / "datasets" / "carmen";
  if (!std::filesystem::is_directory(dir)) {
    std::cout << "CARMEN logs not found in " << dir << ": skipped.\n";
    return;
  }
  std::vector<std::filesystem::path> logs;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().filename().string().ends_with(".log.gz")) logs.push_back(entry.path());
  std::sort(logs.begin(), logs.end());
  std::cout << "### CARMEN logs (real SICK scans, 180 or 361 beams over 180 deg)\n\n";
  std::cout << "Lines per scan (mean) and time per scan in microseconds (median of " << repeat << " runs).\n\n";
  std::vector<std::vector<std::string>> t{{"log", "scans", "beams"}};
  for (const LineMethod m : kMethods) t[0].push_back("lines " + upper(m));
  for (const LineMethod m : kMethods) t[0].push_back("us " + upper(m));
  for (const auto& path : logs) {
    const CarmenLog log = read_carmen_log(path.string());
    std::vector<Scan> scans;
    for (const CarmenLaserScan& c : log.scans) {
      Scan s;
      s.ranges = c.ranges;
      for (std::size_t i = 0; i < c.ranges.size(); ++i) s.angles.push_back(c.start_angle + i * c.angle_step);
      // Readings at or beyond the saturation value mean "no return".
      s.range_max = std::nextafter(log.max_range, 0.0);
      scans.push_back(std::move(s));
    }
    std::vector<std::string> row{path.filename().string(), std::to_string(scans.size()),
                                 scans.empty() ? "0" : std::to_string(scans.front().size())};
    std::vector<std::string> times;
    for (const LineMethod m : kMethods) {
      LineExtractionOptions options;
      options.method = m;
      std::vector<std::vector<Line>> lines;
      const double us = time_method(scans, options, repeat, lines);
      double total = 0;
      for (const auto& l : lines) total += static_cast<double>(l.size());
      row.push_back(fixed(total / std::max<std::size_t>(scans.size(), 1), 2));
      times.push_back(fixed(us, 1));
    }
    row.insert(row.end(), times.begin(), times.end());
    t.push_back(row);
  }
  print_table(t);
}

}  // namespace

int main(int argc, char** argv) {
  using namespace topocut::benchmarks;
  int scans = 200, repeat = 5;
  bool no_carmen = false;
  std::string csv_dir;
  const Program program{
      .name = "lines_benchmark",
      .title = "Line extraction",
      .about = "The five line extractors after Borges & Aldon's protocol (15 walls, scans along a path, 270 deg,\n"
               "0.6 deg, 5 cm noise): lines per visible wall, valid share, errors and time per scan; then on the\n"
               "shared CARMEN logs. One thread.\n",
      .options = {count("scans", scans, 2, "scans along the path (default 200)"),
                  count("repeat", repeat, 1, "timed runs over all scans, median taken (default 5)"),
                  flag("no-carmen", no_carmen, "leave out the CARMEN logs"),
                  text("csv-dir", "DIR", csv_dir, "also write every 20th simulated scan to DIR as CSV")}};
  return benchmark_main(argc, argv, program, [&] {
    run_simulation(static_cast<std::size_t>(scans), repeat, csv_dir);
    if (!no_carmen) run_carmen(repeat);
    return kDone;
  });
}
