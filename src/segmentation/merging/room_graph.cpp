#include "segmentation/merging/room_graph.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>
#include <set>
#include <tuple>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "segmentation/side_width.h"
#include "topocut/core/error.h"
#include "topocut/core/infinity.h"
#include "topocut/map/free_space_polygons.h"
#include "topocut/segmentation/room_merging.h"

namespace topocut {

namespace {

using Key = std::tuple<double, double, double, double>;  // directed edge (a.x, a.y, b.x, b.y)

Key edge_key(const Point2& a, const Point2& b) { return {a.x, a.y, b.x, b.y}; }

double perimeter(const PolygonWithHoles& polygon) {
  double length = perimeter(polygon.outer);
  for (const Ring& hole : polygon.holes) length += perimeter(hole);
  return length;
}

// Vertices per chunk of a ring whose box add_crossings() tests before the vertices.
constexpr std::size_t kRingChunk = 16;

// The bounding boxes of the ring's vertices kRingChunk at a time, in order.
std::vector<Box> ring_chunks(const Ring& ring) {
  std::vector<Box> chunks;
  for (std::size_t first = 0; first < ring.size(); first += kRingChunk) {
    Box& b = chunks.emplace_back();
    for (std::size_t i = first; i < std::min(first + kRingChunk, ring.size()); ++i) {
      b.x0 = std::min(b.x0, ring[i].x);
      b.y0 = std::min(b.y0, ring[i].y);
      b.x1 = std::max(b.x1, ring[i].x);
      b.y1 = std::max(b.y1, ring[i].y);
    }
  }
  return chunks;
}

// Where the line p + t·u (u a unit vector) crosses a ring of one piece, as parameters t; the
// crossing rule is half-open on the side of the line (as the rasterizer's), so a vertex on the line
// is counted once and the even-odd pairing of the sorted values gives the piece's chords. This runs
// for every piece a chord's line meets on every side width merging measures, and real maps' pieces
// have long jagged outlines: a run of vertices whose box (chunks, ring_chunks()) lies clearly on one
// side of the line has no crossing inside it and is skipped; the rest are tested vertex by vertex, by
// the same arithmetic, so the crossings are the same numbers in the same order.
void add_crossings(const Ring& ring, const std::vector<Box>& chunks, const Point2& p, const Point2& u,
                   std::vector<double>& ts) {
  const Point2 n{-u.y, u.x};
  const std::size_t count = ring.size();
  auto side_of = [&](const Point2& v) { return (v.x - p.x) * n.x + (v.y - p.y) * n.y; };
  // +1: every vertex of chunk c is on the positive side, -1: none is, 0: either. The margin is far
  // above the rounding of side_of (which is linear, so a vertex's side lies between its box corners').
  auto chunk_side = [&](std::size_t c) {
    const Box& b = chunks[c];
    const double s[4] = {side_of({b.x0, b.y0}), side_of({b.x1, b.y0}), side_of({b.x0, b.y1}), side_of({b.x1, b.y1})};
    const double margin = 1e-6;
    if (std::min({s[0], s[1], s[2], s[3]}) > margin) return 1;
    if (std::max({s[0], s[1], s[2], s[3]}) < -margin) return -1;
    return 0;
  };
  auto add_edge = [&](const Point2& a, const Point2& b, double sa, double sb) {
    if ((sa > 0.0) == (sb > 0.0)) return;
    const double ta = (a.x - p.x) * u.x + (a.y - p.y) * u.y;
    const double tb = (b.x - p.x) * u.x + (b.y - p.y) * u.y;
    ts.push_back(ta + (tb - ta) * sa / (sa - sb));
  };
  int side = chunks.empty() ? 0 : chunk_side(0);
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    const std::size_t first = c * kRingChunk, last = std::min(first + kRingChunk, count) - 1;
    const std::size_t after = last + 1 < count ? last + 1 : 0;
    const int next_side = c + 1 < chunks.size() ? chunk_side(c + 1) : (chunks.size() == 1 ? side : chunk_side(0));
    if (side == 0) {
      double sa = side_of(ring[first]);
      for (std::size_t i = first; i < last; ++i) {
        const double sb = side_of(ring[i + 1]);
        add_edge(ring[i], ring[i + 1], sa, sb);
        sa = sb;
      }
    }
    // The edge from the chunk's last vertex to the next chunk's first.
    if (side == 0 || side != next_side) add_edge(ring[last], ring[after], side_of(ring[last]), side_of(ring[after]));
    side = next_side;
  }
}

// Cut k's direction (unit, a -> b), its normal into the left or right side, and its middle.
struct CutFrame {
  Point2 u, n, mid;
};

CutFrame cut_frame(const Segment2& c, bool left) {
  const double length = distance(c.a, c.b);
  const Point2 u{(c.b.x - c.a.x) / length, (c.b.y - c.a.y) / length};
  return {u, left ? Point2{-u.y, u.x} : Point2{u.y, -u.x}, {(c.a.x + c.b.x) / 2.0, (c.a.y + c.b.y) / 2.0}};
}

// Area integrals of 1, x, y, x², xy, y² over a ring (signed: positive when counter-clockwise), by
// Green's theorem edge by edge.
void add_ring_moments(const Ring& ring, double m[6]) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& p = ring[i];
    const Point2& q = ring[(i + 1) % n];
    const double c = p.x * q.y - q.x * p.y;
    m[0] += c / 2.0;
    m[1] += c * (p.x + q.x) / 6.0;
    m[2] += c * (p.y + q.y) / 6.0;
    m[3] += c * (p.x * p.x + p.x * q.x + q.x * q.x) / 12.0;
    m[4] += c * (2.0 * p.x * p.y + p.x * q.y + q.x * p.y + 2.0 * q.x * q.y) / 24.0;
    m[5] += c * (p.y * p.y + p.y * q.y + q.y * q.y) / 12.0;
  }
}

}  // namespace

namespace {

// The convex hull of points (cv::convexHull in single precision, as the grid's cells need).
std::vector<Point2> hull_of(const std::vector<Point2>& points) {
  std::vector<cv::Point2f> in, hull;
  in.reserve(points.size());
  for (const Point2& p : points) in.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
  if (in.size() < 3) return points;
  cv::convexHull(in, hull);
  std::vector<Point2> out;
  out.reserve(hull.size());
  for (const cv::Point2f& p : hull) out.push_back({p.x, p.y});
  return out;
}

}  // namespace

// Every piece's directed edges, sorted, each with the first piece (in order) that has it: what the
// measures of the outlines and the cut ends look edges up in, built once instead of a tree of the
// edges per measure.
struct RoomGraph::Edges {
  std::vector<std::pair<Key, int>> sorted;

  explicit Edges(const PieceSet& set) {
    for (std::size_t i = 0; i < set.pieces.size(); ++i) {
      auto add_ring = [&](const Ring& ring) {
        for (std::size_t k = 0; k < ring.size(); ++k)
          sorted.emplace_back(edge_key(ring[k], ring[(k + 1) % ring.size()]), static_cast<int>(i));
      };
      add_ring(set.pieces[i].outer);
      for (const Ring& hole : set.pieces[i].holes) add_ring(hole);
    }
    std::sort(sorted.begin(), sorted.end());  // by edge, then piece: the first of an edge is its first piece
  }

  // The first piece with the edge a -> b, or -1.
  int owner(const Point2& a, const Point2& b) const {
    const Key key = edge_key(a, b);
    const auto it = std::lower_bound(sorted.begin(), sorted.end(), key, [](const std::pair<Key, int>& e, const Key& k) { return e.first < k; });
    return it != sorted.end() && it->first == key ? it->second : -1;
  }
  bool contains(const Point2& a, const Point2& b) const { return owner(a, b) >= 0; }
};

RoomGraph::RoomGraph(const PolygonWithHoles& polygon, const PieceSet& set, const cv::Mat& cells, double resolution,
                     double furniture_size)
    : set_(set), resolution_(resolution), parent_(set.pieces.size()) {
  std::iota(parent_.begin(), parent_.end(), 0);
  members_.resize(set.pieces.size());
  for (std::size_t i = 0; i < set.pieces.size(); ++i) members_[i] = {static_cast<int>(i)};
  boxes_.reserve(set.pieces.size());
  for (const PolygonWithHoles& piece : set.pieces) {
    boxes_.push_back(bounding_box(piece.outer));
    chunks_.push_back({ring_chunks(piece.outer)});
    for (const Ring& hole : piece.holes) chunks_.back().push_back(ring_chunks(hole));
    areas_.push_back(area(piece) * resolution * resolution);
    perimeters_.push_back(perimeter(piece) * resolution);
    double m[6] = {0, 0, 0, 0, 0, 0};
    add_ring_moments(piece.outer, m);
    for (const Ring& hole : piece.holes) add_ring_moments(hole, m);
    moments_.push_back({m[0], m[1], m[2], m[3], m[4], m[5]});
  }
  const Edges edges(set);
  find_sides(edges);
  side_widths_.assign(2 * sides_.size(), SideWidth{});
  side_depths_.assign(2 * sides_.size(), SideWidth{});
  room_measures_.resize(set.pieces.size());
  measure_cut_ends(edges);
  mark_furniture(polygon, furniture_size);
  measure_outlines(edges, cells);
  cells_ = cells;
  measure_scales();
}

// The medians that piece_scale() and cut_scale() return (0 without pieces or cuts). Weighted by area,
// the slivers beside furniture and doors leave the pieces' scale where the rooms and corridors put it.
// A piece's thickness here is 2 area / the perimeter of its convex hull: a robot's map draws walls
// ragged and obstacles as specks, which lengthen the outline without changing the room, and 2 area /
// outline put the same homes' scale at 0.7 of their plans' (seed to seed 0.7 to 1.3). The hulls are
// the pieces' room_hull(), kept for the candidates' convexity.
void RoomGraph::measure_scales() {
  std::vector<std::pair<double, double>> thickness;  // (2 area / hull perimeter, area)
  double total = 0.0;
  for (std::size_t i = 0; i < areas_.size(); ++i) {
    const double hull = perimeter(room_hull(static_cast<int>(i))) * resolution_;
    if (hull <= 0.0) continue;
    thickness.emplace_back(2.0 * areas_[i] / hull, areas_[i]);
    total += areas_[i];
  }
  std::sort(thickness.begin(), thickness.end());
  double below = 0.0;
  for (const auto& [t, a] : thickness) {
    piece_scale_ = t;
    below += a;
    if (below >= 0.5 * total) break;
  }
  std::vector<double> lengths;
  for (const Side& side : sides_) lengths.push_back(side.length);
  if (lengths.empty()) return;
  const std::size_t middle = lengths.size() / 2;
  std::nth_element(lengths.begin(), lengths.begin() + static_cast<std::ptrdiff_t>(middle), lengths.end());
  cut_scale_ = lengths[middle];
}

namespace {

// The cell holding point p of the grid coordinates the pieces are in (x = column, y = rows-1-row at
// the cells' centres, as free_space_polygons() writes them), kUnknown beyond the grid. Reading row
// floor(y) instead read the map upside down, half a cell off: a small room walled all round measured
// its outline mostly against whatever the mirrored map had there.
int cell_at(const cv::Mat& cells, const Point2& p) {
  const int c = static_cast<int>(std::floor(p.x + 0.5)), r = cells.rows - 1 - static_cast<int>(std::floor(p.y + 0.5));
  if (c < 0 || r < 0 || c >= cells.cols || r >= cells.rows) return kUnknown;
  return cells.at<unsigned char>(r, c);
}

// What lies just outside a piece's wall edge a -> b (grid coordinates): the occupied and never-seen
// lengths (cells) of the edge, sampled a cell apart. Outside is the side whose cell is not free (the
// piece's own side is floor); an edge with floor on both sides (a cleaned-away strip) counts as neither.
void classify_edge(const cv::Mat& cells, const Point2& a, const Point2& b, double& occupied, double& unknown) {
  const double length = distance(a, b);
  if (length <= 0.0) return;
  const Point2 n{-(b.y - a.y) / length, (b.x - a.x) / length};
  const int samples = std::max(1, static_cast<int>(std::lround(length)));
  const double step = length / samples;
  auto cell = [&cells](double x, double y) { return cell_at(cells, {x, y}); };
  for (int i = 0; i < samples; ++i) {
    const double t = (i + 0.5) / samples;
    const Point2 p{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
    for (const double d : {0.75, 1.5}) {
      const int left = cell(p.x + d * n.x, p.y + d * n.y), right = cell(p.x - d * n.x, p.y - d * n.y);
      if (left == kFree && right == kFree) continue;
      const int outside = left == kFree ? right : right == kFree ? left : std::min(left, right);
      if (outside == kOccupied) occupied += step;
      else if (outside == kUnknown) unknown += step;
      break;
    }
  }
}

}  // namespace

// Each piece's outline edges that no other piece shares (walls in the making), split by what lies
// beyond them in the grid.
void RoomGraph::measure_outlines(const Edges& edges, const cv::Mat& cells) {
  wall_lengths_.assign(set_.pieces.size(), 0.0);
  unknown_lengths_.assign(set_.pieces.size(), 0.0);
  auto for_each_edge = [](const PolygonWithHoles& piece, const auto& visit) {
    auto ring_edges = [&visit](const Ring& ring) {
      for (std::size_t k = 0; k < ring.size(); ++k) visit(ring[k], ring[(k + 1) % ring.size()]);
    };
    ring_edges(piece.outer);
    for (const Ring& hole : piece.holes) ring_edges(hole);
  };
  for (std::size_t i = 0; i < set_.pieces.size(); ++i) {
    double occupied = 0.0, unknown = 0.0;
    for_each_edge(set_.pieces[i], [&](const Point2& a, const Point2& b) {
      if (edges.contains(b, a)) return;  // shared with another piece: a cut
      if (cells.empty()) occupied += distance(a, b);
      else classify_edge(cells, a, b, occupied, unknown);
    });
    wall_lengths_[i] = occupied * resolution_;
    unknown_lengths_[i] = unknown * resolution_;
  }
}

// The length of room r's outline that is no cut to another room: what the wall and never-seen
// shares are shares of, so that they say what the room's own outline runs along, apart from how
// much of it is open (the open share): on a drawn plan every such outline is wall, whatever the cuts.
double RoomGraph::own_outline(int r) { return room_perimeter(r) - shared_cut_length(r, -1); }

double RoomGraph::wall_length(int r) {
  double length = 0.0;
  for (const int member : members(r)) length += wall_lengths_[static_cast<std::size_t>(member)];
  return length;
}

double RoomGraph::unknown_length(int r) {
  double length = 0.0;
  for (const int member : members(r)) length += unknown_lengths_[static_cast<std::size_t>(member)];
  return length;
}

namespace {
// A length along a room's outline over the outline (own_outline()), at most 1; 0 without one.
double outline_share(double length, double outline) { return outline > 0.0 ? std::min(length / outline, 1.0) : 0.0; }
}  // namespace

double RoomGraph::wall_share(int r) { return outline_share(wall_length(r), own_outline(r)); }

bool RoomGraph::walls_seen() {
  if (!walls_seen_) walls_seen_ = cells_.empty() || cv::countNonZero(cells_ == kOccupied) > 0;
  return *walls_seen_;
}

double RoomGraph::unknown_share(int r) { return outline_share(unknown_length(r), own_outline(r)); }

// The free-space angle at each cut end, and the wall edges there that the cut continues: pieces meet
// only at shared vertices, so the interior angles of the pieces having the end as a vertex add up to
// the free space's angle, and an edge met by no other piece in reverse is a wall.
void RoomGraph::measure_cut_ends(const Edges& edges) {
  struct Corner {
    Point2 prev, next;
  };
  // The pieces' corners at the cut ends only (sorted), in the order of the pieces and their rings.
  using Vertex = std::pair<double, double>;
  std::vector<Vertex> ends;
  for (std::size_t k = 0; k < sides_.size(); ++k)
    if (sides_[k].left >= 0)
      for (const Point2& end : {set_.cuts[k].a, set_.cuts[k].b}) ends.emplace_back(end.x, end.y);
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  auto end_index = [&ends](const Point2& v) -> std::ptrdiff_t {
    const auto it = std::lower_bound(ends.begin(), ends.end(), Vertex{v.x, v.y});
    return it != ends.end() && *it == Vertex{v.x, v.y} ? it - ends.begin() : -1;
  };
  std::vector<std::vector<Corner>> corners(ends.size());
  auto add_ring = [&](const Ring& ring) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::ptrdiff_t at = end_index(ring[i]);
      if (at >= 0) corners[static_cast<std::size_t>(at)].push_back({ring[(i + n - 1) % n], ring[(i + 1) % n]});
    }
  };
  for (const PolygonWithHoles& piece : set_.pieces) {
    add_ring(piece.outer);
    for (const Ring& hole : piece.holes) add_ring(hole);
  }
  auto is_wall = [&](const Point2& a, const Point2& b) { return !edges.contains(b, a); };
  for (std::size_t k = 0; k < sides_.size(); ++k) {
    Side& side = sides_[k];
    if (side.left < 0) continue;
    const Segment2& c = set_.cuts[k];
    const double length = distance(c.a, c.b);
    double angles[2] = {0.0, 0.0};
    double skew[2] = {M_PI / 2.0, M_PI / 2.0};  // above any folded angle: no wall met yet
    double continued[2] = {0.0, 0.0};
    for (int e = 0; e < 2; ++e) {
      const Point2& v = e == 0 ? c.a : c.b;
      const Point2& other = e == 0 ? c.b : c.a;
      const Point2 out{(v.x - other.x) / length, (v.y - other.y) / length};  // the cut's direction beyond v
      const std::ptrdiff_t at = end_index(v);
      if (at < 0) continue;
      for (const Corner& corner : corners[static_cast<std::size_t>(at)]) {
        const double to_next = std::atan2(corner.next.y - v.y, corner.next.x - v.x);
        const double to_prev = std::atan2(corner.prev.y - v.y, corner.prev.x - v.x);
        double interior = to_prev - to_next;
        while (interior <= 0.0) interior += 2.0 * M_PI;
        angles[e] += interior;
        for (const bool next : {false, true}) {
          const Point2& w = next ? corner.next : corner.prev;
          const bool wall = next ? is_wall(v, w) : is_wall(w, v);
          const double wl = distance(v, w);
          if (!wall || wl <= 0.0) continue;
          const double along = ((w.x - v.x) * out.x + (w.y - v.y) * out.y) / wl;
          if (along > 0.98) continued[e] = std::max(continued[e], wl * resolution_);
          // The angle between the cut's line and the wall's, folded into [0, pi / 4].
          double angle = std::fmod(std::acos(std::clamp(std::abs(along), 0.0, 1.0)), M_PI / 2.0);
          if (angle > M_PI / 4.0) angle = M_PI / 2.0 - angle;
          skew[e] = std::min(skew[e], angle);
        }
      }
    }
    side.wall_continued = std::max(continued[0], continued[1]);
    for (const double end_skew : skew)
      if (end_skew <= M_PI / 4.0) side.skew = std::max(side.skew, end_skew);
    side.end_angle[0] = std::min(angles[0], angles[1]);
    side.end_angle[1] = std::max(angles[0], angles[1]);
  }
}

void RoomGraph::find_sides(const Edges& edges) {
  sides_.resize(set_.cuts.size());
  piece_sides_.resize(set_.pieces.size());
  for (std::size_t k = 0; k < set_.cuts.size(); ++k) {
    const Segment2& c = set_.cuts[k];
    const int left = edges.owner(c.a, c.b), right = edges.owner(c.b, c.a);
    if (left < 0 || right < 0 || left == right) continue;
    const CutRule rule = k < set_.rules.size() ? set_.rules[k] : CutRule::kDecomposition;
    sides_[k] = {left, right, distance(c.a, c.b) * resolution_, rule};
    piece_sides_[static_cast<std::size_t>(left)].push_back(k);
    piece_sides_[static_cast<std::size_t>(right)].push_back(k);
  }
}

// Which cut ends lie on an obstacle inside the component (a hole), how large the largest of those is,
// and whether it is furniture (at most furniture_size a side, 0: none): a room does not end at a table.
// The cut ends are sorted by x, so that each hole looks only at the ends beside its box.
void RoomGraph::mark_furniture(const PolygonWithHoles& polygon, double furniture_size) {
  const double limit = furniture_size / resolution_;
  const double near = 1.5;  // cells: the pieces come from the polygon simplified by about a cell
  struct End {
    Point2 at;
    std::size_t k;
  };
  std::vector<End> ends;
  for (std::size_t k = 0; k < sides_.size(); ++k)
    if (sides_[k].left >= 0)
      for (const Point2& end : {set_.cuts[k].a, set_.cuts[k].b}) ends.push_back({end, k});
  std::sort(ends.begin(), ends.end(), [](const End& p, const End& q) { return p.at.x < q.at.x; });
  for (const Ring& hole : polygon.holes) {
    const Box box = bounding_box(hole);
    const double extent = std::max(box.x1 - box.x0, box.y1 - box.y0);
    const bool furniture = furniture_size > 0.0 && box.x1 - box.x0 <= limit && box.y1 - box.y0 <= limit;
    auto first = std::lower_bound(ends.begin(), ends.end(), box.x0 - near, [](const End& e, double x) { return e.at.x < x; });
    for (auto it = first; it != ends.end() && !(it->at.x > box.x1 + near); ++it) {
      const Point2& end = it->at;
      if (end.y < box.y0 - near || end.y > box.y1 + near) continue;
      bool on = false;
      for (std::size_t i = 0; i < hole.size() && !on; ++i) {
        // An edge whose box (grown by a little more than near) misses the end is farther than near:
        // most of a long hole's edges, measured without the distance.
        const Point2& a = hole[i];
        const Point2& b = hole[(i + 1) % hole.size()];
        const double grow = near * 1.001 + 1e-9;
        if (end.x < std::min(a.x, b.x) - grow || end.x > std::max(a.x, b.x) + grow || end.y < std::min(a.y, b.y) - grow ||
            end.y > std::max(a.y, b.y) + grow)
          continue;
        on = distance_to_segment(end, {a, b}) <= near;
      }
      if (!on) continue;
      Side& side = sides_[it->k];
      ++side.ends_on_holes;
      side.hole_extent = std::max(side.hole_extent, extent * resolution_);
      side.furniture = side.furniture || furniture;
    }
  }
}

int RoomGraph::root(int i) {
  while (parent_[static_cast<std::size_t>(i)] != i) {
    parent_[static_cast<std::size_t>(i)] = parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(i)])];
    i = parent_[static_cast<std::size_t>(i)];
  }
  return i;
}

void RoomGraph::unite(int a, int b) {
  int ra = root(a), rb = root(b);
  if (ra == rb) return;
  if (rb < ra) std::swap(ra, rb);
  parent_[static_cast<std::size_t>(rb)] = ra;
  std::vector<int>& into = members_[static_cast<std::size_t>(ra)];
  std::vector<int>& from = members_[static_cast<std::size_t>(rb)];
  into.insert(into.end(), from.begin(), from.end());
  from.clear();
  area_sum_[ra] = room_area(ra) + room_area(rb);
  area_sum_.erase(rb);
  const auto hull_a = hulls_.find(ra), hull_b = hulls_.find(rb);
  if (hull_a != hulls_.end() && hull_b != hulls_.end()) {
    std::vector<Point2> points = hull_a->second;
    points.insert(points.end(), hull_b->second.begin(), hull_b->second.end());
    hull_a->second = hull_of(points);
  } else if (hull_a != hulls_.end()) {
    hulls_.erase(hull_a);  // computed again from the members when asked
  }
  hulls_.erase(rb);
}

bool RoomGraph::separates(std::size_t k) {
  const Side& s = sides_[k];
  return s.left >= 0 && root(s.left) != root(s.right);
}

double RoomGraph::room_area(int r) {
  const auto it = area_sum_.find(r);
  return it != area_sum_.end() ? it->second : areas_[static_cast<std::size_t>(r)];
}

RoomGraph::RoomMeasures& RoomGraph::measures(int r) {
  RoomMeasures& m = room_measures_[static_cast<std::size_t>(r)];
  if (m.pieces == members(r).size()) return m;
  m.pieces = members(r).size();
  m.sides.clear();
  for (const int member : members(r)) {
    const std::vector<std::size_t>& own = piece_sides_[static_cast<std::size_t>(member)];
    m.sides.insert(m.sides.end(), own.begin(), own.end());
  }
  // Ascending, so that sums over them add in the order of the cuts, as they always did.
  std::sort(m.sides.begin(), m.sides.end());
  m.sides.erase(std::unique(m.sides.begin(), m.sides.end()), m.sides.end());
  m.hull_area.reset();
  m.perimeter = 0.0;
  for (const int member : members(r)) m.perimeter += perimeters_[static_cast<std::size_t>(member)];
  m.open = 0.0;
  for (const std::size_t k : m.sides) {
    const Side& s = sides_[k];
    const bool inside = root(s.left) == r && root(s.right) == r;
    if (inside) m.perimeter -= 2.0 * s.length;
    else m.open += s.length;  // a cut beside r not inside it separates r from another room
  }
  return m;
}

const std::vector<std::size_t>& RoomGraph::room_sides(int r) { return measures(r).sides; }

double RoomGraph::room_perimeter(int r) { return measures(r).perimeter; }

double RoomGraph::room_thickness(int r) {
  const double length = room_perimeter(r);
  return length > 0.0 ? 2.0 * room_area(r) / length : 0.0;
}

const std::vector<Point2>& RoomGraph::room_hull(int r) {
  const auto found = hulls_.find(r);
  if (found != hulls_.end()) return found->second;
  std::vector<Point2> points;
  for (const int member : members(r)) {
    const Ring& outer = set_.pieces[static_cast<std::size_t>(member)].outer;
    points.insert(points.end(), outer.begin(), outer.end());
  }
  return hulls_[r] = hull_of(points);
}

double RoomGraph::convex_hull_area(const std::vector<int>& rooms) {
  if (rooms.size() == 1) {
    std::optional<double>& known = measures(rooms[0]).hull_area;
    if (!known) {
      const std::vector<Point2>& hull = room_hull(rooms[0]);
      known = hull.size() < 3 ? 0.0 : std::abs(signed_area(hull)) * resolution_ * resolution_;
    }
    return *known;
  }
  std::vector<Point2> points;
  for (const int r : rooms) {
    const std::vector<Point2>& hull = room_hull(r);
    points.insert(points.end(), hull.begin(), hull.end());
  }
  if (points.size() < 3) return 0.0;
  return std::abs(signed_area(hull_of(points))) * resolution_ * resolution_;
}

double RoomGraph::elongation(const std::vector<int>& rooms) {
  Moments t;
  for (const int r : rooms)
    for (const int member : members(r)) {
      const Moments& m = moments_[static_cast<std::size_t>(member)];
      t.a += m.a, t.x += m.x, t.y += m.y, t.xx += m.xx, t.xy += m.xy, t.yy += m.yy;
    }
  if (t.a <= 0.0) return 1.0;
  const double cx = t.x / t.a, cy = t.y / t.a;
  const double sxx = t.xx / t.a - cx * cx, syy = t.yy / t.a - cy * cy, sxy = t.xy / t.a - cx * cy;
  const double mean = (sxx + syy) / 2.0, spread = std::sqrt(std::max(0.0, (sxx - syy) * (sxx - syy) / 4.0 + sxy * sxy));
  const double small = mean - spread, large = mean + spread;
  return small > 0.0 ? std::sqrt(large / small) : 100.0;
}

double RoomGraph::shared_cut_length(int r, int s) {
  if (s < 0) return measures(r).open;
  double length = 0.0;
  for (const std::size_t k : room_sides(r)) {
    const Side& side = sides_[k];
    const int a = root(side.left), b = root(side.right);
    if (a == b) continue;
    if ((a == r && b == s) || (b == r && a == s)) length += side.length;
  }
  return length;
}

double RoomGraph::chord(int r, const Point2& p, const Point2& u) {
  std::vector<std::pair<double, double>>& spans = chord_spans_;
  std::vector<double>& ts = chord_ts_;
  spans.clear();
  const Point2 n{-u.y, u.x};
  for (const int member : members(r)) {
    const std::size_t i = static_cast<std::size_t>(member);
    const Box& b = boxes_[i];
    const double s[4] = {(b.x0 - p.x) * n.x + (b.y0 - p.y) * n.y, (b.x1 - p.x) * n.x + (b.y0 - p.y) * n.y,
                         (b.x0 - p.x) * n.x + (b.y1 - p.y) * n.y, (b.x1 - p.x) * n.x + (b.y1 - p.y) * n.y};
    if (std::min({s[0], s[1], s[2], s[3]}) > 0.0 || std::max({s[0], s[1], s[2], s[3]}) <= 0.0) continue;
    ts.clear();
    const PolygonWithHoles& piece = set_.pieces[i];
    const std::vector<std::vector<Box>>& chunks = chunks_[i];
    add_crossings(piece.outer, chunks[0], p, u, ts);
    for (std::size_t h = 0; h < piece.holes.size(); ++h) add_crossings(piece.holes[h], chunks[h + 1], p, u, ts);
    std::sort(ts.begin(), ts.end());
    for (std::size_t k = 0; k + 1 < ts.size(); k += 2) spans.emplace_back(ts[k], ts[k + 1]);
  }
  std::sort(spans.begin(), spans.end());
  // Join touching spans (pieces of one room share their cuts), keep the one around t = 0.
  const double touch = 1e-9;
  double lo = 0.0, hi = 0.0;
  bool open = false;
  for (const auto& [a, b] : spans) {
    if (open && a <= hi + touch) {
      hi = std::max(hi, b);
      continue;
    }
    if (open && lo <= 0.0 && hi >= 0.0) return hi - lo;
    lo = a;
    hi = b;
    open = true;
  }
  if (open && lo <= 0.0 && hi >= 0.0) return hi - lo;
  return 0.0;
}

double RoomGraph::side_width(std::size_t k, int r, bool left, double depth_m) {
  SideWidth& known = side_widths_[2 * k + (left ? 0 : 1)];
  const std::size_t pieces = members(r).size();
  if (known.room == r && known.pieces == pieces && known.depth == depth_m) return known.width;
  known = {r, pieces, depth_m, measure_side_width(k, r, left, depth_m)};
  return known.width;
}

double RoomGraph::measure_side_width(std::size_t k, int r, bool left, double depth_m) {
  const auto [u, n, mid] = cut_frame(set_.cuts[k], left);
  const double depth = std::max(depth_m / resolution_, 1.0);
  const double widest = sampled_side_width(depth, kInfinity, [&](double d) -> std::optional<double> {
    const double w = chord(r, {mid.x + d * n.x, mid.y + d * n.y}, u);
    if (w <= 0.0) return std::nullopt;  // past the room's wall
    return w;
  });
  return widest * resolution_;
}

double RoomGraph::side_depth(std::size_t k, int r, bool left) {
  SideWidth& known = side_depths_[2 * k + (left ? 0 : 1)];
  const std::size_t pieces = members(r).size();
  if (known.room == r && known.pieces == pieces) return known.width;
  const auto [u, n, mid] = cut_frame(set_.cuts[k], left);
  known = {r, pieces, 0.0, chord(r, {mid.x + 0.5 * n.x, mid.y + 0.5 * n.y}, n) * resolution_};
  return known.width;
}

PieceSet RoomGraph::result() {
  // Rooms in the order of their first piece; the cuts between two rooms in input order.
  std::vector<int> order;
  std::vector<std::vector<int>> members(parent_.size());
  for (std::size_t i = 0; i < parent_.size(); ++i) {
    const int r = root(static_cast<int>(i));
    if (members[static_cast<std::size_t>(r)].empty()) order.push_back(r);
    members[static_cast<std::size_t>(r)].push_back(static_cast<int>(i));
  }
  // Each merged room's polygon is the union of its pieces. If that fails (pieces that do not
  // meet along whole edges, which DuDe's never do), the room stays as its pieces.
  std::map<int, PolygonWithHoles> unions;
  std::set<int> broken;
  for (const int r : order) {
    const std::vector<int>& m = members[static_cast<std::size_t>(r)];
    if (m.size() < 2) continue;
    std::vector<PolygonWithHoles> parts;
    for (const int i : m) parts.push_back(set_.pieces[static_cast<std::size_t>(i)]);
    try {
      unions[r] = union_of_pieces(parts);
    } catch (const Error&) {
      broken.insert(r);
    }
  }
  PieceSet out;
  std::set<std::pair<double, double>> ends;  // end points of the cuts that stay
  for (std::size_t k = 0; k < sides_.size(); ++k) {
    const Side& s = sides_[k];
    if (s.left < 0 || (root(s.left) == root(s.right) && !broken.count(root(s.left)))) continue;
    out.add_cut(set_.cuts[k], s.rule);
    ends.insert({set_.cuts[k].a.x, set_.cuts[k].a.y});
    ends.insert({set_.cuts[k].b.x, set_.cuts[k].b.y});
  }
  for (const int r : order) {
    const std::vector<int>& m = members[static_cast<std::size_t>(r)];
    if (m.size() == 1 || broken.count(r)) {
      for (const int i : m) out.pieces.push_back(set_.pieces[static_cast<std::size_t>(i)]);
      continue;
    }
    // Where a removed cut met a straight wall the union goes straight on; such vertices are
    // dropped unless a remaining cut ends there (the cut must stay an edge of both rooms).
    PolygonWithHoles room = unions.at(r);
    auto tidy = [&](Ring& ring) {
      Ring kept = remove_collinear_vertices(ring, [&](const Point2& p) { return ends.count({p.x, p.y}) > 0; });
      if (kept.size() >= 3) ring = std::move(kept);
    };
    tidy(room.outer);
    for (Ring& hole : room.holes) tidy(hole);
    out.pieces.push_back(std::move(room));
  }
  return out;
}

}  // namespace topocut
