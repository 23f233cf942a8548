#include <coverkit/graph/grid_search.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

using namespace coverkit::graph;

namespace {
/// A grid drawn top row first ('.' passable, '#' not); cell id = row·cols + col, row 0 at the bottom.
struct Drawn {
  int cols = 0, rows = 0;
  std::vector<char> open;
  explicit Drawn(const std::vector<std::string>& lines) : cols(static_cast<int>(lines.front().size())), rows(static_cast<int>(lines.size())) {
    for (int r = 0; r < rows; ++r)
      for (char ch : lines[static_cast<std::size_t>(rows - 1 - r)]) open.push_back(ch == '.');
  }
  bool operator()(int v) const { return open[static_cast<std::size_t>(v)] != 0; }
};
}  // namespace

TEST(GridComponents, LabelsOfAHandMadeGrid) {
  // row 0 is the bottom line; cells touching only at a corner are not joined: (3,1)-(4,2) and
  // (4,2)-(3,3), col and row
  const Drawn g({
      "..#.#",  // row 3
      "#.##.",  // row 2
      "..#.#",  // row 1
      "#.#..",  // row 0
  });
  const std::vector<int> label = gridComponents(g.cols, g.rows, g);
  // numbered in row order of each component's first cell: {1,5,6,11,15,16} 0, {3,4,8} 1, {14} 2,
  // {18} 3
  const std::vector<int> expected = {
      -1, 0, -1, 1,  1,   // row 0
      0,  0, -1, 1,  -1,  // row 1
      -1, 0, -1, -1, 2,   // row 2
      0,  0, -1, 3,  -1,  // row 3
  };
  EXPECT_EQ(label, expected);
}

TEST(GridComponents, EveryCellAskedOnceAndEdgeCases) {
  int asked = 0;
  const std::vector<int> all = gridComponents(3, 2, [&](int) { return ++asked, true; });
  EXPECT_EQ(asked, 6);
  EXPECT_EQ(all, std::vector<int>(6, 0));
  EXPECT_EQ(gridComponents(4, 1, [](int v) { return v != 1; }), (std::vector<int>{0, -1, 1, 1}));
  EXPECT_EQ(gridComponents(2, 2, [](int) { return false; }), std::vector<int>(4, -1));
  EXPECT_TRUE(gridComponents(0, 0, [](int) { return true; }).empty());
}

TEST(GridComponents, OneLargeComponentNeedsNoRecursion) {
  // a serpentine of 10^6 cells: one component, one long path through it
  const int n = 1000;
  const std::vector<int> label = gridComponents(n, n, [&](int v) {
    const int c = v % n, r = v / n;
    return r % 2 == 0 || (r % 4 == 1 ? c == n - 1 : c == 0);
  });
  std::size_t in = 0;
  for (int k : label) {
    ASSERT_LE(k, 0);
    in += k == 0;
  }
  EXPECT_EQ(in, static_cast<std::size_t>(n / 2) * n + n / 2);
}

TEST(GridAStar, ShortestPathsFourAndEightConnected) {
  const Drawn g({
      ".....",  // row 2
      ".###.",  // row 1
      ".....",  // row 0
  });
  std::vector<int> explored;
  GridAStar four(g.cols, g.rows, false);
  const std::vector<int> p = four.search(5, 9, g, explored);  // (0,1) to (4,1), round the wall
  ASSERT_EQ(p.size(), 7u);
  EXPECT_EQ(p.front(), 5);
  EXPECT_EQ(p.back(), 9);
  for (std::size_t i = 1; i < p.size(); ++i) EXPECT_EQ(std::abs(p[i] % 5 - p[i - 1] % 5) + std::abs(p[i] / 5 - p[i - 1] / 5), 1);
  // 8-connected: the corners of the wall cannot be cut, so the path is as long in cells
  GridAStar eight(g.cols, g.rows, true);
  EXPECT_EQ(eight.search(5, 9, g, explored).size(), 7u);
  // a diagonal with both side cells free is taken: (0,0) to (1,1) on an open 2×2 grid
  GridAStar open2(2, 2, true);
  EXPECT_EQ(open2.search(0, 3, [](int) { return true; }, explored), (std::vector<int>{0, 3}));
  // walled off: no path
  EXPECT_TRUE(four.search(0, 14, [](int v) { return v != 5 && v != 1; }, explored).empty());
}
