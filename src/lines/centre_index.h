#pragma once
// Internal to SMF's merge phase: the centres of gravity of the clusters being merged, asked for the
// two nearest centres of a cluster and for the clusters a moved centre comes within reach of, in
// about log n steps instead of a pass over every cluster (the pass made the merge phase grow with
// the square of a scan's beams). A 2-d tree whose leaves take the moved centres (a fused centre
// lies between two old ones, so the splits stay sensible); it is rebuilt once the moved or removed
// centres since the last build outnumber half the live ones.
#include <array>
#include <vector>

#include "topocut/core/geometry.h"

namespace topocut::detail {

class CentreIndex {
 public:
  // Centres by id (0..n-1), all live.
  explicit CentreIndex(std::vector<Point2> centres);

  // The two live centres nearest to id's by distance(), ties to the lower id (-1 where fewer exist).
  std::array<int, 2> nearest_two(int id) const;
  // Records that a centre closer than reach to id's changes id's two nearest (reach: the distance of
  // the second; -infinity: never report id).
  void set_reach(int id, double reach);
  void remove(int id);
  void move(int id, const Point2& centre);
  // Appends the live ids c with distance(centre of c, p) <= reach of c.
  void within_reach(const Point2& p, std::vector<int>& out) const;

 private:
  struct Node {
    std::vector<int> items;       // a leaf's ids (moved ones stay listed, skipped by position)
    int left = -1, right = -1;    // children; -1 for a leaf
    int parent = -1;
    bool by_x = true;             // the split: left below `split` on x (or y)
    double split = 0;
    double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
    double max_reach = 0;         // an upper bound of its items' reach
    int live = 0;                 // listed live items below: a node without any is never searched
  };
  int build(std::vector<int>::iterator first, std::vector<int>::iterator last, int parent);
  void rebuild();
  void insert(int id);
  void unlist(int id);
  double box_distance(const Node& node, const Point2& p) const;  // squared
  void offer(int id, int candidate, std::array<int, 2>& best, std::array<double, 2>& best_d) const;
  bool listed(int id, int leaf) const { return live_[id] && leaf_of_[id] == leaf; }

  std::vector<Point2> centre_;
  std::vector<double> reach_;
  std::vector<char> live_;
  std::vector<int> leaf_of_;
  std::vector<Node> nodes_;
  int live_count_ = 0, changes_ = 0;
};

}  // namespace topocut::detail
