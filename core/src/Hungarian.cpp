// Hungarian algorithm in the shortest-augmenting-path form with row and column potentials:
// each row is added in turn and joined through a Dijkstra-like search over reduced costs.
#include "slamroute/core/Hungarian.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace slamroute {
namespace {

using Matrix = std::vector<std::vector<double>>;

void checkShape(const Matrix& cost) {
  for (const auto& row : cost) {
    if (row.size() != cost.front().size())
      throw std::invalid_argument("hungarianAssignment: rows of different lengths");
    for (double c : row)
      if (!std::isfinite(c)) throw std::invalid_argument("hungarianAssignment: non-finite cost");
  }
}

Matrix transposed(const Matrix& m) {
  Matrix t(m.front().size(), std::vector<double>(m.size()));
  for (std::size_t r = 0; r < m.size(); ++r)
    for (std::size_t c = 0; c < m[r].size(); ++c) t[c][r] = m[r][c];
  return t;
}

/// rows <= columns. Returns the column of every row. Index 0 of the 1-based arrays is the
/// virtual column from which each new row's search starts.
std::vector<int> assignRows(const Matrix& a) {
  const std::size_t n = a.size(), m = a.front().size();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0);
  std::vector<std::size_t> rowOfCol(m + 1, 0), way(m + 1, 0);
  for (std::size_t i = 1; i <= n; ++i) {
    rowOfCol[0] = i;
    std::size_t j0 = 0;
    std::vector<double> minv(m + 1, inf);
    std::vector<bool> used(m + 1, false);
    do {  // grow the alternating tree until it reaches a free column
      used[j0] = true;
      const std::size_t i0 = rowOfCol[j0];
      double delta = inf;
      std::size_t j1 = 0;
      for (std::size_t j = 1; j <= m; ++j) {
        if (used[j]) continue;
        const double cur = a[i0 - 1][j - 1] - u[i0] - v[j];
        if (cur < minv[j]) minv[j] = cur, way[j] = j0;
        if (minv[j] < delta) delta = minv[j], j1 = j;
      }
      for (std::size_t j = 0; j <= m; ++j) {
        if (used[j])
          u[rowOfCol[j]] += delta, v[j] -= delta;
        else
          minv[j] -= delta;
      }
      j0 = j1;
    } while (rowOfCol[j0] != 0);
    do {  // flip the augmenting path back to the virtual column
      const std::size_t j1 = way[j0];
      rowOfCol[j0] = rowOfCol[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  std::vector<int> colOfRow(n, -1);
  for (std::size_t j = 1; j <= m; ++j)
    if (rowOfCol[j] != 0) colOfRow[rowOfCol[j] - 1] = static_cast<int>(j - 1);
  return colOfRow;
}

}  // namespace

Assignment hungarianAssignment(const Matrix& cost) {
  Assignment out;
  if (cost.empty() || cost.front().empty()) {
    out.columnOfRow.assign(cost.size(), -1);
    checkShape(cost);
    return out;
  }
  checkShape(cost);
  const bool wide = cost.size() <= cost.front().size();
  if (wide) {
    out.columnOfRow = assignRows(cost);
  } else {  // more rows than columns: assign every column a row, the remaining rows get -1
    const std::vector<int> rowOfCol = assignRows(transposed(cost));
    out.columnOfRow.assign(cost.size(), -1);
    for (std::size_t c = 0; c < rowOfCol.size(); ++c)
      out.columnOfRow[rowOfCol[c]] = static_cast<int>(c);
  }
  for (std::size_t r = 0; r < cost.size(); ++r)
    if (out.columnOfRow[r] >= 0) out.totalCost += cost[r][out.columnOfRow[r]];
  return out;
}

}  // namespace slamroute
