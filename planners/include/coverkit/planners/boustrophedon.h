#pragma once
// Boustrophedon coverage on an exact cell decomposition (issue 13).
//
// Reference: H. Choset and P. Pignon, "Coverage Path Planning: The Boustrophedon Cellular
// Decomposition", Field and Service Robotics (1997): decompose free space into cells bounded by
// walls at the critical points of a sweep line (where its connectivity changes), order the cells by
// a walk of the adjacency (Reeb) graph, and cover every cell with back-and-forth lanes. The paper
// works on the workspace of a point robot; here the cells are those of the disc robot's exact C-free
// (planners/decomposition.h), so a lane's ends are where the disc touches the boundary.
//
// Decisions where the paper leaves things open:
//  - Lanes run along the sweep lines (perpendicular to the sweep direction), from one end of the
//    cell to the other (τ inside, see below), k + 1 of them at spacing s = width / k ≤ 2r: the
//    discs of adjacent lanes meet or overlap, and a cell that ends at C-free's boundary (an
//    obstacle's side) has a lane there to sweep the band of width r beside it. Cells that end at a
//    wall share that lane's strip with their neighbour: the price of not knowing, per cell end,
//    whether it is wall or boundary along its whole length.
//  - The wall band. Beside a wall of the workspace C-free's boundary is at distance r, and the
//    band between them is swept only by a centre that runs along that boundary: the discs at lane
//    ends touch the wall at the lanes' x alone (between two lanes 2r apart they miss
//    (2 − π/2)·r² of it). So every piece of a cell's top and bottom boundary is followed, at
//    τ = min(r/100, half the cell's height) inside it (refined until every chord is clear): the
//    sweep runs along the first side to the far end, back over the lanes in a serpentine (an odd
//    number of lanes, so it ends on the other side), and along the other side again. That is
//    lanes + 3 × the cell's width, the least a closed walk over every lane and both sides needs
//    (the sides' inner lane ends have odd degree: a Chinese postman tour doubles one side's
//    length); a serpentine alone (lanes + width) covered 0.985 of pillars.wkt at r = 0.25. τ costs
//    a sliver of width τ along C-free's boundary. Two lanes need no third and no last pass: the
//    first pass follows one side, the serpentine's single turn the other. With three lanes or
//    more, the serpentine goes from one lane end to the next along the chord when it is clear
//    (the side passes follow both sides already; on a ragged side the chord saves the side's
//    corners), and along the side where it is not.
//  - Side passes follow the boundary τ inside it, one leg per boundary piece (a parallel line or a
//    concentric arc); two line legs meet where their parallel lines cross, so a corner of the
//    boundary is one corner of the path, and lane ends lie on these curves, so the walk never
//    steps back along a side (it did: a lane end on a slanted side was τ off the leg's end, two
//    reversals per lane end). A line and an arc, or two arcs, meeting at a corner are joined the
//    same way, where their offset curves cross (nearest the joint, ahead of the first leg's entry
//    and before the second's exit); before, a short connector between the two normals' ends went
//    back and forth at every such corner, and a scanned wall has one at every pixel step (on
//    the ROS basement map at r = 0.15, reversals 846 → 300).
//  - Where a leg (or the way onto it) is not clear, that leg alone is replaced by chords between
//    points τ inside the side, each clear and within r/20 of the side (sampled at both ends and
//    the middle of every boundary piece), split at the sample farthest from it; the other legs
//    stay. Before, the whole side fell back to chords split only until clear: a chord across the
//    foot of a spike of C-free left the spike unswept (on a generated scan of 5 cm pixels at
//    r = 0.15, coverage of the coverable region 0.933 → 0.976).
//  - Pockets. A region that fits in a box of r/4 × r/4 (a notch of a scanned wall, a wedge where
//    two C-obstacles nearly meet) is not swept on its own: the robot passes its mouth, and a
//    visit costs a transition in and out, two reversals or more, for a sliver of area. The
//    statistics pockets and pocket_area report them. On the ROS warehouse map at r = 0.15, 72
//    pockets of 0.0005 m² in all; turns 1431 → 1041, coverage 0.9984 → 0.9981.
//  - Slivers. A piece shorter than 1e-9·r (what a fillet leaves of a piece, or a connector
//    between legs that meet within rounding) has a heading that is rounding noise, and counted
//    as one or two turns of its own: it is dropped, the line beside it stretched over it (checked
//    exactly); between two arcs, one under 1e-10 long is left out (the validator's continuity
//    tolerance is 1e-9, and it checks the gap as a segment).
//  - Rounded corners (parameter round, default true; false keeps the corners of the paper). The
//    paper's lanes meet at right-angle corners, two per lane: most of the turns a robot makes. A
//    corner of the serpentine (lane to side, side to lane) or of a transition becomes an arc of
//    radius up to r tangent to both pieces (r, r/2, ... r/64, the first whose arc and shortened
//    pieces are clear, exactly); a corner with no clear arc stays. In an open room a lane pair's
//    two arcs of radius r make one half circle. This loses no coverage: the side passes run
//    through every lane end, and a lane gives up at most r(1 − sin α)/cos α of its end (α the
//    side's angle to the sweep line), so every point within r of what is cut off is within r of
//    the side pass. The side passes sweep the band beside the boundary, which a rounded corner
//    leaves in part: their corners are rounded only where the arc passes within r/20 of the
//    corner (radius r, r/2, ... down to r/16, the largest that is clear and that close). A side
//    pass's corner is where the disc reaches deepest into a notch of C-free's boundary; what the
//    arc gives up there is a lens at most r/20 thick beyond the disc's reach. Corners turning by
//    more than about 115° (where even r/16 is farther off) keep their corner. r/20 is our choice:
//    on a scanned wall the steps of one pixel make corners of 30-50° at every step, which this
//    rounds with radius r/4 and more. With the other changes of that revision (offset curves
//    joined where they cross, chords within r/20, pockets) the coverage of the coverable region
//    stayed 0.9979 on average over the 200 worlds and moved by at most 0.0022 either way on the
//    ROS maps (docs/decompositions.md).
//  - Chains (parameter chains, default true; false sweeps every cell on its own, as the paper
//    does). A cell and a neighbour that begins where it ends, joined through a vertical wall, have
//    closed intervals that overlap on that wall, so every vertical line meets their union in one
//    interval: the union is swept as one cell. Left to right, each cell takes the free right
//    neighbour it shares the longest wall with. A chain costs one entry and one set of side
//    passes, and its lanes run on across its walls (no lanes doubled on both sides of a wall, no
//    rounding up per cell). Inside a chain, and between regions, the robot moves cell by cell
//    (the interval of a chain jumps at its walls, where splitting a chord may never clear a
//    corner). On the benchmark's 15-hole world: 57 cells in 23 chains, length −12 %, coverage
//    0.9965 → 0.9977; the turns stay (a side pass turns where the chain's side jumps at a wall).
//  - Order: depth-first on the cell graph from the start's cell, nearest neighbour first (the
//    Reeb graph's walk), then 2-opt on the order with shortest-path distances in the cell graph
//    (up to 400 cells; beyond that the DFS order is kept: O(n²) per pass). Each cell is entered at
//    the corner (left/right, up/down) nearest the robot.
//  - Transitions between cells follow a shortest path of the cell graph, through the middle of the
//    longest wall shared by consecutive cells, then pulled straight (from each point the farthest
//    later point a clear segment reaches, checked exactly: 155 → 100 turns in transitions on the
//    15-hole world); inside a cell, a straight segment, split at the
//    middle of the cell's interval until every piece is clear; where that fails, through gates at
//    the x of the boundary's vertices (the interval of a monotone cell jumps at a vertical piece of
//    boundary, and a split point on the far side of that corner never clears it), or through a
//    point beside two doors on one wall line (an obstacle's side between them), or back along the
//    path's last lines.
//  - Safety: the plan is made in the C-free of radius r + μ (μ = 2^-24·r, at least 2^-40 of the
//    extent): every piece is checked exactly there (CSpace::segmentClear), so rounding the frame's
//    points back from a rotated frame (an error near 1e-16 of the extent) cannot bring the disc
//    within r of an obstacle. The coverage lost to μ is below 1e-6.
//  - A cell that cannot be reached (a failed transition, never seen) is skipped and reported
//    (status partial coverage, statistic skipped_cells).
//  - direction=best plans the directions of the workspace's longest edge families (the four with
//    the most total edge length, modulo 180°) and 0° and 90°, and keeps the plan with the least
//    length + r × total turning (radians).
//  - Gaps exactly 2r wide. C-free is closed (cspace.h): a disc may pass a gap exactly 2r wide along
//    its centre line. The plan's C-free (radius r + μ) is cut there, so components joined to the
//    start's only through such a gap are not crossed: their cells are counted
//    (cells_behind_exact_gaps, area_behind_exact_gaps, via CSpace::closedComponentOf) and the status
//    is partial coverage. (On a grid map at resolution 1/10 the centre line of such a gap is not a
//    double: no double path crosses it at all.)
// Coverage claim: the start's component of C-free ⊕ disc(r), less what lies behind such gaps.
#include <coverkit/planners/planner.h>

namespace coverkit::planners {

class BoustrophedonPlanner : public Planner {
public:
  std::string name() const override { return "boustrophedon"; }
  std::string description() const override;
  std::vector<ParamSpec> params() const override;
  Capabilities capabilities() const override;
  Plan plan(const PlanningContext& context, const ParamSet& params, const TerminationCondition& stop) override;
};

}  // namespace coverkit::planners
