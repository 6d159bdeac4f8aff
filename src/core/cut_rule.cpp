#include "topocut/core/cut_rule.h"

namespace topocut {

std::string to_string(CutRule rule) {
  switch (rule) {
    case CutRule::kDoor: return "door";
    case CutRule::kWallOpening: return "wall-opening";
    case CutRule::kIslandCut: return "island-cut";
    case CutRule::kWallLine: return "wall-line";
    case CutRule::kDecomposition: return "decomposition";
  }
  return "decomposition";
}

}  // namespace topocut
