#include "exploration/simulated_world.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "exploration/seeded_random.h"
#include "topocut/core/error.h"

namespace topocut {

namespace {

constexpr unsigned char kOn = 255;
// Metres of floor kept in front of furniture and around tables: a way past for the robot.
constexpr double kPassage = 0.8;

// The random streams of the stages (SeededRandom's second argument).
enum Stream : std::uint32_t { kWallStream = 1, kDoorStream, kWindowStream, kFurnitureStream, kClutterStream, kOutsideStream };

// The world as it is being built, in the frame: every cell is floor, solid or exterior; glass
// (windows) was solid, obstacles lie on the exterior.
struct Draft {
  double resolution = 0.05;
  cv::Mat floor, solid, exterior, glass, obstacles;  // CV_8UC1, 0 / 255
  cv::Mat rooms;                                     // CV_32SC1
  cv::Mat keep_clear;                                // CV_8UC1: no furniture or clutter here (around doors)
};

int cells(double metres, double resolution) { return static_cast<int>(std::lround(metres / resolution)); }

// Distance in cells from every cell to the nearest non-zero cell of mask (large where mask is empty).
cv::Mat distance_to(const cv::Mat& mask) {
  cv::Mat distance;
  cv::distanceTransform(mask == 0, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  return distance;
}

// The free components of the plan that belong to a building: those not touching the image border,
// and those that do but lie mostly in people's rooms (a plan cropped tight). A free background
// around the building is exterior.
cv::Mat interior_free(const OccupancyGrid& plan, const cv::Mat& rooms) {
  const cv::Mat free = plan.cells == kFree;
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(free, labels, stats, centroids, 8, CV_32S);
  std::vector<int> in_rooms(static_cast<std::size_t>(n), 0);
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      if (rooms.at<int>(r, c) > 0) ++in_rooms[static_cast<std::size_t>(labels.at<int>(r, c))];
  std::vector<unsigned char> keep(static_cast<std::size_t>(n), 0);
  for (int i = 1; i < n; ++i) {
    const int x = stats.at<int>(i, cv::CC_STAT_LEFT), y = stats.at<int>(i, cv::CC_STAT_TOP);
    const int w = stats.at<int>(i, cv::CC_STAT_WIDTH), h = stats.at<int>(i, cv::CC_STAT_HEIGHT);
    const bool touches_border = x == 0 || y == 0 || x + w == labels.cols || y + h == labels.rows;
    keep[static_cast<std::size_t>(i)] = !touches_border || 2 * in_rooms[static_cast<std::size_t>(i)] >= stats.at<int>(i, cv::CC_STAT_AREA);
  }
  cv::Mat interior(labels.size(), CV_8UC1);
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      interior.at<unsigned char>(r, c) = keep[static_cast<std::size_t>(labels.at<int>(r, c))] ? kOn : 0;
  return interior;
}

// image placed into a frame of box's size at box (box in image's coordinates, may reach beyond it),
// fill elsewhere.
cv::Mat framed(const cv::Mat& image, const cv::Rect& box, const cv::Scalar& fill) {
  cv::Mat out(box.size(), image.type(), fill);
  const cv::Rect common = box & cv::Rect(0, 0, image.cols, image.rows);
  if (!common.empty()) image(common).copyTo(out(common - box.tl()));
  return out;
}

// The exterior: space reached from the frame's border through cells farther than outer_wall from
// the floor. What lies closer is wall, whatever the plan drew there: black, the grey of unknown space
// (r2v's outside, walls drawn grey in some Bormann maps) or a free background.
cv::Mat find_exterior(const cv::Mat& floor, int outer_wall_cells) {
  const cv::Mat open = distance_to(floor) > outer_wall_cells;
  cv::Mat labels;
  const int n = cv::connectedComponents(open, labels, 4, CV_32S);
  std::vector<unsigned char> outside(static_cast<std::size_t>(n), 0);
  auto mark = [&](int r, int c) {
    const int l = labels.at<int>(r, c);
    if (l > 0) outside[static_cast<std::size_t>(l)] = 1;
  };
  for (int c = 0; c < labels.cols; ++c) mark(0, c), mark(labels.rows - 1, c);
  for (int r = 0; r < labels.rows; ++r) mark(r, 0), mark(r, labels.cols - 1);
  cv::Mat exterior(labels.size(), CV_8UC1);
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      exterior.at<unsigned char>(r, c) = outside[static_cast<std::size_t>(labels.at<int>(r, c))] ? kOn : 0;
  return exterior;
}

// Thickens the walls by one cell (floor next to a solid cell becomes solid) or thins them (a solid
// cell next to the floor becomes floor where the wall is at least three cells thick; the exterior
// counts as wall, so outer walls only lose their inner face).
void change_walls(Draft& d, int change) {
  const cv::Mat kernel = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
  for (int i = 0; i < std::abs(change); ++i) {
    if (change > 0) {
      cv::Mat grown;
      cv::dilate(d.solid, grown, kernel);
      const cv::Mat added = grown & d.floor;
      d.solid |= added;
      d.floor &= ~added;
    } else {
      cv::Mat depth, deepest, near_floor;
      cv::distanceTransform(d.solid | d.exterior, depth, cv::DIST_C, 3);
      cv::dilate(depth, deepest, kernel);
      cv::dilate(d.floor, near_floor, cv::getStructuringElement(cv::MORPH_CROSS, {3, 3}));
      const cv::Mat removed = d.solid & (depth == 1.0f) & (deepest >= 2.0f) & near_floor;
      d.solid &= ~removed;
      d.floor |= removed;
    }
  }
}

struct Door {
  std::vector<int> cells;  // row * width + column
};

// The doors: components of floor in no room that touch two rooms or more and are at most
// max_width across (their box's diagonal).
std::vector<Door> find_doors(const Draft& d, double max_width) {
  const cv::Mat unroomed = d.floor & (d.rooms == 0);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(unroomed, labels, stats, centroids, 8, CV_32S);
  std::vector<std::set<int>> touched(static_cast<std::size_t>(n));
  std::vector<Door> parts(static_cast<std::size_t>(n));
  const int w = labels.cols, h = labels.rows;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) {
      const int l = labels.at<int>(r, c);
      if (l == 0) continue;
      parts[static_cast<std::size_t>(l)].cells.push_back(r * w + c);
      for (int dr = -1; dr <= 1; ++dr)
        for (int dc = -1; dc <= 1; ++dc) {
          const int nr = r + dr, nc = c + dc;
          if (nr < 0 || nc < 0 || nr >= h || nc >= w) continue;
          const int room = d.rooms.at<int>(nr, nc);
          if (room > 0 && d.floor.at<unsigned char>(nr, nc)) touched[static_cast<std::size_t>(l)].insert(room);
        }
    }
  std::vector<Door> doors;
  for (int i = 1; i < n; ++i) {
    const double across = std::hypot(stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT)) * d.resolution;
    if (touched[static_cast<std::size_t>(i)].size() >= 2 && across <= max_width) doors.push_back(std::move(parts[static_cast<std::size_t>(i)]));
  }
  // In raster order of their first cells: OpenCV's parallel labelling numbers components by how
  // many threads it ran on, and the doors' draws must not depend on that.
  std::sort(doors.begin(), doors.end(), [](const Door& a, const Door& b) { return a.cells.front() < b.cells.front(); });
  return doors;
}

// Closes each door with the given probability: its cells and their neighbours become solid (a door
// leaf no diagonal beam slips through). Every door is kept clear of furniture. Returns the closed count.
int close_doors(Draft& d, const std::vector<Door>& doors, const SimulatedMapOptions& o, SeededRandom& rng) {
  cv::Mat all = cv::Mat::zeros(d.floor.size(), CV_8UC1), closed = all.clone();
  int count = 0;
  for (const Door& door : doors) {
    const bool close = rng.chance(o.closed_doors);
    for (const int i : door.cells) {
      all.data[i] = kOn;
      if (close) closed.data[i] = kOn;
    }
    count += close ? 1 : 0;
  }
  cv::dilate(closed, closed, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
  closed &= ~d.exterior;
  d.solid |= closed;
  d.floor &= ~closed;
  const int clearance = std::max(1, cells(o.door_clearance, d.resolution));
  cv::dilate(all, d.keep_clear, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * clearance + 1, 2 * clearance + 1}));
  return count;
}

// Cuts windows into the outer wall: spans of 0.8 to 2.4 m centred on cells of the wall's outer
// face, through the wall's thickness, until their share of the face is reached. Returns their count.
int cut_windows(Draft& d, const SimulatedMapOptions& o, SeededRandom& rng) {
  d.glass = cv::Mat::zeros(d.floor.size(), CV_8UC1);
  if (o.windows <= 0.0 || o.outside <= 0.0) return 0;
  const int wall = std::max(1, cells(o.outer_wall, d.resolution));
  const cv::Mat to_floor = distance_to(d.floor), to_exterior = distance_to(d.exterior);
  std::vector<int> face;
  const int w = d.floor.cols, h = d.floor.rows;
  for (int r = 1; r + 1 < h; ++r)
    for (int c = 1; c + 1 < w; ++c) {
      if (!d.solid.at<unsigned char>(r, c) || to_floor.at<float>(r, c) > wall + 1) continue;
      if (d.exterior.at<unsigned char>(r - 1, c) || d.exterior.at<unsigned char>(r + 1, c) ||
          d.exterior.at<unsigned char>(r, c - 1) || d.exterior.at<unsigned char>(r, c + 1))
        face.push_back(r * w + c);
    }
  if (face.empty()) return 0;
  const double wanted = o.windows * static_cast<double>(face.size()) * d.resolution;  // metres of window
  double opened = 0.0;
  std::vector<std::pair<cv::Point, double>> placed;  // centre, half length in cells
  for (int attempt = 0; attempt < 400 && opened < wanted; ++attempt) {
    const double length = rng.uniform(0.8, 2.4);
    const int i = face[static_cast<std::size_t>(rng.below(face.size()))];
    const cv::Point centre(i % w, i / w);
    const double half = 0.5 * length / d.resolution;
    const double gap = 1.0 / d.resolution;
    const bool crowded = std::any_of(placed.begin(), placed.end(), [&](const auto& p) {
      return cv::norm(p.first - centre) < p.second + half + gap;
    });
    if (crowded) continue;
    const int reach = static_cast<int>(std::ceil(half));
    for (int r = std::max(0, centre.y - reach); r <= std::min(h - 1, centre.y + reach); ++r)
      for (int c = std::max(0, centre.x - reach); c <= std::min(w - 1, centre.x + reach); ++c) {
        if (std::hypot(c - centre.x, r - centre.y) > half || !d.solid.at<unsigned char>(r, c)) continue;
        if (to_floor.at<float>(r, c) > wall + 2 || to_exterior.at<float>(r, c) > wall + 2) continue;
        d.glass.at<unsigned char>(r, c) = kOn;
      }
    placed.push_back({centre, half});
    opened += length;
  }
  d.solid &= ~d.glass;
  return static_cast<int>(placed.size());
}

// Where furniture may go: cells allowed in one room (of rooms' label room, or in no room), or
// anywhere allowed when rooms is empty.
struct Room {
  const cv::Mat& allowed;  // CV_8UC1
  const cv::Mat& rooms;    // CV_32SC1 or empty
  int room = 0;
};

// A rectangle of w x h cells with top-left corner at (x, y) may take furniture: every cell allowed.
bool fits(const Room& where, int x, int y, int w, int h) {
  const cv::Mat& allowed = where.allowed;
  if (x < 0 || y < 0 || x + w > allowed.cols || y + h > allowed.rows) return false;
  for (int r = y; r < y + h; ++r) {
    const unsigned char* row = allowed.ptr<unsigned char>(r);
    const int* label = where.rooms.empty() ? nullptr : where.rooms.ptr<int>(r);
    for (int c = x; c < x + w; ++c)
      if (!row[c] || (label && label[c] != 0 && label[c] != where.room)) return false;
  }
  return true;
}

// Every cell of box lies in the frame and on the floor.
bool all_floor(const Draft& d, const cv::Rect& box) {
  if (box.x < 0 || box.y < 0 || box.x + box.width > d.floor.cols || box.y + box.height > d.floor.rows) return false;
  return cv::countNonZero(d.floor(box)) == box.area();
}

void set_solid(Draft& d, cv::Mat& allowed, const cv::Rect& box) {
  d.solid(box).setTo(kOn);
  d.floor(box).setTo(0);
  allowed(box).setTo(0);
}

// The floor cells of every room, in row-major order, by room label.
std::map<int, std::vector<int>> room_cells(const Draft& d) {
  std::map<int, std::vector<int>> out;
  for (int r = 0; r < d.rooms.rows; ++r)
    for (int c = 0; c < d.rooms.cols; ++c) {
      const int room = d.rooms.at<int>(r, c);
      if (room > 0 && d.floor.at<unsigned char>(r, c)) out[room].push_back(r * d.rooms.cols + c);
    }
  return out;
}

// Beds, sofas, shelves, wardrobes, desks and cabinets (metres, long side first), each pushed from a
// random place in its room against a wall, until furniture covers its share of the room's floor.
void place_furniture(Draft& d, const SimulatedMapOptions& o, SeededRandom& rng) {
  if (o.furniture <= 0.0) return;
  static constexpr std::array<std::array<double, 2>, 6> kPieces{{{2.0, 1.4}, {2.0, 0.9}, {1.2, 0.4}, {1.0, 0.6}, {1.4, 0.7}, {0.8, 0.45}}};
  const int width = d.floor.cols;
  const int passage = std::max(1, cells(kPassage, d.resolution));
  cv::Mat allowed = d.floor & ~d.keep_clear;
  for (const auto& [room, room_floor] : room_cells(d)) {
    const Room where{allowed, d.rooms, room};
    const double wanted = o.furniture * static_cast<double>(room_floor.size());
    double covered = 0.0;
    for (int attempt = 0; attempt < 60 && covered < wanted; ++attempt) {
      const auto& piece = kPieces[static_cast<std::size_t>(rng.below(kPieces.size()))];
      const bool along_x = rng.chance(0.5);
      const int w = std::max(1, cells(piece[along_x ? 0 : 1], d.resolution));
      const int h = std::max(1, cells(piece[along_x ? 1 : 0], d.resolution));
      if (covered + w * h > wanted * 1.5) continue;
      const int centre = room_floor[static_cast<std::size_t>(rng.below(room_floor.size()))];
      int x = centre % width - w / 2, y = centre / width - h / 2;
      if (!fits(where, x, y, w, h)) continue;
      // Pushed across its long side, toward one of the two walls it faces.
      const int sign = rng.chance(0.5) ? 1 : -1;
      const int dx = along_x ? 0 : sign, dy = along_x ? sign : 0;
      while (fits(where, x + dx, y + dy, w, h)) x += dx, y += dy;
      // Its back against a wall (not stopped by a door's clearance or another room), and floor in
      // front of it, so that no piece closes a passage inside a room.
      const cv::Rect back = dy > 0 ? cv::Rect(x, y + h, w, 1)
                            : dy < 0 ? cv::Rect(x, y - 1, w, 1)
                            : dx > 0 ? cv::Rect(x + w, y, 1, h)
                                     : cv::Rect(x - 1, y, 1, h);
      const cv::Rect front = dy > 0 ? cv::Rect(x, y - passage, w, passage)
                             : dy < 0 ? cv::Rect(x, y + h, w, passage)
                             : dx > 0 ? cv::Rect(x - passage, y, passage, h)
                                      : cv::Rect(x + w, y, passage, h);
      const cv::Rect frame(0, 0, d.floor.cols, d.floor.rows);
      if ((back & frame) != back || 2 * cv::countNonZero(d.solid(back)) < back.area() || !all_floor(d, front)) continue;
      set_solid(d, allowed, cv::Rect(x, y, w, h));
      covered += w * h;
    }
  }
}

// What a lidar a few centimetres above the floor sees of a table and its chairs: legs, one cell each.
bool place_table(Draft& d, cv::Mat& allowed, const Room& where, int cx, int cy, SeededRandom& rng) {
  const int w = cells(rng.uniform(0.8, 1.6), d.resolution), h = cells(rng.uniform(0.6, 0.9), d.resolution);
  const int x = cx - w / 2, y = cy - h / 2;
  // The chairs' room around the table must be floor too.
  const int chair = cells(0.4, d.resolution), gap = cells(0.1, d.resolution);
  const int margin = chair + gap;
  if (!fits(where, x - margin, y - margin, w + 2 * margin, h + 2 * margin)) return false;
  const int passage = cells(kPassage, d.resolution);
  if (!all_floor(d, cv::Rect(x - margin - passage, y - margin - passage, w + 2 * (margin + passage), h + 2 * (margin + passage))))
    return false;
  std::vector<cv::Point> legs{{x, y}, {x + w - 1, y}, {x, y + h - 1}, {x + w - 1, y + h - 1}};
  const std::array<cv::Point, 4> chair_corners{cv::Point(x + w / 2 - chair / 2, y - margin), cv::Point(x + w / 2 - chair / 2, y + h + gap),
                                               cv::Point(x - margin, y + h / 2 - chair / 2), cv::Point(x + w + gap, y + h / 2 - chair / 2)};
  for (const cv::Point& corner : chair_corners) {
    if (!rng.chance(0.7)) continue;
    for (const cv::Point& leg : {corner, corner + cv::Point(chair - 1, 0), corner + cv::Point(0, chair - 1), corner + cv::Point(chair - 1, chair - 1)})
      legs.push_back(leg);
  }
  for (const cv::Point& leg : legs) set_solid(d, allowed, cv::Rect(leg.x, leg.y, 1, 1));
  return true;
}

// Small things on the floor: tables with chairs (legs), bins and boxes, `clutter` per 10 m².
void place_clutter(Draft& d, const SimulatedMapOptions& o, SeededRandom& rng) {
  if (o.clutter <= 0.0) return;
  const int width = d.floor.cols;
  const double cell_area = d.resolution * d.resolution;
  cv::Mat allowed = d.floor & ~d.keep_clear;
  for (const auto& [room, room_floor] : room_cells(d)) {
    const Room where{allowed, d.rooms, room};
    const double expected = o.clutter * static_cast<double>(room_floor.size()) * cell_area / 10.0;
    // The fraction of a thing is placed with its probability, so small rooms get some too.
    int count = static_cast<int>(expected);
    if (rng.chance(expected - count)) ++count;
    for (int k = 0, attempt = 0; k < count && attempt < 10 * count; ++attempt) {
      const int at = room_floor[static_cast<std::size_t>(rng.below(room_floor.size()))];
      const int cx = at % width, cy = at / width;
      const double kind = rng.uniform();
      if (kind < 0.4) {
        if (place_table(d, allowed, where, cx, cy, rng)) ++k;
        continue;
      }
      const int side = kind < 0.7 ? std::max(1, cells(rng.uniform(0.05, 0.15), d.resolution))   // bins, posts
                                  : std::max(1, cells(rng.uniform(0.25, 0.5), d.resolution));   // boxes
      if (!fits(where, cx - side / 2, cy - side / 2, side, side)) continue;
      set_solid(d, allowed, cv::Rect(cx - side / 2, cy - side / 2, side, side));
      ++k;
    }
  }
}

// Trees, posts and cars on the open ground, at least 0.5 m (cars 1 m) from the building.
void place_outside_obstacles(Draft& d, const SimulatedMapOptions& o, SeededRandom& rng) {
  d.obstacles = cv::Mat::zeros(d.floor.size(), CV_8UC1);
  if (o.outside <= 0.0 || o.outside_obstacles <= 0.0) return;
  const cv::Mat from_building = distance_to(~d.exterior);
  const double near = 0.5 / d.resolution;
  std::vector<int> ground;
  for (int r = 0; r < d.exterior.rows; ++r)
    for (int c = 0; c < d.exterior.cols; ++c)
      if (from_building.at<float>(r, c) >= near) ground.push_back(r * d.exterior.cols + c);
  if (ground.empty()) return;
  const double area = static_cast<double>(ground.size()) * d.resolution * d.resolution;
  const int count = static_cast<int>(std::lround(o.outside_obstacles * area / 100.0));
  // Cars keep 1 m from the building, everything else `near`.
  cv::Mat allowed = from_building >= near, car_allowed = from_building >= 1.0 / d.resolution;
  const cv::Mat no_rooms;
  for (int k = 0; k < count; ++k) {
    const int at = ground[static_cast<std::size_t>(rng.below(ground.size()))];
    const cv::Point centre(at % d.exterior.cols, at / d.exterior.cols);
    const double kind = rng.uniform();
    cv::Rect box;
    cv::Mat shape;  // CV_8UC1 of box's size
    if (kind < 0.2) {  // a car, 4.4 x 1.8 m, either way round
      const bool along_x = rng.chance(0.5);
      const int w = cells(along_x ? 4.4 : 1.8, d.resolution), h = cells(along_x ? 1.8 : 4.4, d.resolution);
      box = cv::Rect(centre.x - w / 2, centre.y - h / 2, w, h);
      if (!fits(Room{car_allowed, no_rooms, 0}, box.x, box.y, w, h)) continue;
      shape = cv::Mat(box.size(), CV_8UC1, cv::Scalar(kOn));
    } else {
      // Trees and bushes, or posts.
      const double radius = kind < 0.8 ? rng.uniform(0.15, 0.6) : rng.uniform(0.05, 0.1);
      const int r = std::max(0, cells(radius, d.resolution));
      box = cv::Rect(centre.x - r, centre.y - r, 2 * r + 1, 2 * r + 1);
      if (!fits(Room{allowed, no_rooms, 0}, box.x, box.y, box.width, box.height)) continue;
      shape = cv::Mat::zeros(box.size(), CV_8UC1);
      cv::circle(shape, {r, r}, r, cv::Scalar(kOn), cv::FILLED);
    }
    d.obstacles(box) |= shape;
    allowed(box).setTo(0, shape);
    car_allowed(box).setTo(0, shape);
  }
}

}  // namespace

SimulatedWorld build_simulated_world(const OccupancyGrid& plan, const cv::Mat& plan_rooms, const SimulatedMapOptions& o,
                                     std::uint32_t seed) {
  const double res = plan.resolution;
  const cv::Mat inside = interior_free(plan, plan_rooms);
  if (cv::countNonZero(inside & (plan_rooms > 0)) == 0)
    throw Error("the plan has no free cell inside a building that lies in one of people's rooms");
  // The frame: the building with the open ground (at least 0.5 m) and its outer wall around it.
  const int margin = static_cast<int>(std::ceil((std::max(o.outside, 0.5) + o.outer_wall) / res));
  cv::Rect box = cv::boundingRect(inside);
  box = cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin);

  Draft d;
  d.resolution = res;
  d.floor = framed(inside, box, cv::Scalar(0));
  d.rooms = framed(plan_rooms, box, cv::Scalar(0));
  d.exterior = find_exterior(d.floor, std::max(1, cells(o.outer_wall, res)));
  d.solid = ~(d.floor | d.exterior);

  SimulatedWorld out;
  SeededRandom wall_rng(seed, kWallStream);
  out.wall_change = o.wall_change > 0 ? static_cast<int>(wall_rng.below(2 * o.wall_change + 1)) - o.wall_change : 0;
  // Doors are found on the floor as drawn: thinned walls would join every door's cells along them.
  const std::vector<Door> doors = find_doors(d, o.max_door_width);
  change_walls(d, out.wall_change);
  SeededRandom door_rng(seed, kDoorStream);
  out.doors = static_cast<int>(doors.size());
  out.closed_doors = close_doors(d, doors, o, door_rng);
  SeededRandom window_rng(seed, kWindowStream);
  out.windows = cut_windows(d, o, window_rng);
  SeededRandom furniture_rng(seed, kFurnitureStream), clutter_rng(seed, kClutterStream), outside_rng(seed, kOutsideStream);
  place_furniture(d, o, furniture_rng);
  place_clutter(d, o, clutter_rng);
  place_outside_obstacles(d, o, outside_rng);

  out.world.resolution = res;
  out.world.origin = {plan.origin.x + box.x * res, plan.origin.y + (plan.height() - box.y - box.height) * res};
  const cv::Mat ground = o.outside > 0.0 ? (d.exterior & ~d.obstacles) : cv::Mat::zeros(d.floor.size(), CV_8UC1);
  const cv::Mat passable = d.floor | d.glass | ground;
  out.world.cells = cv::Mat(d.floor.size(), CV_8UC1, cv::Scalar(kOccupied));
  out.world.cells.setTo(kFree, passable);
  // The robot's centre stays robot_radius from every surface (half a cell beyond the cell centres).
  out.drivable = d.floor & (distance_to(~d.floor) >= o.robot_radius / res + 0.5);
  out.exterior = d.exterior;
  out.glass = d.glass;
  out.rooms = d.rooms;
  out.offset = -box.tl();
  return out;
}

}  // namespace topocut
