// The contours of one mountain as a tree: a contour's parent is the next lower contour that
// encloses it; the outermost contour is the root. Levels count from the seed (level 0): +k inward
// (up), -k outward (down).
#pragma once

#include <cmath>
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
  /// True if the contour lies below the one enclosing it: a level of a closed depression (a
  /// crater's wall or floor), whose inside descends.
  bool descends(int node) const {
    const ContourNode& n = nodes[static_cast<std::size_t>(node)];
    return n.parent >= 0 && nodes[static_cast<std::size_t>(n.parent)].elevation_m > n.elevation_m;
  }
  /// Contours without children that are not the floor of a depression: the summit contours.
  std::vector<int> summits() const {
    std::vector<int> out;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i].children.empty() && !descends(static_cast<int>(i))) out.push_back(static_cast<int>(i));
    return out;
  }
  /// Elevation of the seed contour (0 for an empty tree). [Units: m]
  double seed_elevation() const { return nodes.empty() ? 0.0 : nodes[static_cast<std::size_t>(seed)].elevation_m; }
  /// The elevation step of one level, from the first contour off the seed's level (1 when the
  /// tree has one level). [Units: m]
  double interval() const {
    for (const ContourNode& node : nodes)
      if (node.level != 0) return std::fabs((node.elevation_m - seed_elevation()) / node.level);
    return 1.0;
  }
  int depth(int node) const {
    int d = 1;
    while (nodes[static_cast<std::size_t>(node)].parent >= 0) node = nodes[static_cast<std::size_t>(node)].parent, ++d;
    return d;
  }
};

}  // namespace sansui::contour
