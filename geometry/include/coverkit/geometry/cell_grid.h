#pragma once
// Exact cell classification (issue 2): sub-cells D×D and mega-cells 2D×2D tiling the workspace's
// bounding box from its lower-left corner. The grid is extended up and right to a whole number of
// mega-cells; cells beyond W are blocked.
//
// Classification by obstacles (C-space classification comes with the C-space):
//  - free:    the closed cell meets no obstacle interior (cell ⊆ W);
//  - blocked: the open cell contains no point of W's interior;
//  - partial: the rest.
// A mega-cell is free when its four sub-cells are, blocked when they all are, partial otherwise.
// Decided exactly (rationals; CGAL predicates) with a per-edge walk over the cells each boundary
// edge crosses and a row-by-row parity sweep with an active-edge list, so the cost is
// O((cells + crossed cells + rows·active edges) · log) instead of cells × vertices.
#include <coverkit/geometry/types.h>

#include <cstdint>
#include <vector>

namespace coverkit {

enum class CellState : std::uint8_t { kFree = 0, kPartial = 1, kBlocked = 2 };
const char* toString(CellState s);

struct CellIndex {
  int col = 0, row = 0;
};
inline bool operator==(CellIndex a, CellIndex b) { return a.col == b.col && a.row == b.row; }

class CellGrid {
public:
  CellGrid() = default;
  CellGrid(Rational originX, Rational originY, Rational subSize, int megaCols, int megaRows);

  const Rational& originX() const { return ox_; }
  const Rational& originY() const { return oy_; }
  const Rational& subSize() const { return d_; }
  double subSizeD() const { return dd_; }
  int subCols() const { return 2 * mc_; }
  int subRows() const { return 2 * mr_; }
  int megaCols() const { return mc_; }
  int megaRows() const { return mr_; }
  std::size_t subCount() const { return sub_.size(); }
  std::size_t megaCount() const { return static_cast<std::size_t>(mc_) * mr_; }

  CellState sub(int col, int row) const { return sub_[static_cast<std::size_t>(row) * subCols() + col]; }
  void setSub(int col, int row, CellState s) { sub_[static_cast<std::size_t>(row) * subCols() + col] = s; }
  CellState mega(int col, int row) const;
  bool insideSub(int col, int row) const { return col >= 0 && row >= 0 && col < subCols() && row < subRows(); }
  bool insideMega(int col, int row) const { return col >= 0 && row >= 0 && col < mc_ && row < mr_; }

  /// Exact centre and corners.
  Point subCenter(int col, int row) const;
  Point megaCenter(int col, int row) const;
  PointD subCenterD(int col, int row) const;
  /// Sub-cell containing p under the half-open rule [x0, x1) × [y0, y1); nullopt outside the grid.
  bool locateSub(const Point& p, CellIndex& out) const;
  bool locateSubD(PointD p, CellIndex& out) const;

  std::size_t count(CellState s) const;
  std::size_t countMega(CellState s) const;

private:
  Rational ox_, oy_, d_;
  double oxd_ = 0, oyd_ = 0, dd_ = 0;
  bool exactD_ = false;   ///< the origin and the sub-cell size are doubles exactly
  int mc_ = 0, mr_ = 0;
  std::vector<CellState> sub_;
};

/// Classifies the cells of a workspace exactly. `subSize` must be > 0.
CellGrid classifyCells(const Workspace& w, const Rational& subSize);

/// Exact point-in-W test: strictly inside (true), on the boundary or outside (false).
bool strictlyInside(const Workspace& w, const Point& p);

}  // namespace coverkit
