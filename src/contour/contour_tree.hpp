// The contours of one mountain as a tree: a contour's parent is the next lower contour that
// encloses it; the outermost contour is the root. Levels count from the seed (level 0): +k inward
// (up), -k outward (down).
#pragma once

#include <vector>

#include "contour/geometry.hpp"

namespace sansui::contour {

struct ContourNode {
  Ring ring;                  ///< counter-clockwise, metres
  int level = 0;              ///< 0 seed, +k inward, -k outward
  double elevation_m = 0.0;   ///< [Units: m]
  int parent = -1;            ///< index of the enclosing lower contour, -1 for a root
  std::vector<int> children;  ///< contours directly inside, one level up
};

struct ContourTree {
  std::vector<ContourNode> nodes;
  int seed = 0;  ///< index of the seed contour

  std::vector<int> roots() const {
    std::vector<int> out;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i].parent < 0) out.push_back(static_cast<int>(i));
    return out;
  }
  /// Contours without children: the summit contours.
  std::vector<int> summits() const {
    std::vector<int> out;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i].children.empty()) out.push_back(static_cast<int>(i));
    return out;
  }
  int depth(int node) const {
    int d = 1;
    while (nodes[static_cast<std::size_t>(node)].parent >= 0) node = nodes[static_cast<std::size_t>(node)].parent, ++d;
    return d;
  }
};

}  // namespace sansui::contour
