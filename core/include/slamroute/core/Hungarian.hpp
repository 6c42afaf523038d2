#pragma once
// Minimum-cost assignment (Hungarian algorithm with potentials, O(n^2 m)). Debian's LEMON has
// min-cost flow and general-graph weighted matching but no bipartite assignment, and core does
// not link LEMON; this small exact solver serves the fleet planner and online exploration.
#include <vector>

namespace slamroute {

struct Assignment {
  std::vector<int> columnOfRow;  ///< per row: the assigned column, or -1 (more rows than columns)
  double totalCost = 0.0;        ///< sum of cost[r][columnOfRow[r]] over assigned rows
};

/// Assigns rows to columns so that every row (if rows <= columns) or every column (if
/// rows > columns) is used exactly once and the total cost is minimal. cost must be rectangular
/// with finite entries; an empty matrix gives an empty assignment. Throws std::invalid_argument.
Assignment hungarianAssignment(const std::vector<std::vector<double>>& cost);

}  // namespace slamroute
