// Smooth-STC, offline (Algorithm 1) and online (Algorithm 2). See smooth_stc.h for the reference.
//
// Our reading of the paper, and the decisions where it is vague or contradicts itself:
//
//  - Cells (4.1): sub-cells D × D with D = 2r (the robot's size), mega-cells 2D × 2D, classified by
//    the obstacles in the workspace, as for STC: free (no obstacle in the closed mega-cell),
//    partially occupied, or blocked (no free workspace inside).
//  - Adjacency (4.4.1): two mega-cells are joined only when their common border is entirely free.
//    Between two free mega-cells it always is; a partially occupied mega-cell is never joined to
//    take part in the tree as an inner node: it is a leaf.
//  - Input and output edges (4.4.2): the text says a partial mega-cell "only has an output edge",
//    Algorithm 1 (2.2) says it "only has an input edge", and the online text says both. We follow
//    Algorithm 1 and Fig 12: the edge from a free mega-cell x to a partial neighbour y is y's input
//    edge, and y has no other edge (a leaf). The tree itself is STC's: depth-first,
//    counter-clockwise (Algorithm 1, step 1; `tree` may choose another strategy).
//  - The leaf rule (2.2 and Fig 12): the robot goes around the tree counter-clockwise; where x's
//    side faces y it leaves along the right lane of the edge x → y, "follows the edge in until its
//    centre meets the C-space boundary", follows that boundary from the right of the edge to its
//    left, and returns along the left lane. We make this exact and general: let U be the 2D × 2D
//    rectangle between the two lanes, from the row of x's sub-cell centres on that side to the far
//    row of y's (exactly the rectangle STC's path would go around if y were free). The sweep is
//    the boundary of U ∩ C-free, counter-clockwise, from where the right lane enters C-free to
//    where the boundary comes back to x's row (CSpace::sweeps). Where nothing blocks U this is
//    STC's path around y; where an obstacle does, it is the C-space contour (segments and exact
//    arcs), with C-free on the left, as the paper draws it.
//  - Completeness (our additions; the paper claims "almost 100%", we measure and need it; each has
//    a parameter whose other value is the paper's rule, docs/smooth-stc.md has the figures):
//    * entries=every: an obstacle can split y so that the part beyond it is not reached from the
//      input edge, so y is entered from every free neighbour whose side the tour walks along;
//    * reach=run: obstacles larger than a mega-cell leave partial mega-cells that border no free
//      one, so U goes on straight through the whole run of partial mega-cells beyond y. U is 2r
//      wide: every point of the part of U ∩ C-free its boundary bounds lies within r of it. A run
//      crossed end to end from one side is not swept again from the other;
//    * pockets=join: free mega-cells cut off from the tree by partial ones are toured with their
//      own tree, entered from a sweep that crossed the run to them, as if the run were a tree edge;
//    * tips are cut: where U ∩ C-free narrows to a point its boundary reverses (a spike); it is cut
//      straight across where the two sides are r/16 apart. A tip is any turn of more than 150°
//      (a reversal by docs/metrics.md): at 175°, the first rule, lanes that meet a contour at a
//      grazing angle (a 155°-173° turn into the contour) were left as reversals.
//  - No reversal that is only rounding (ours): a sliver (a line shorter than 10^-9 r, left where two
//    pieces computed apart meet an ulp away) has a direction that is noise and turned a straight
//    joint into two right angles or a reversal (and hid real reversals as two right angles); it is
//    merged into a neighbouring line, or stepped over between two arcs (the validator's continuity
//    tolerance is 10^-9 and it checks the step). A loop spliced at a joint an ulp from its vertex is
//    spliced as at that vertex (the line there and back would have a direction that is noise, and
//    made the splice choose the loop's direction at random). A spur (a line back along the one
//    before it) whose stretch beyond the nearer end other pieces sweep is cut off.
//  - Gaps are visited only where nothing else can reach them (`gaps=auto`; `leave`, the default
//    before; `visit`, every gap, the rule before that): a gap's visit is a dead end left the way it
//    was entered, a reversal, which the paper's promise of paths without reversing excludes. On
//    coverage-vs-complexity's 204 worlds visiting every gap added 0.01 points of the coverable
//    region and all of the 0.07 reversals a plan that were left; for large robots (r = 1/40 of the
//    width among 10-20 obstacles of 1-2 m) 0.17 points and 0.37 reversals a plan. But a corridor or
//    door exactly 2r wide (a grid map's one-pixel passage at r of half a pixel) is C-free at r and
//    closed at r + ε + δ, where the sweeps, loops and patches run: leaving it left the shelving of
//    warehouse-20-40-10-2-2.map at r = 1 (0.43 of the coverable region against Full-STC's 0.99)
//    and the one-pixel corridors of the Moving AI maps at r = 0.5 (below Full-STC on three of five).
//    auto visits the groups of gaps that hold a sub-cell squeezed between edges on two opposite
//    sides, a reversal at each dead end as Full-STC makes there; no world of our experiments has
//    one (their plans are those of `leave` to the byte).
//  - Fewer turns (our defaults; the paper's tree and every detour stay reachable with
//    `tree=dfs_ccw;detours=every`): the paper promises paths no longer than Full-STC's, and turning
//    is what costs a real robot time. The tree has long straight branches (`tree=auto`): of
//    `kruskal_straight` (every row of free mega-cells one straight branch), its columns-first twin
//    and `longest_runs` (columns where a column run is more than twice the row run: a strip along a
//    side wall is one branch, not a comb of short rows), the one whose tour turns least, counted on
//    the tree (a right angle at each corner of a node whose two arms there are both or neither tree
//    edges). On ros/grid.yaml at r = 0.25 that takes the turning from 10,579° to 3,298°; on the
//    seeded worlds 0.2-5 % (6 worlds per count of 2, 10, 25 obstacles); `kruskal_straight` alone was
//    the default before. A tree weighted against branches that pass beside partial mega-cells (so
//    that they end at them) was tried and turned 21 % more on a 25-obstacle world: more, shorter
//    branches. The sweep at the end of a branch facing a partial mega-cell goes
//    straight on from the tour's lane, round the contour and straight back, and adds no corner. Any
//    other sweep leaves the tour and comes back (two corners, 180° more turning): with
//    `detours=needed` it is made only where it sweeps at least r² that the tour, the branch-end
//    sweeps and the detours taken before it (in tour order) do not (estimated in doubles from
//    samples; it decides which sweeps are made, never whether one is safe). Offline only: the
//    decision looks at the whole tour, which an online robot does not know yet.
//  - Rounded by default (`post=fillet`; `post=none` keeps the corners): the paper draws smooth
//    turns, and a corner costs a real robot a stop and a turn on the spot. The plan goes on through
//    the `fillet` path processor (optimise/, docs/post-processing.md) in the pipeline rather than
//    inside the planner, so the rounding is the one every planner can have, with its exact clearance
//    checks and its coverage guard, and the plan is validated exactly after it. Offline only: the
//    guard asks what the rest of the path sweeps. A fillet between lines turns as much as its
//    corner, so it removes corners and reversals, not turning; at a notch between two arcs of a
//    contour (a grid map's staircase) it shortens the arcs, which turn the other way, and takes
//    some turning off (ros/turtlebot3_world.yaml at r = 0.25: 146 → 0 turns, 15,072° → 12,746°,
//    for 0.0008 of the coverable region). The guard's rim is 0.01 r, not the processor's
//    0.04 r: on the seeded worlds (6 per count of 2, 10, 25 obstacles, r = 0.25) it keeps 0.03-0.15
//    points more of the coverable region for 4-7 % more robot time (smaller arcs are driven slower),
//    and on ros/grid.yaml at r = 0.25 0.9979 against 0.9975 (when it was chosen, with the revision
//    of that day, 0.9981 against 0.9966). Coverage is the planner's first promise.
//  - Contour passes (`contours`, ours; the paper has none): the sweeps meet the C-space contour
//    only inside their rectangles, so the band along each obstacle and each wall was swept a piece
//    at a time, with a sweep or a filled corner for each piece (a saw of short sweeps along a
//    straight wall, about 90° more turning for each filled corner). One pass along every boundary
//    loop of the start's component of C-free (the whole map's C-space at r + ε + δ, each piece then
//    checked exactly at r) sweeps that band in one piece for the loop's own turning (360° round a
//    convex obstacle). It is spliced in after the sweeps where it adds the least turning, best at a
//    joint on the loop in the loop's direction (where a sweep meets it), else by a straight line
//    there and back (checked exactly). Where the 64 that turn least all have their lines blocked
//    (the joints that turn least may lie across an obstacle: a pair of close discs in an open
//    area), the 256 joints nearest the loop are tried, nearest first. Decision: a loop spliced by a
//    longer line there and back costs turning and length, a loop left costs its whole band (16 ×
//    16 m worlds with 25 discs at r = 0.8: 0.924 → 0.980 of the coverable region). The loops
//    count as swept when the detours are chosen, so the sweeps they make redundant are left out,
//    and the corner fill is off by default with them (`corners=auto`: the wedges it fills lie
//    along walls and contours, which the loops sweep), except where the path sweeps too little
//    (`fill_below`, ours): after the patches, the robot centres reached from the path's own
//    (sampled every r/2) that nothing sweeps, over their area and r along every loop (the band
//    between C-free and the obstacles), estimate the share left; below 0.99 (the coverage the
//    planner promises) the corners are filled. A large robot among obstacles about a mega-cell in
//    size has many turns for its area, each leaving a wedge of r²(1 − π/4) that the loops do not
//    reach: on 16 m worlds at r = 0.4 with 10-20 obstacles of 1-2 m of each of the six shapes
//    (seeds 9301-9306) the mean coverage of a shape and a count was 0.9885-0.9923, worst world
//    0.9822; with the fill where needed 0.9906-0.9943, worst 0.9863, for 4.7 % more turning.
//    Decision: a fixed threshold on an estimate, not a rule on the robot's size: it asks what the
//    plan leaves, and on coverage-vs-complexity's worlds at r = 0.25 (0.991 or more without the
//    fill) it changes nothing (the 204 worlds give the figures of the revision before, to the
//    digit; the fill there turns 1.3-1.7 × as much for coverage that is already above 0.99).
//    The estimate misses what the loops leave in a star's notches (the centres cannot go there):
//    two star worlds estimated at 0.990 and 0.992 cover 0.986 and 0.987.
//    Rooms the path reaches through a gap exactly 2r wide (a one-cell door of a grid map at
//    r = half a cell) are other components at r + ε + δ: their loops are spliced after the rooms
//    pass, from a joint within 3r (room-64-64-8.map at r = 0.5: 0.960 → 0.982 of the coverable
//    region; the start's loop alone left the corners of the other 63 rooms unswept).
//    Measured on coverage-vs-complexity's 204 worlds (docs/experiments.md): coverage 0.9914 →
//    0.994, total turning 2.07 → 1.27 × Full-STC's, robot time 1.20 → 1.10 ×. Offline only (the
//    online robot knows a contour only as far as it has sensed it). `auto` passes on maps of at
//    most 20,000 vertices: the whole map's C-space costs 0.5 s at 9,000 pieces and 8 s at 90,000
//    (a 10^6-pixel map, where the rest of the plan takes under 2 s), and there it fills corners.
//  - Mitred loop corners (`loop_corners=mitre`, ours; `arc` keeps the C-space contour's arcs): a
//    loop's arc round an obstacle's corner sweeps a disc of 2r about the corner, and the lane 2r
//    further out sweeps from 2r outward along the sides only: a wedge of up to (4 − π) r² at the
//    corner that nothing sweeps, below the patches' r². Each arc of radius r (+ ε + δ), at most
//    120°, between lines at least r long (so not a scan's staircase) becomes the two tangent lines
//    to their crossing where both are exactly clear: the same turning and the same joints. The
//    loops are mitred before the tour, so the detours and splices see the corners' squares as
//    swept, and a lane through the crossing (a grid-aligned map's lanes cross there) splices the
//    loop without a line there and back. After the rooms pass a mitred corner still whole in the
//    path gets its arc back unless its lines sweep at least r²/8 nothing else does (sampled every
//    r/8): kept everywhere, the corners cost robot time on coverage-vs-complexity's worlds (2,805 →
//    2,828 s at 25 obstacles, with the fillet) for no coverage at four decimals. ros/grid.yaml at
//    r = 0.25: 0.9970 → 0.9979 of the coverable region (Full-STC 0.9978), 3,658° → 3,150° of
//    turning (the wedges at the corners of the box in the middle; a patch circle no longer needed).
//  - Patches (`patches`, ours; the paper has none): the sweeps stay inside their 2D × 2D rectangles
//    and the passes within 2r of a contour, so C-free between obstacles more than 4r apart across
//    partially occupied mega-cells that border no free one is left (large robots among obstacles
//    about a mega-cell in size: 0.987 of the coverable region on experiments/configs/
//    smooth_stc_large_robots.yaml). Every group of robot centres (sampled every r/2, 4-connected to
//    the path's own) that nothing sweeps, of at least `patches` r² (default 1), gets a circle
//    tangent to a nearby line of the path (the robot runs round it and on along the line: 360° of
//    turning, no corner, nothing the line swept is lost; a triangular bump off the line turns only
//    4α but gives up the line's strip, which cost 1.5 points when tried, and a stem there and back
//    to a loop turns 720°), of radius the distance to the group's middle or half of it, checked
//    exactly; at most three a group. Large robots: 0.987 → 0.991; ros/grid.yaml at r = 0.25:
//    0.9966 → 0.9970; the 25-obstacle probe worlds: 0.9900 → 0.9918 for 6.8 % more turning
//    (`patches=2`: 0.9906 for 0.4 %; 0.5 catches the wedges at the tour's corners too, at 1.4-1.8 ×
//    the turning). With the contour passes; online too (below).
//    Second version (ours), for open areas of 40-100 r² in cluttered worlds, which one circle aimed
//    at the middle cut in two (the middle of the two halves then lies on the circle, and the group
//    was not split again) or could not reach (no line within 8r of the middle): after each circle
//    what is open is split again into connected parts, each patched on its own; the targets are
//    the middle and up to three open centres farthest from those before; circles may be tangent to
//    arcs (the contour loops of round obstacles are arcs); the candidate that sweeps the most open
//    centres goes first, none under half of `patches` r²; and a group gets up to 3 + area / 8r²
//    circles (at most 16). Decision: rank by what a circle sweeps, not by its size: every circle
//    turns 360° whatever its radius, so sweeping more a circle means fewer circles. Measured on
//    18 × 14 m worlds with 30 obstacles at r = 0.3 (seeds 9001-9006): 0.9833 → 0.9901 (worst
//    0.9626 → 0.9886) with slightly less turning (54,364° → 54,290°); the figures of every
//    experiment are in docs/smooth-stc.md. What it gives up: a part left below `patches` r² after
//    a circle is not patched on, so on room-64-64-8.map at r = 0.5 (wedges of 0.5-1 r² beside the
//    lanes' U-turns) 0.9900 → 0.9883 for 21 % less turning. Decision: `patches` stays 1 (0.5
//    covers 0.9927 there, but costs 1.3 × the turning on the large robots' worlds, which cover 0.99
//    at 1 already); a user who wants the wedges sets it. Third radius (ours): each candidate is
//    also tried at 0.3 of the distance, a circle that reaches just past the target, for an open
//    area hemmed in by obstacles that the two larger circles cut into (16 m world, 20 discs of
//    1-2 m, r = 0.4, seed 9302: a group of 11 r² that no circle reached gets one, 0.9858 →
//    0.9874 of the coverable region). Only where no larger circle is exactly clear: ranked with
//    them, a small circle that sweeps more open centres went first on ros/turtlebot3_world.yaml
//    at r = 0.25 and left the rest of its group below `patches` r² (0.9910 → 0.9892).
//  - Taut stretches (`taut`, ours): a grid map's contours are stairs of pixels, and their C-space
//    contours scallops of arcs meeting in notches, some 30° of turning each way at every pixel. A
//    stretch of up to 32 pieces within 0.0625 r of the line between its ends becomes that line
//    where the line turns less, makes no reversal and is exactly clear (ros/depot.yaml at
//    r = 0.25, rounded: 94,852° → 90,308°, 3,405 → 3,344 s of robot time, for 0.0001 of the
//    coverable region; 0.25 r cut deeper notches: 0.9935 → 0.9877). The notches left are rounded
//    by the fillet (arc pairs). Offline only.
//  - Exactness: the sweep runs on the C-space of radius r + ε + δ. ε (a power of two just above
//    the C-space's approximation bound, 1e-6 × the map's extent) keeps the sweep outside the
//    conservative C-obstacles of radius r as well, whose irrational edges are replaced by pieces up
//    to ε outside (so the path also lies in the library's own C-free, which the tests check);
//    δ = 2^-36 × extent (a power of two) is more than rounding the sweep's exact points (square
//    roots where lanes meet arcs) to doubles can move them (~2^-52 × extent); every inserted piece is then checked
//    exactly against the true radius r (ClearanceChecker, as the validator reads lines and arcs),
//    and a sweep with a failing piece is left out and counted (`sweeps_rejected`), never kept.
//  - Online (Algorithm 2): the Spiral-STC robot (sensor of the four neighbouring mega-cells); when
//    its walk reaches a side facing a mega-cell that is not free, it sweeps it from what its
//    obstacle sensor has reported (ObstacleSensor: the rings that come into a mega-cell's box grown
//    by a sub-cell, only for the robot's mega-cell and its neighbours; any other question throws).
//    It senses its own mega-cell and the leaf, and along a run each next mega-cell from the one
//    before as the contour reaches it; the sweep is made from the rings known so far
//    (OnlineSweeper). A sweep depends only on obstacles within r + ε + δ < D of U, all of which
//    have been reported by then, and the pieces are those of the offline planner, so with the
//    paper's dfs_ccw rule the plan equals the offline one to the byte (tested, with the two
//    additions below off). A pocket's tree is grown by the same rule once the robot is in it.
//  - Online rooms and contour passes (ours; `rooms=travel`, `contours=auto`, as offline; the paper's
//    online robot has neither): with the sweeps alone the online robot covered 0.38 of the coverable
//    region on 16 × 16 m worlds with 30 obstacles of 0.8-2 m at r = 0.4 (most mega-cells partial),
//    0.94 with 20, against the offline planner's 0.99. The robot senses, along its path, the
//    mega-cell it is in and the four beside it, and knows a sub-cell's state only in a mega-cell it
//    has sensed. Contours: a C-space loop is followed when the path first comes within 3r of it (the
//    first joint in path order, never with a reversal), not where the whole path would turn least;
//    each piece of the loop depends only on obstacles within r + ε + δ < D of it, which the sensor
//    reports for the mega-cell the robot is in, so the loops are taken from the whole map's C-space
//    (the same pieces) and the robot senses along them. Rooms: the offline pass with every way held
//    to what the robot knew before the piece of the path it leaves from (a room learnt of late is
//    reached from where the path ends instead, with a longer way). Decision: coverage is the
//    planner's first promise; the online robot now covers more than the offline planner with 10,
//    20 and 30 obstacles (it splices every loop it comes to, of any component, keeps the corner
//    fill, and patches) for 1.4-1.8 × the offline robot time; `rooms=leave;contours=none` is the sweeps-only
//    robot. Patches (online, `patches`, default 1 as offline): with 30 obstacles it covered 1.9
//    points less than the offline planner, on ROS maps up to 9.3 points less, all of it in
//    pockets of partially occupied mega-cells that only the offline patches reached. The online
//    robot patches after its contours and rooms: the samples only where the robot sensed (a
//    sample's 1.02r reach in sensed mega-cells), and a circle tangent to piece j only where every
//    mega-cell its reach (radius + 1.02r about its centre) overlaps was sensed before piece j began,
//    so the exact check, run against the whole map, reads only obstacles the robot knew there. What
//    is still open is judged from the whole path, as for the rooms (a room is one no tour reached).
//    Decision, the rooms' rule: what a piece relies on of the world is what the robot had sensed
//    before it; which places are left open is judged from the whole path, so the patches are online
//    in what they know of the world, not in when they are chosen (a robot choosing at piece j would
//    also make circles into places that later pieces sweep). With 30 obstacles
//    0.9713 → 0.9927 (offline 0.9912); figures in docs/smooth-stc.md.
#include <coverkit/planners/smooth_stc.h>

#include <coverkit/geometry/cspace.h>
#include <coverkit/geometry/fillet.h>
#include <coverkit/geometry/metrics.h>
#include <coverkit/geometry/parallel.h>
#include <coverkit/geometry/validate.h>

#include <coverkit/planners/sensor.h>

#include "walk_path.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <map>
#include <numeric>
#include <set>
#include <tuple>
#include <unordered_set>

namespace coverkit::planners {

namespace {

using Clock = std::chrono::steady_clock;

/// `patches`, offline and online; `checked` says what a circle is checked against.
ParamSpec patchesParam(const std::string& checked) {
  return {"patches", ParamType::kDouble, "1", "0:1000|none",
          "with the contour passes: circles tangent to the path into each group of robot centres that nothing sweeps, of at "
          "least this area in r^2 (groups between obstacles more than 4r apart), " + checked + "; or none"};
}

std::vector<ParamSpec> entryParam() {
  return {{"entries", ParamType::kChoice, "every", "every|parent",
           "which free neighbours enter a partially occupied mega-cell: every one the tour passes (complete), or only "
           "the first, its tree parent (the paper's single input edge)"},
          {"reach", ParamType::kChoice, "run", "run|cell",
           "how far a sweep goes: through the whole run of partially occupied mega-cells straight beyond the free one "
           "(run), or into the neighbouring mega-cell only (cell, the paper's leaf)"},
          {"pockets", ParamType::kChoice, "join", "join|leave",
           "free mega-cells cut off from the tree by partially occupied ones, beyond a run swept end to end: toured with "
           "their own tree from the sweep (join), or left to the sweeps (leave)"},
          {"corners", ParamType::kChoice, "fill", "fill|keep",
           "at a right-angle turn whose outer corner nothing else sweeps: run on to the sub-cell's edge and cut back "
           "diagonally (fill), or turn at the centre as STC does (keep)"},
          {"sweeps", ParamType::kChoice, "trace", "trace|exact",
           "how a sweep's contour is made: traced directly among axis-parallel edges where every decision has a margin, "
           "the exact Boolean operations otherwise (trace), or always the exact Boolean operations (exact; slower, the "
           "same contours to 1e-9 of the extent)"}};
}

/// ε + δ: ε a power of two at least the C-space's approximation bound (1e-6 of the extent, see
/// CSpace), δ a power of two, 2^-36 of the extent.
/// Two points closer than this are one joint: the path steps from one to the other without a
/// piece between (the validator's continuity tolerance is 10^-9 and it checks such a step exactly;
/// here only rounding, an ulp or so, is that close). A piece so short would have a direction that
/// is noise, a turn of up to 180° at each end for the metrics and for a robot.
constexpr double kJointGap = 1e-10;

/// The cosine of the smallest heading change the metrics count as a reversal
/// (MetricOptions::reversalDeg): the tips and spurs rules remove exactly those.
const double kReversalCos = std::cos(MetricOptions{}.reversalDeg * M_PI / 180);

Rational slackOf(const Workspace& w) {
  const Box b = w.bbox();
  const double extent = std::max(std::max(Rational(b.xmax - b.xmin).get_d(), Rational(b.ymax - b.ymin).get_d()), 1e-9);
  return exactFromDouble(std::ldexp(1.0, std::ilogb(1e-6 * extent) + 1)) + exactFromDouble(std::ldexp(1.0, std::ilogb(extent) - 36));
}


/// A side of a mega-cell the walk goes along, with the mega-cell beyond it on the walk's right.
struct Opening {
  std::size_t move;   ///< walk[move] → walk[move + 1]
  int dir;            ///< direction of the move (graph::Dir)
  int leafCol, leafRow;
  int run = 1;        ///< mega-cells the sweep reaches: the leaf and the partial ones straight beyond it
};

CSpace::SweepRequest requestOf(const CellGrid& cells, const std::vector<CellIndex>& walk, const Opening& o) {
  const CellIndex a = walk[o.move], d = walk[o.move + 1];
  return {cells.subCenter(a.col, a.row), cells.subCenter(d.col, d.row), Rational(2 * o.run * cells.subSize())};
}

/// A line or arc of the path, read exactly as the validator reads it, keeps the disc clear.
bool pieceClear(ClearanceChecker& check, const PathSegment& p) {
  return p.kind == PathSegment::Kind::kLine ? check.clear(p.from, p.to) : check.clearArc(p.from, p.to, p.center, p.ccw);
}

/// Unit heading of a piece at its start or end.
PointD unitHeading(const PathSegment& p, bool atEnd) {
  double x, y;
  if (p.kind == PathSegment::Kind::kLine) {
    x = p.to.x - p.from.x, y = p.to.y - p.from.y;
  } else {
    const PointD q = atEnd ? p.to : p.from;
    x = -(q.y - p.center.y), y = q.x - p.center.x;
    if (!p.ccw) x = -x, y = -y;
  }
  const double n = std::hypot(x, y);
  return n > 0 ? PointD{x / n, y / n} : PointD{0, 0};
}

/// The point at arc length `l` from the start of a piece (0 ≤ l ≤ len, its length).
PointD pointAlong(const PathSegment& p, double l, double len) {
  if (len <= 0) return p.from;
  if (p.kind == PathSegment::Kind::kLine) {
    const double t = std::min(1.0, std::max(0.0, l / len));
    return {p.from.x + t * (p.to.x - p.from.x), p.from.y + t * (p.to.y - p.from.y)};
  }
  const double rho = std::hypot(p.from.x - p.center.x, p.from.y - p.center.y);
  const double a = std::atan2(p.from.y - p.center.y, p.from.x - p.center.x) + (p.ccw ? 1 : -1) * l / rho;
  return {p.center.x + rho * std::cos(a), p.center.y + rho * std::sin(a)};
}

/// A box holding a piece: its ends' for a line, its whole circle's for an arc.
BoxD boundsOf(const PathSegment& s) {
  if (s.kind == PathSegment::Kind::kArc) {
    const double rho = std::hypot(s.from.x - s.center.x, s.from.y - s.center.y);
    return {s.center.x - rho, s.center.y - rho, s.center.x + rho, s.center.y + rho};
  }
  return {std::min(s.from.x, s.to.x), std::min(s.from.y, s.to.y), std::max(s.from.x, s.to.x), std::max(s.from.y, s.to.y)};
}

/// Whether p lies within `limit` of piece s (in doubles: squared distances for lines; for arcs,
/// the circle's annulus first, so that most arcs need no angles).
bool withinReach(const PathSegment& s, PointD p, double limit) {
  if (s.kind == PathSegment::Kind::kLine) {
    const double dx = s.to.x - s.from.x, dy = s.to.y - s.from.y, len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - s.from.x) * dx + (p.y - s.from.y) * dy) / len2 : 0;
    t = std::min(1.0, std::max(0.0, t));
    const double ex = p.x - s.from.x - t * dx, ey = p.y - s.from.y - t * dy;
    return ex * ex + ey * ey <= limit * limit;
  }
  const double rho = std::hypot(s.from.x - s.center.x, s.from.y - s.center.y);
  const double dc = std::hypot(p.x - s.center.x, p.y - s.center.y);
  if (std::abs(dc - rho) > limit) return false;   // beyond the whole circle's reach
  const double a0 = std::atan2(s.from.y - s.center.y, s.from.x - s.center.x), a1 = std::atan2(s.to.y - s.center.y, s.to.x - s.center.x);
  const double ap = std::atan2(p.y - s.center.y, p.x - s.center.x);
  auto sweep = [&](double from, double to) {  // ccw angle from `from` to `to` in [0, 2π)
    double d = to - from;
    while (d < 0) d += 2 * M_PI;
    return d;
  };
  const bool inside = s.ccw ? sweep(a0, ap) <= sweep(a0, a1) : sweep(a1, ap) <= sweep(a1, a0);
  if (inside) return true;   // |dc − ρ| ≤ limit above
  return std::min(std::hypot(p.x - s.from.x, p.y - s.from.y), std::hypot(p.x - s.to.x, p.y - s.to.y)) <= limit;
}

/// The pieces of a path by bucket (side 2r, coarser where the box would need more than about 16
/// million), growing as pieces are added (a list per bucket, linked through one array), for "does
/// some piece pass within r of this point" in doubles. It decides only which sweeps are worth
/// making and where to go, never safety. Points outside the box are covered by nothing.
class CoverIndex {
public:
  CoverIndex(double r, BoxD box) : r_(r) {
    const double reach = r * (1 + 1e-6);
    box_ = {box.xmin - reach, box.ymin - reach, box.xmax + reach, box.ymax + reach};
    const double w = box_.xmax - box_.xmin, h = box_.ymax - box_.ymin;
    constexpr double kMaxCells = 16.0 * 1024 * 1024;
    cell_ = std::max({2 * r, std::sqrt(w * h / kMaxCells), std::max(w, h) / kMaxCells, 1e-300});
    nx_ = static_cast<long>(w / cell_) + 1, ny_ = static_cast<long>(h / cell_) + 1;
    head_.assign(static_cast<std::size_t>(nx_ * ny_), -1);
  }
  void add(const PathSegment& s) {
    const auto i = static_cast<std::int32_t>(pieces_.size());
    pieces_.push_back(s);
    const BoxD b = boundsOf(s);
    const double reach = r_ * (1 + 1e-6);
    for (long by = key(b.ymin - reach, box_.ymin, ny_); by <= key(b.ymax + reach, box_.ymin, ny_); ++by)
      for (long bx = key(b.xmin - reach, box_.xmin, nx_); bx <= key(b.xmax + reach, box_.xmin, nx_); ++bx) {
        std::int32_t& h = head_[static_cast<std::size_t>(by * nx_ + bx)];
        entries_.push_back({i, h});
        h = static_cast<std::int32_t>(entries_.size() - 1);
      }
  }
  bool covered(PointD p) const {
    if (!(p.x >= box_.xmin && p.y >= box_.ymin && p.x <= box_.xmax && p.y <= box_.ymax)) return false;
    const double limit = r_ * (1 + 1e-9);
    for (std::int32_t e = head_[static_cast<std::size_t>(key(p.y, box_.ymin, ny_) * nx_ + key(p.x, box_.xmin, nx_))]; e >= 0;
         e = entries_[static_cast<std::size_t>(e)].next)
      if (withinReach(pieces_[static_cast<std::size_t>(entries_[static_cast<std::size_t>(e)].piece)], p, limit)) return true;
    return false;
  }
  /// The area within r of `pieces` that no piece added so far reaches, estimated from samples every
  /// r/4 along them at five offsets across (−3r/4 … 3r/4): every sample lies in the coverable region,
  /// as the pieces lie in C-free.
  double uncovered(const std::vector<PathSegment>& pieces) const {
    double area = 0;
    for (const PathSegment& p : pieces) {
      const double len = p.length();
      const int n = std::max(1, static_cast<int>(std::ceil(len / (r_ / 4))));
      for (int k = 0; k < n; ++k) {
        const PointD q = pointAlong(p, (k + 0.5) * len / n, len);
        PathSegment at = p;
        at.from = q;
        const PointD t = unitHeading(at, false);
        for (double o : {-0.75, -0.375, 0.0, 0.375, 0.75})
          if (!covered(PointD{q.x - o * r_ * t.y, q.y + o * r_ * t.x})) area += len / n * 0.375 * r_;
      }
    }
    return area;
  }

private:
  struct Entry {
    std::int32_t piece, next;
  };
  long key(double v, double origin, long n) const {
    return std::min(n - 1, std::max(0L, static_cast<long>((v - origin) / cell_)));
  }
  double r_, cell_ = 1;
  BoxD box_;
  long nx_ = 1, ny_ = 1;
  std::vector<PathSegment> pieces_;
  std::vector<std::int32_t> head_;
  std::vector<Entry> entries_;
};

/// The tour of a pocket's tree from a sub-cell (closed), or empty.
using PocketWalk = std::function<std::vector<CellIndex>(CellIndex start)>;

/// The workspace's edges by cell, for "is some obstacle edge within `reach` of this point" in
/// doubles (the patches' samples, the pinched gaps): it decides only where to try, never safety.
class EdgeIndex {
public:
  /// The workspace's edges by cell (side `reach`, coarser where that would exceed about a million
  /// cells), listed per cell in two passes (count, then fill).
  EdgeIndex(const Workspace& w, double reach, BoxD box) : reach_(reach), box_(box) {
    const double W = box.xmax - box.xmin, H = box.ymax - box.ymin;
    cell_ = std::max({reach, std::sqrt(W * H / (1024.0 * 1024)), std::max(W, H) / (1024.0 * 1024), 1e-300});
    nx_ = static_cast<long>(W / cell_) + 1, ny_ = static_cast<long>(H / cell_) + 1;
    for (const Ring* ring : w.rings())
      for (std::size_t i = 0; i < ring->size(); ++i) {
        const Point& p = (*ring)[i];
        const Point& q = (*ring)[(i + 1) % ring->size()];
        edges_.push_back({PointD{p.x.get_d(), p.y.get_d()}, PointD{q.x.get_d(), q.y.get_d()}});
      }
    auto each = [&](const std::pair<PointD, PointD>& e, auto&& f) {
      const auto& [a, b] = e;
      for (long y = key(std::min(a.y, b.y) - reach, box_.ymin, ny_); y <= key(std::max(a.y, b.y) + reach, box_.ymin, ny_); ++y)
        for (long x = key(std::min(a.x, b.x) - reach, box_.xmin, nx_); x <= key(std::max(a.x, b.x) + reach, box_.xmin, nx_); ++x)
          f(static_cast<std::size_t>(y * nx_ + x));
    };
    start_.assign(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
    for (const auto& e : edges_) each(e, [&](std::size_t c) { ++start_[c + 1]; });
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    list_.resize(start_.back());
    for (std::size_t e = 0; e < edges_.size(); ++e) each(edges_[e], [&](std::size_t c) { list_[fill[c]++] = static_cast<std::uint32_t>(e); });
  }
  /// No edge within `reach` of p.
  bool clearOf(PointD p) const {
    const auto c = static_cast<std::size_t>(key(p.y, box_.ymin, ny_) * nx_ + key(p.x, box_.xmin, nx_));
    for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) {
      const auto& [a, b] = edges_[list_[k]];
      const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
      const double t = l2 > 0 ? std::min(1.0, std::max(0.0, ((p.x - a.x) * dx + (p.y - a.y) * dy) / l2)) : 0;
      if (std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy) < reach_) return false;
    }
    return true;
  }

private:
  long key(double v, double origin, long n) const {
    return std::min(n - 1, std::max(0L, static_cast<long>((v - origin) / cell_)));
  }
  double reach_, cell_ = 1;
  BoxD box_;
  long nx_ = 1, ny_ = 1;
  std::vector<std::pair<PointD, PointD>> edges_;
  std::vector<std::size_t> start_;   ///< the edges of cell c: list_[start_[c] .. start_[c + 1])
  std::vector<std::uint32_t> list_;
};

/// Puts the sweeps into the tour's path, and the tours of the pockets they reach into the sweeps.
/// One per plan: the mega-cells in some tour, the runs swept end to end and the counts are shared
/// by the main tour and the pockets' tours.
class Refiner {
public:
  /// Online, `sensor` and `sweeper` are given: each sweep is made from what the sensor has reported.
  Refiner(const PlanningContext& ctx, const ParamSet& params, ClearanceChecker& check, PocketWalk pocketWalk,
          ObstacleSensor* sensor = nullptr, OnlineSweeper* sweeper = nullptr)
      : ctx_(ctx), cells_(ctx.cells), sensor_(sensor), sweeper_(sweeper), trace_(params.text("sweeps") == "trace"),
        every_(params.text("entries") == "every"),
        throughRuns_(params.text("reach") == "run"), pockets_(params.text("pockets") == "join"),
        needed_(!sensor && params.text("detours") == "needed"), onlineGaps_(sensor && params.text("gaps") == "auto"), check_(check),
        pocketWalk_(std::move(pocketWalk)), inTree_(cells_.megaCount(), 0), swept_(cells_.megaCount(), 0) {}

  /// The sweeps of `walk`'s openings (and the pockets behind them) inserted into its placed `path`.
  void tour(const std::vector<CellIndex>& walk, Path& path) {
    for (const CellIndex& c : walk) inTree_[megaIndex(c.col / 2, c.row / 2)] = 1;
    const std::vector<Opening> open = openings(walk);
    std::vector<std::uint8_t> innerClear;
    const std::vector<CSpace::Sweep> sweeps = contours(walk, open, innerClear);
    insert(walk, open, sweeps, innerClear, path);
  }

  /// tour() for several walks at once, offline: the sweeps of all of them made in one batch (one
  /// set of buckets of the obstacles' pieces, not one per walk), then each walk's put into its path
  /// in order.
  void tourMany(const std::vector<std::pair<const std::vector<CellIndex>*, Path*>>& tours) {
    if (sensor_ || tours.size() < 2) {
      for (const auto& [walk, path] : tours) tour(*walk, *path);
      return;
    }
    std::vector<std::vector<Opening>> open;
    std::vector<CSpace::SweepRequest> requests;
    for (const auto& [walk, path] : tours) {
      for (const CellIndex& c : *walk) inTree_[megaIndex(c.col / 2, c.row / 2)] = 1;
      open.push_back(openings(*walk));
      for (const Opening& o : open.back()) requests.push_back(requestOf(cells_, *walk, o));
    }
    std::vector<std::uint8_t> inner;
    const std::vector<CSpace::Sweep> all = offlineSweeps(requests, inner);
    std::size_t from = 0;
    for (std::size_t i = 0; i < tours.size(); ++i) {
      const std::size_t n = open[i].size();
      const std::vector<CSpace::Sweep> sweeps(all.begin() + static_cast<std::ptrdiff_t>(from), all.begin() + static_cast<std::ptrdiff_t>(from + n));
      const std::vector<std::uint8_t> innerClear(inner.begin() + static_cast<std::ptrdiff_t>(from), inner.begin() + static_cast<std::ptrdiff_t>(from + n));
      insert(*tours[i].first, open[i], sweeps, innerClear, *tours[i].second);
      from += n;
    }
  }

  /// Pieces the path will pass (contour loops spliced in after the sweeps): counted as swept when
  /// deciding which detours are needed.
  void precover(const std::vector<PathSegment>& pieces) { precovered_.insert(precovered_.end(), pieces.begin(), pieces.end()); }

  void report(Plan& plan) const {
    std::size_t leaves = 0;
    for (auto v : swept_) leaves += v;
    plan.statistics["sweeps"] = static_cast<double>(inserted_);
    plan.statistics["sweeps_unreached"] = static_cast<double>(unreached_);
    plan.statistics["sweeps_shared"] = static_cast<double>(shared_);
    plan.statistics["sweeps_rejected"] = static_cast<double>(rejected_);
    plan.statistics["sweeps_traced"] = static_cast<double>(traced_);
    plan.statistics["partial_mega_cells_swept"] = static_cast<double>(leaves);
    plan.statistics["arcs"] = static_cast<double>(arcs_);
    plan.statistics["pockets_joined"] = static_cast<double>(pocketsJoined_);
    plan.statistics["pockets_left"] = static_cast<double>(pocketsLeft_);
    plan.statistics["detours_skipped"] = static_cast<double>(skipped_);
    plan.statistics["rooms_joined"] = static_cast<double>(roomsJoined_);
    plan.statistics["rooms_left"] = static_cast<double>(roomsLeft_);
    if (sensor_) plan.statistics["rooms_from_end"] = static_cast<double>(roomsFromEnd_);
    if (sensor_) plan.statistics["frontier_trips"] = static_cast<double>(frontierTrips_);
    plan.statistics["gaps_visited"] = static_cast<double>(gapsJoined_);
    plan.statistics["gaps_left"] = static_cast<double>(gapsLeft_);
    plan.statistics["excursions_dropped"] = static_cast<double>(excursionsDropped_);
    plan.statistics["travel_passes"] = static_cast<double>(passes_);
  }

private:
  std::size_t megaIndex(int col, int row) const { return static_cast<std::size_t>(row) * cells_.megaCols() + col; }

  /// The mega-cells straight beyond (col, row) in direction `d`, (col, row) included, that no tour
  /// covers: partially occupied ones; with pockets left, also free ones outside every tree (cut
  /// off from the tree by partially occupied mega-cells), which a joined pocket's tour covers.
  int runFrom(int col, int row, int d) const {
    int n = 0;
    while (cells_.insideMega(col, row) &&
           (cells_.mega(col, row) == CellState::kPartial ||
            (!pockets_ && cells_.mega(col, row) == CellState::kFree && !inTree_[megaIndex(col, row)]))) {
      ++n;
      col += graph::kDx[d];
      row += graph::kDy[d];
    }
    return std::max(n, 1);
  }

  std::vector<Opening> openings(const std::vector<CellIndex>& walk) const {
    std::vector<Opening> out;
    // entries=parent: one opening a leaf (a set, not an array the size of the map: a room's walk
    // is small and there may be hundreds of them)
    std::unordered_set<std::size_t> entered;
    for (std::size_t i = 0; i + 1 < walk.size(); ++i) {
      const CellIndex a = walk[i], b = walk[i + 1];
      if (a.col / 2 != b.col / 2 || a.row / 2 != b.row / 2) continue;
      int dir = -1;
      for (int d = 0; d < 4; ++d)
        if (b.col - a.col == graph::kDx[d] && b.row - a.row == graph::kDy[d]) dir = d;
      if (dir < 0) continue;
      const int right = (dir + 3) & 3;
      // both cells on the mega-cell's side that faces `right`
      const int na = (a.col + graph::kDx[right]) / 2, ma = (a.row + graph::kDy[right]) / 2;
      if (a.col + graph::kDx[right] < 0 || a.row + graph::kDy[right] < 0 || (na == a.col / 2 && ma == a.row / 2)) continue;
      const int lc = a.col / 2 + graph::kDx[right], lr = a.row / 2 + graph::kDy[right];
      if (!cells_.insideMega(lc, lr) || cells_.mega(lc, lr) == CellState::kFree) continue;
      if (!every_ && !entered.insert(megaIndex(lc, lr)).second) continue;
      out.push_back({i, dir, lc, lr, throughRuns_ ? runFrom(lc, lr, right) : 1});
    }
    return out;
  }

  /// The sweeps of the openings; offline also `innerClear`: whether each sweep's pieces other than
  /// its first and last (which insert() trims to the path) keep the disc clear, checked exactly on
  /// ctx.threads threads (insert() checks the rest; empty online, where insert() checks all).
  /// Offline: each sweep clipped from the C-obstacle pieces near its rectangle
  /// (CSpace::localSweeps): no C-space of the whole map, a cost linear in the sweeps; and whether
  /// each one's inner pieces are exactly clear (checkInner).
  std::vector<CSpace::Sweep> offlineSweeps(const std::vector<CSpace::SweepRequest>& requests, std::vector<std::uint8_t>& innerClear) {
    const Rational r = ctx_.problem.robots.at(0).radius;
    std::vector<CSpace::Sweep> out =
        CSpace::localSweeps(ctx_.problem.workspace, Rational(r + slackOf(ctx_.problem.workspace)), requests, 1e-6, ctx_.threads, trace_);
    innerClear = checkInner(out);
    return out;
  }

  std::vector<CSpace::Sweep> contours(const std::vector<CellIndex>& walk, const std::vector<Opening>& open,
                                      std::vector<std::uint8_t>& innerClear) {
    std::vector<CSpace::SweepRequest> requests;
    requests.reserve(open.size());
    for (const Opening& o : open) requests.push_back(requestOf(cells_, walk, o));
    if (!sensor_) return offlineSweeps(requests, innerClear);
    // Online (Algorithm 2, step 2.4.1): the robot reaches each opening in walk order, senses its
    // mega-cell and the leaf, and each further mega-cell of a run from the one before as the
    // contour reaches it; the sweep is made from the obstacles reported so far (OnlineSweeper).
    std::vector<CSpace::Sweep> out;
    out.reserve(open.size());
    auto learn = [&](const std::vector<ObstacleSensor::RingRef>& rings) {
      for (const ObstacleSensor::RingRef& g : rings) sweeper_->addRing(g.region, g.ring);
    };
    for (std::size_t j = 0; j < open.size(); ++j) {
      const Opening& o = open[j];
      const int right = (o.dir + 3) & 3;
      int col = walk[o.move].col / 2, row = walk[o.move].row / 2;
      sensor_->moveTo(col, row);
      learn(sensor_->sense(col, row));
      for (int c = 0; c < o.run; ++c) {
        const int next = o.leafCol + c * graph::kDx[right], nextRow = o.leafRow + c * graph::kDy[right];
        sensor_->moveTo(col, row);
        learn(sensor_->sense(next, nextRow));
        col = next;
        row = nextRow;
      }
      out.push_back(sweeper_->sweep(requests[j]));
    }
    return out;
  }

  /// For each sweep, whether its pieces between the first and the last are exactly clear: the
  /// sweeps in contiguous blocks of at least 16, one per thread, each block with its own checker
  /// (one block: the tour's). The verdicts are the exact test's, whatever the thread count.
  std::vector<std::uint8_t> checkInner(const std::vector<CSpace::Sweep>& sweeps) {
    std::vector<std::uint8_t> ok(sweeps.size(), 1);
    const std::size_t blocks = std::min<std::size_t>(detail::threadCount(ctx_.threads), std::max<std::size_t>(1, sweeps.size() / 16));
    detail::parallelFor(blocks, ctx_.threads, [&](std::size_t b) {
      std::optional<ClearanceChecker> own;
      if (blocks > 1) own.emplace(ctx_.problem.workspace, ctx_.problem.robots.at(0).radius);
      ClearanceChecker& check = own ? *own : check_;
      for (std::size_t j = sweeps.size() * b / blocks; j < sweeps.size() * (b + 1) / blocks; ++j) {
        const std::vector<PathSegment>& p = sweeps[j].pieces;
        for (std::size_t i = 1; ok[j] && i + 1 < p.size(); ++i) ok[j] = pieceClear(check, p[i]);
      }
    });
    return ok;
  }

  static std::array<int, 4> runKey(const Opening& o) {
    const int right = (o.dir + 3) & 3, vertical = graph::kDx[right] == 0;
    const int at = vertical ? o.leafRow : o.leafCol, end = at + (o.run - 1) * (vertical ? graph::kDy[right] : graph::kDx[right]);
    return {vertical, vertical ? o.leafCol : o.leafRow, std::min(at, end), std::max(at, end)};
  }

  bool clear(const PathSegment& p) { return pieceClear(check_, p); }

  /// Lines through the points, a straight run (on one axis) one line.
  static std::vector<PathSegment> mergedLines(const std::vector<PointD>& way) {
    std::vector<PathSegment> out;
    for (std::size_t i = 1; i < way.size(); ++i) {
      if (!out.empty()) {
        PathSegment& last = out.back();
        const bool sameX = last.from.x == last.to.x && last.to.x == way[i].x, sameY = last.from.y == last.to.y && last.to.y == way[i].y;
        const bool onward = (last.to.x - last.from.x) * (way[i].x - last.to.x) + (last.to.y - last.from.y) * (way[i].y - last.to.y) > 0;
        if ((sameX || sameY) && onward) {
          last.to = way[i];
          continue;
        }
      }
      out.push_back(PathSegment::line(way[i - 1], way[i]));
    }
    return out;
  }

  /// The walk's sub-cell centres as lines.
  std::vector<PathSegment> linesThrough(const std::vector<CellIndex>& walk) const {
    std::vector<PointD> way;
    way.reserve(walk.size());
    for (const CellIndex& c : walk) way.push_back(cells_.subCenterD(c.col, c.row));
    return mergedLines(way);
  }

  /// The cell grid's box, in doubles.
  BoxD mapBox() const {
    const PointD a = cells_.subCenterD(0, 0), b = cells_.subCenterD(cells_.subCols() - 1, cells_.subRows() - 1);
    const double h = cells_.subSizeD() / 2;
    return {a.x - h, a.y - h, b.x + h, b.y + h};
  }

  static int dirOf(CellIndex a, CellIndex b) {
    for (int d = 0; d < 4; ++d)
      if (b.col - a.col == graph::kDx[d] && b.row - a.row == graph::kDy[d]) return d;
    return -1;
  }

  /// Which sweeps to make (detours=needed). A sweep whose two lanes go straight on from the tour's
  /// moves before and after it (the end of a branch facing the leaf) replaces the tour's turn by the
  /// contour and adds no corner: always made. So is one that may reach a pocket. Every other sweep
  /// leaves the tour and comes back, two more corners and 180° more turning, and is made only when
  /// what it would sweep is not swept already, by the tour or the sweeps taken before it (about
  /// r² of it, estimated in doubles: it decides only which sweeps are made; each is checked exactly).
  std::vector<std::uint8_t> chosen(const std::vector<CellIndex>& walk, const std::vector<Opening>& open,
                                   const std::vector<CSpace::Sweep>& sweeps, const Path& path) const {
    std::vector<std::uint8_t> take(open.size(), 1);
    if (!needed_) return take;
    const double r = ctx_.problem.robots.at(0).radius.get_d();
    // the index covers the sweeps' box (every point it is asked about lies within r of a sweep):
    // a room's tour asks about the room, not the map
    BoxD box{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
             std::numeric_limits<double>::lowest()};
    for (const CSpace::Sweep& sw : sweeps)
      for (const PathSegment& p : sw.pieces) {
        const BoxD q = boundsOf(p);
        box = {std::min(box.xmin, q.xmin), std::min(box.ymin, q.ymin), std::max(box.xmax, q.xmax), std::max(box.ymax, q.ymax)};
      }
    if (!(box.xmin <= box.xmax)) return take;   // no sweep: nothing to choose
    CoverIndex index(r, box);
    for (const PathSegment& p : path.segments) index.add(p);
    for (const PathSegment& p : precovered_) index.add(p);
    std::vector<std::size_t> detours;
    for (std::size_t j = 0; j < open.size(); ++j) {
      const Opening& o = open[j];
      const CSpace::Sweep& sw = sweeps[j];
      if (!sw.reached || sw.pieces.empty()) continue;
      const int right = (o.dir + 3) & 3, i = static_cast<int>(o.move);
      const bool in = i > 0 && dirOf(walk[o.move - 1], walk[o.move]) == right;
      const bool out = o.move + 2 < walk.size() && dirOf(walk[o.move + 1], walk[o.move + 2]) == ((right + 2) & 3);
      const int zc = o.leafCol + o.run * graph::kDx[right], zr = o.leafRow + o.run * graph::kDy[right];
      const bool pocket = pockets_ && sw.farSide && cells_.insideMega(zc, zr) && cells_.mega(zc, zr) == CellState::kFree &&
                          !inTree_[megaIndex(zc, zr)];
      if ((in && out) || pocket) {
        for (const PathSegment& p : sw.pieces) index.add(p);
      } else {
        detours.push_back(j);
      }
    }
    for (std::size_t j : detours) {
      if (index.uncovered(sweeps[j].pieces) >= r * r) {
        for (const PathSegment& p : sweeps[j].pieces) index.add(p);
      } else {
        take[j] = 0;
      }
    }
    return take;
  }

  /// Each opening's move is part of one axis-parallel segment of the path (runs are merged, or cut
  /// near obstacles); the sweep replaces the part of it between its entry and exit.
  void insert(const std::vector<CellIndex>& walk, const std::vector<Opening>& open, const std::vector<CSpace::Sweep>& sweeps,
              const std::vector<std::uint8_t>& innerClear, Path& path) {
    std::vector<PathSegment> out;
    out.reserve(path.segments.size());
    std::size_t k = 0;  // next segment of `path` not yet copied
    const double tol = 1e-9 * std::max(1.0, cells_.subSizeD() * std::max(cells_.megaCols(), cells_.megaRows()));
    const std::vector<std::uint8_t> take = chosen(walk, open, sweeps, path);
    for (std::size_t j = 0; j < open.size(); ++j) {
      const CSpace::Sweep& s = sweeps[j];
      const Opening& o = open[j];
      traced_ += s.traced;
      if (!s.reached || s.pieces.empty()) {
        ++unreached_;
        continue;
      }
      if (!take[j]) {
        ++skipped_;
        continue;
      }
      // a run swept end to end from one side (along U's far side) is not swept again from its other end
      if (o.run > 1 && runsDone_.count(runKey(o))) {
        ++shared_;
        continue;
      }
      const bool horizontal = o.dir == 0 || o.dir == 2;
      const double sign = (o.dir == 0 || o.dir == 1) ? 1 : -1;
      const PointD A = cells_.subCenterD(walk[o.move].col, walk[o.move].row);
      auto alongOf = [&](PointD p) { return sign * (horizontal ? p.x : p.y); };
      auto fixedOf = [&](PointD p) { return horizontal ? p.y : p.x; };
      // the segment (current remainder first) holding the move
      std::size_t at = k;
      for (; at < path.segments.size(); ++at) {
        const PathSegment& seg = path.segments[at];
        const bool axis = seg.kind == PathSegment::Kind::kLine && (horizontal ? seg.from.y == seg.to.y : seg.from.x == seg.to.x);
        if (axis && std::abs(fixedOf(seg.from) - fixedOf(A)) <= tol && alongOf(seg.to) > alongOf(seg.from) &&
            alongOf(s.entry) >= alongOf(seg.from) - tol && alongOf(s.exit) <= alongOf(seg.to) + tol)
          break;
      }
      if (at == path.segments.size()) {
        ++rejected_;
        continue;
      }
      // copy the segments before, then split this one (its start may be the exit of an earlier sweep)
      for (; k < at; ++k) out.push_back(path.segments[k]);
      const PathSegment cur = path.segments[at];
      auto onSeg = [&](PointD p) {
        const double c = sign * std::min(std::max(alongOf(p), alongOf(cur.from)), alongOf(cur.to));
        return horizontal ? PointD{c, cur.from.y} : PointD{cur.from.x, c};
      };
      const PointD pe = onSeg(s.entry), pw = onSeg(s.exit);
      std::vector<PathSegment> pieces = s.pieces;
      pieces.front().from = pe;
      pieces.back().to = pw;
      bool ok = alongOf(pe) <= alongOf(pw);
      const bool inner = !innerClear.empty();  // the pieces between the first and the last are checked
      if (inner) ok = ok && innerClear[j];
      for (std::size_t i = 0; ok && i < pieces.size(); ++i)
        if (!inner || i == 0 || i + 1 == pieces.size()) ok = clear(pieces[i]);
      if (!ok) {
        ++rejected_;
        continue;
      }
      if (o.run > 1 && s.farSide) runsDone_.insert(runKey(o));
      const int right = (o.dir + 3) & 3;
      for (int c = 0; c < o.run; ++c) {
        const int col = o.leafCol + c * graph::kDx[right], row = o.leafRow + c * graph::kDy[right];
        if (cells_.mega(col, row) == CellState::kPartial) swept_[megaIndex(col, row)] = 1;
      }
      if (pockets_ && s.farSide) joinPocket(walk, o, pieces);
      if (!(pe.x == cur.from.x && pe.y == cur.from.y)) out.push_back(PathSegment::line(cur.from, pe));
      for (const PathSegment& p : pieces) {
        arcs_ += p.kind == PathSegment::Kind::kArc;
        out.push_back(p);
      }
      ++inserted_;
      // the rest of the segment stays to be copied (or split again)
      path.segments[at].from = pw;
      k = at;
      if (pw.x == cur.to.x && pw.y == cur.to.y) ++k;
    }
    for (; k < path.segments.size(); ++k) out.push_back(path.segments[k]);
    path.segments.swap(out);
  }

  /// A pocket: free mega-cells that no tour covers, beyond a run swept end to end. Its own tree is
  /// toured from the sub-cell on the sweep's right lane round to the one on its left lane (as if the
  /// run were a tree edge), and that tour replaces the sweep's pieces along U's far side: up the
  /// right lane into the pocket, round it, down the left lane. The two joining lines are checked
  /// exactly; when one fails, or the pocket's walk cannot be placed, the pocket stays out.
  void joinPocket(const std::vector<CellIndex>& walk, const Opening& o, std::vector<PathSegment>& pieces) {
    const int right = (o.dir + 3) & 3, dx = graph::kDx[right], dy = graph::kDy[right];
    const int zc = o.leafCol + o.run * dx, zr = o.leafRow + o.run * dy;
    if (!cells_.insideMega(zc, zr) || cells_.mega(zc, zr) != CellState::kFree || inTree_[megaIndex(zc, zr)]) return;
    const CellIndex a = walk[o.move], d = walk[o.move + 1];
    // the pocket's sub-cells next to the run, on the lanes of a and d
    const CellIndex zR = dx == 0 ? CellIndex{a.col, 2 * zr + (dy < 0)} : CellIndex{2 * zc + (dx < 0), a.row};
    const CellIndex zL = dx == 0 ? CellIndex{d.col, zR.row} : CellIndex{zR.col, d.row};
    std::vector<CellIndex> pw = pocketWalk_(zR);
    if (pw.size() < 3 || !(pw.front() == zR) || !(pw.back() == zR) || !(pw[pw.size() - 2] == zL)) {
      ++pocketsLeft_;
      return;
    }
    pw.pop_back();
    // the far side of U, in doubles, and the pieces along it
    const PointD ad = cells_.subCenterD(a.col, a.row);
    const double farAt = (dx == 0 ? ad.y : ad.x) + (dx + dy) * 2.0 * o.run * cells_.subSizeD();
    const double tol = 1e-9 * std::max(1.0, std::abs(farAt));
    auto onFar = [&](const PathSegment& p) {
      return p.kind == PathSegment::Kind::kLine && std::abs((dx == 0 ? p.from.y : p.from.x) - farAt) <= tol &&
             std::abs((dx == 0 ? p.to.y : p.to.x) - farAt) <= tol;
    };
    std::size_t f1 = pieces.size(), f2 = 0;
    for (std::size_t i = 0; i < pieces.size(); ++i)
      if (onFar(pieces[i])) f1 = std::min(f1, i), f2 = i;
    if (f1 == pieces.size()) {
      ++pocketsLeft_;
      return;
    }
    std::vector<std::size_t> marked;
    for (const CellIndex& c : pw)
      if (!inTree_[megaIndex(c.col / 2, c.row / 2)]) marked.push_back(megaIndex(c.col / 2, c.row / 2)), inTree_[marked.back()] = 1;
    PlacedWalk placed = placeWalk(ctx_, pw, cells_.subCenter(zR.col, zR.row), false);
    const PointD F1 = pieces[f1].from, F2 = pieces[f2].to;
    bool ok = placed.unsafeCells.empty() && placed.startClear && !placed.path.segments.empty();
    PathSegment up, down;
    if (ok) {
      up = PathSegment::line(F1, placed.path.segments.front().from);
      down = PathSegment::line(placed.path.segments.back().to, F2);
      ok = clear(up) && clear(down);
    }
    if (!ok) {
      for (std::size_t m : marked) inTree_[m] = 0;
      ++pocketsLeft_;
      return;
    }
    tour(pw, placed.path);  // the pocket's own sweeps (and pockets)
    std::vector<PathSegment> joined(pieces.begin(), pieces.begin() + static_cast<std::ptrdiff_t>(f1));
    joined.push_back(up);
    joined.insert(joined.end(), placed.path.segments.begin(), placed.path.segments.end());
    joined.push_back(down);
    joined.insert(joined.end(), pieces.begin() + static_cast<std::ptrdiff_t>(f2) + 1, pieces.end());
    pieces.swap(joined);
    ++pocketsJoined_;
  }


  /// Rooms (rooms=travel): free mega-cells that no tour reaches, where partially occupied mega-cells
  /// cut them off and no sweep crossed to them (a room behind a door narrower than a mega-cell or
  /// not in line with a lane). A breadth-first search over free sub-cells, from every sub-cell
  /// whose centre the path passes, finds the nearest sub-cell e of such a mega-cell; the robot
  /// leaves the path there, goes to e from centre to centre (each move stays in the union of two
  /// free sub-cells, which holds the disc, and is checked exactly), tours the room's own tree with
  /// its sweeps (and pockets) from e back to e, and returns the same way. The search goes on; a
  /// room toured is in a tree, so it is entered once. Which sub-cells start the search, and the
  /// order, follow the path: the plan is the same every time. A door of a scan turned against the
  /// map's axes holds no chain of free sub-cells: when the lanes find no room, the search starts
  /// from the path's joints too (travelPass with `joints`), which the contour passes bring through
  /// every door of the start's component.
public:
  /// An excursion decided in a pass: the way there and back, and the room's walk and tour (whose
  /// sweeps are made for all the pass's rooms at once).
  struct Excursion {
    std::size_t segment;
    PointD at;
    std::vector<PathSegment> there, back;
    std::vector<CellIndex> walk;
    Path tour;
    bool room;
    int joint = -1;                    ///< the sub-cell a joint's line goes to, else -1
    std::vector<std::size_t> marked;   ///< the mega-cells the room's walk put in a tree
  };

  struct Source {
    std::size_t segment;
    PointD at;
    bool joint = false;   ///< at the end of the segment, off the sub-cells' centres (a way's first line leaves it obliquely)
  };

  /// `gaps`: leave, visit, or auto (visit only the groups that hold a pinched sub-cell, markGaps).
  void travel(Path& path, const std::string& gaps) {
    std::vector<std::uint8_t> failed(cells_.megaCount(), 0);
    bool rooms = false;   // a free mega-cell outside every tree: else no search
    for (int row = 0; row < cells_.megaRows() && !rooms; ++row)
      for (int col = 0; col < cells_.megaCols() && !rooms; ++col)
        rooms = cells_.mega(col, row) == CellState::kFree && !inTree_[megaIndex(col, row)];
    // a room whose every way from the lanes is blocked (a door off the sub-cell grid: a scan not
    // aligned with the map's axes) is looked for again from the path's joints
    while (rooms && (travelPass(path, failed, false, false) || (unreachedRooms_ && travelPass(path, failed, false, true)))) {
    }
    if (gaps == "leave") return;
    markGaps(path, gaps == "auto");
    if (std::find(gap_.begin(), gap_.end(), std::uint8_t{1}) == gap_.end()) return;
    while (travelPass(path, failed, true, false)) {
    }
  }

  /// Rooms online (smooth_stc_online, rooms=travel): what the offline rooms pass does, from what the
  /// robot knows when it is where it leaves its path. As it goes, the robot senses the mega-cell it
  /// is in and the four beside it (the obstacle sensor, which throws on any other question); it
  /// knows a sub-cell's state only in a mega-cell it has sensed (the rings reported there decide
  /// it; it is read from the cell grid, which holds what those rings give). A pass is the offline
  /// one (travelPass) with each way held to what the robot knew before the piece of the path it
  /// leaves from: the search goes from a source on piece k only into mega-cells sensed before piece
  /// k (knownAt_), so a room is entered from the path only after the robot came near it. What no
  /// pass reaches (a room the robot learnt of only after its last source near it) is looked for
  /// from where the path ends, the robot's last position, with all it knows (endSearch).
  /// Decision: a room learnt of late is reached from the end of the path, by a longer way, rather
  /// than from a point the robot had passed before it knew of the room. `explore`: the gaps and
  /// frontiers from the end as well (endSearch); off where the contour passes are (a map of more
  /// than 20,000 vertices under contours=auto), as each search from the end walks the known free
  /// sub-cells: on a 10^6-cell map hundreds of trips would cost minutes.
  void travelOnline(Path& path, bool explore) {
    if (failedOnline_.empty()) failedOnline_.assign(cells_.megaCount(), 0);
    // a known free mega-cell in no tree (else no search)
    auto roomKnown = [&] {
      for (int row = 0; row < cells_.megaRows(); ++row)
        for (int col = 0; col < cells_.megaCols(); ++col) {
          const std::size_t m = megaIndex(col, row);
          if (cells_.mega(col, row) == CellState::kFree && !inTree_[m] && !failedOnline_[m] && knownAt_[m] != std::numeric_limits<std::size_t>::max())
            return true;
        }
      return false;
    };
    senseAll(path);
    while (roomKnown() && travelPass(path, failedOnline_, false, false)) senseAll(path);   // ways inserted within the path: sensed again in order
    // then from the end, with all the robot knows (each search senses what it appends): every room
    // known from a sub-cell the end is joined to through known free sub-cells
    while ((explore || roomKnown()) && endSearch(path, explore)) {
    }
  }

  /// Online: every mega-cell that box b (clamped to the grid, grown by a millionth of a sub-cell)
  /// overlaps was sensed before piece `when` began (knownAt_, from senseAll; `when` = the number
  /// of pieces: sensed at all). The sensor reports every ring that comes into a sensed mega-cell, so
  /// then the robot knows every obstacle edge in b.
  bool knownBefore(const BoxD& b, std::size_t when) const {
    const double m = 2 * cells_.subSizeD(), ox = cells_.originX().get_d(), oy = cells_.originY().get_d(), e = 1e-6 * cells_.subSizeD();
    auto idx = [&](double v, double o, int n) { return std::min(n - 1, std::max(0, static_cast<int>(std::floor((v - o) / m)))); };
    for (int row = idx(b.ymin - e, oy, cells_.megaRows()); row <= idx(b.ymax + e, oy, cells_.megaRows()); ++row)
      for (int col = idx(b.xmin - e, ox, cells_.megaCols()); col <= idx(b.xmax + e, ox, cells_.megaCols()); ++col)
        if (knownAt_[megaIndex(col, row)] > when) return false;
    return true;
  }

  /// The robot senses along the whole path, in order: knownAt_[m] is 1 + the first piece along
  /// which it sensed mega-cell m (what is known before piece k began: knownAt_ ≤ k).
  void senseAll(const Path& path) {
    knownAt_.assign(cells_.megaCount(), std::numeric_limits<std::size_t>::max());
    sensedFrom_.assign(cells_.megaCount(), 0);
    asked_.resize(cells_.megaCount(), 0);
    for (std::size_t k = 0; k < path.segments.size(); ++k) senseAlong(path.segments[k], k + 1);
  }

  /// From the end of the path, with all the robot knows: the nearest sub-cell of a known free
  /// mega-cell in no tree, over known free sub-cells, the first step never back the way the path
  /// came (a reversal); the way there and the room's tour are appended (the robot goes on from
  /// there). Returns whether a room was toured.
  /// With no room known, the nearest pinched gap it knows (gaps=auto: a free sub-cell the path
  /// leaves uncovered, squeezed between edges on two opposite sides, a corridor exactly 2r wide;
  /// markGaps): the way there and its group of gaps depth-first (each next sub-cell beside the
  /// robot's, so in a mega-cell it has sensed; none in a free mega-cell, a room), as far as its
  /// moves are exactly clear, ending at the last new one (`gaps_visited`); a group of one is left,
  /// as offline. With neither, the robot explores: it goes to the nearest known free sub-cell from
  /// which it would sense a mega-cell it has not (a frontier: one beside that sub-cell's
  /// mega-cell; the 16 nearest tried, nearest first, until one's way is exactly clear), and searches
  /// again from there (`frontier_trips`). After a gap's walk or a frontier trip the first step may
  /// go back the way it came: it most likely ended in a dead end, which is left only so.
  /// Decision: the offline rooms pass reaches free mega-cells behind corridors exactly 2r wide (a
  /// grid map's one-pixel passages at r of half a pixel), whose mega-cells are all partially
  /// occupied, so the tour never comes near what lies beyond; an online robot that only toured the
  /// rooms it had sensed left them (a maze at r = 0.5 covered 0.76 against offline's 0.98). Each
  /// trip senses at least one new mega-cell and each walk takes its gaps, so they end.
  bool endSearch(Path& path, bool explore) {
    const int sc = cells_.subCols();
    const std::size_t now = path.segments.size();
    auto knownFree = [&](int c, int r) {
      return cells_.insideSub(c, r) && knownAt_[megaIndex(c / 2, r / 2)] <= now && cells_.sub(c, r) == CellState::kFree;
    };
    std::optional<CoverIndex> cover;   // for the gaps alone
    if (explore && onlineGaps_) cover.emplace(coverIndexOf(path));
    // the path ends where a gap's walk or a frontier trip ended (a dead end, most likely)
    const bool mayReverse = detourEnd_ == path.segments.size();
    if (failedGapOnline_.size() != cells_.subCount()) failedGapOnline_.assign(cells_.subCount(), 0);
    for (;;) {
      if (path.segments.empty()) return false;
      const PointD at = path.segments.back().to, heading = unitHeading(path.segments.back(), true);
      CellIndex s;
      if (!cells_.locateSubD(at, s) || !knownFree(s.col, s.row)) return false;
      const int start = s.row * sc + s.col;
      std::vector<int> parent(cells_.subCount(), -2), queue{start};
      parent[static_cast<std::size_t>(start)] = -1;
      int found = -1, gap = -1;
      std::vector<int> frontiers;   // in the search's order: nearest first
      auto unsensedBeside = [&](int col, int row) {
        for (int d = 0; d < 4; ++d) {
          const int mc = col / 2 + graph::kDx[d], mr = row / 2 + graph::kDy[d];
          if (cells_.insideMega(mc, mr) && knownAt_[megaIndex(mc, mr)] > now) return true;
        }
        return false;
      };
      for (std::size_t head = 0; head < queue.size() && found < 0; ++head) {
        const int v = queue[head], col = v % sc, row = v / sc;
        const std::size_t m = megaIndex(col / 2, row / 2);
        if (v != start && cells_.mega(col / 2, row / 2) == CellState::kFree && !inTree_[m] && !failedOnline_[m]) {
          found = v;
          break;
        }
        if (explore && v != start && frontiers.size() < kFrontiersTried && unsensedBeside(col, row)) frontiers.push_back(v);
        if (explore && onlineGaps_ && gap < 0 && v != start && !failedGapOnline_[static_cast<std::size_t>(v)] && gapAt(*cover, col, row) && pinched(v)) gap = v;
        for (int d = 0; d < 4; ++d) {
          const int c = col + graph::kDx[d], r = row + graph::kDy[d];
          if (!knownFree(c, r) || parent[static_cast<std::size_t>(r * sc + c)] != -2) continue;
          if (v == start && !mayReverse) {   // the first move: from `at` to the start's centre, then to (c, r)
            const PointD q = cells_.subCenterD(c, r);
            const double dx = q.x - at.x, dy = q.y - at.y, n = std::hypot(dx, dy);
            if (n > 0 && (heading.x * dx + heading.y * dy) / n < kReversalCos) continue;
          }
          parent[static_cast<std::size_t>(r * sc + c)] = v;
          queue.push_back(r * sc + c);
        }
      }
      // the robot goes on along `pieces` (from the path's end), sensing as it goes
      auto append = [&](const std::vector<PathSegment>& pieces) {
        path.segments.insert(path.segments.end(), pieces.begin(), pieces.end());
        for (std::size_t k = now; k < path.segments.size(); ++k) senseAlong(path.segments[k], k + 1);
      };
      auto allClear = [&](const std::vector<PathSegment>& pieces) {
        return !pieces.empty() && std::all_of(pieces.begin(), pieces.end(), [&](const PathSegment& p) { return clear(p); });
      };
      // the way from `at` to sub-cell t over the search's chain, straight runs merged (none where
      // the robot stands at t's centre already)
      auto wayTo = [&](int t) {
        std::vector<int> chain{t};
        while (parent[static_cast<std::size_t>(chain.back())] >= 0) chain.push_back(parent[static_cast<std::size_t>(chain.back())]);
        std::vector<PointD> way{at};
        for (std::size_t i = chain.size(); i-- > 0;) way.push_back(cells_.subCenterD(chain[i] % sc, chain[i] / sc));
        std::vector<PathSegment> there = mergedLines(way);
        while (!there.empty() && there.front().length() <= 1e-9 * cells_.subSizeD()) there.erase(there.begin());
        return there;
      };
      if (found < 0 && gap >= 0) {   // a pinched gap (a corridor exactly 2r wide): there, and its group depth-first
        // its group: the gaps 4-connected to it, none in a free mega-cell (a room, toured with its
        // own tree once found: next search)
        gap_.assign(cells_.subCount(), 0);
        groupOf(gap, 1, [&](int c, int rr) {
          return !gap_[static_cast<std::size_t>(rr) * sc + c] && cells_.mega(c / 2, rr / 2) != CellState::kFree && gapAt(*cover, c, rr);
        });
        std::vector<CellIndex> pw = gapWalk(gap);
        if (pw.size() < 2) {   // a niche of one sub-cell, left as offline
          failedGapOnline_[static_cast<std::size_t>(gap)] = 1;
          continue;
        }
        // the walk ends at its last new sub-cell (the robot goes on from there, not back)
        std::size_t last = 0;
        std::set<std::pair<int, int>> seen;
        for (std::size_t i = 0; i < pw.size(); ++i)
          if (seen.insert({pw[i].col, pw[i].row}).second) last = i;
        pw.resize(last + 1);
        std::vector<PathSegment> there = wayTo(gap);
        if (!allClear(there)) {
          for (const CellIndex& c : pw) failedGapOnline_[static_cast<std::size_t>(c.row) * sc + c.col] = 1;
          ++gapsLeft_;
          continue;
        }
        // the walk as far as its moves are exactly clear (checked as the robot comes to them)
        for (const PathSegment& p : linesThrough(pw)) {
          if (!clear(p)) break;
          there.push_back(p);
        }
        append(there);
        ++gapsJoined_;
        detourEnd_ = path.segments.size();
        return true;
      }
      if (found < 0) {   // explore: the way to the nearest frontier whose way is exactly clear, sensing as it goes
        for (int frontier : frontiers) {
          std::vector<PathSegment> there = wayTo(frontier);
          if (!allClear(there)) continue;
          append(there);
          ++frontierTrips_;
          detourEnd_ = path.segments.size();
          return true;
        }
        return false;
      }
      const CellIndex ec{found % sc, found / sc};
      const std::size_t room = megaIndex(ec.col / 2, ec.row / 2);
      std::vector<PathSegment> there = wayTo(found);
      std::vector<CellIndex> pw = pocketWalk_(ec);
      bool ok = pw.size() >= 3 && pw.front() == ec && pw.back() == ec && !there.empty();
      std::vector<std::size_t> marked;
      PlacedWalk placed;
      if (ok) {
        placed = placeRoom(pw, ec, marked);
        ok = placed.unsafeCells.empty() && placed.startClear && !placed.path.segments.empty();
      }
      if (ok) {
        joinWay(there, placed.path.segments);
        ok = allClear(there);
      }
      if (!ok) {
        for (std::size_t m : marked) inTree_[m] = 0;
        failedOnline_[room] = 1;
        ++roomsLeft_;
        continue;
      }
      tour(pw, placed.path);   // the room's sweeps, made online as the robot reaches them
      there.insert(there.end(), placed.path.segments.begin(), placed.path.segments.end());
      append(there);
      ++roomsJoined_;
      ++roomsFromEnd_;
      return true;
    }
  }

  /// The robot senses, at points along `p` (every sub-cell, half a mega-cell: a mega-cell a piece
  /// only clips at a corner may be missed, which only leaves the robot knowing less), the mega-cell
  /// it is in and the four beside it, once from each mega-cell it passes; what it senses is known
  /// from `when` on. The sensor is asked from a mega-cell only the first time (asked_): a replay of
  /// the path (senseAll, after ways were inserted) recomputes when things became known from what
  /// the robot already heard.
  void senseAlong(const PathSegment& p, std::size_t when) {
    const double len = p.length(), step = cells_.subSizeD();
    const std::size_t n = static_cast<std::size_t>(std::min(1e7, std::ceil(len / step))) + 1;
    for (std::size_t i = 0; i <= n; ++i) {
      CellIndex c;
      if (!cells_.locateSubD(pointAlong(p, len * static_cast<double>(i) / static_cast<double>(n), len), c)) continue;
      const int col = c.col / 2, row = c.row / 2;
      if (sensedFrom_[megaIndex(col, row)] || cells_.mega(col, row) == CellState::kBlocked) continue;
      sensedFrom_[megaIndex(col, row)] = 1;
      const bool ask = !asked_[megaIndex(col, row)];   // a replay (senseAll) remembers the answers
      asked_[megaIndex(col, row)] = 1;
      if (ask) sensor_->moveTo(col, row);
      for (int d = 0; d <= 4; ++d) {
        const int nc = col + (d < 4 ? graph::kDx[d] : 0), nr = row + (d < 4 ? graph::kDy[d] : 0);
        if (!cells_.insideMega(nc, nr)) continue;
        if (ask) sensor_->sense(nc, nr);
        std::size_t& k = knownAt_[megaIndex(nc, nr)];
        k = std::min(k, when);
      }
    }
  }

  /// The path's pieces (and the loops counted before the detours) by bucket.
  CoverIndex coverIndexOf(const Path& path) const {
    CoverIndex index(ctx_.problem.robots.at(0).radius.get_d(), mapBox());
    for (const PathSegment& p : path.segments) index.add(p);
    for (const PathSegment& p : precovered_) index.add(p);
    return index;
  }

  /// A free sub-cell that the path leaves uncovered, a gap: two of five points (the centre and four
  /// at r/2 from it) farther than r from every piece; a tree's mega-cell is toured through every one
  /// of its sub-cells' centres, so none of its sub-cells is.
  bool gapAt(const CoverIndex& index, int col, int row) const {
    if (cells_.sub(col, row) != CellState::kFree || (cells_.mega(col / 2, row / 2) == CellState::kFree && inTree_[megaIndex(col / 2, row / 2)]))
      return false;
    const double r = ctx_.problem.robots.at(0).radius.get_d();
    const PointD c = cells_.subCenterD(col, row);
    int missed = 0;
    for (const PointD& d : {PointD{0, 0}, PointD{r / 2, 0}, PointD{-r / 2, 0}, PointD{0, r / 2}, PointD{0, -r / 2}})
      missed += !index.covered(PointD{c.x + d.x, c.y + d.y});
    return missed >= 2;
  }

  /// Sub-cell v is squeezed between obstacle edges on two opposite sides (markGaps): an edge
  /// within 2(ε + δ) of the middles of both its left and right sides, or of both its bottom and top
  /// (doubles). Those points lie in v's mega-cell's box grown by a sub-cell, whose obstacles the
  /// online robot's sensor reports with the mega-cell.
  bool pinched(int v) {
    if (!pinchedEdges_) pinchedEdges_ = std::make_unique<EdgeIndex>(ctx_.problem.workspace, 2 * slackOf(ctx_.problem.workspace).get_d(), mapBox());
    const double r = ctx_.problem.robots.at(0).radius.get_d();
    const PointD c = cells_.subCenterD(v % cells_.subCols(), v / cells_.subCols());
    const EdgeIndex& edges = *pinchedEdges_;
    return (!edges.clearOf({c.x + r, c.y}) && !edges.clearOf({c.x - r, c.y})) || (!edges.clearOf({c.x, c.y + r}) && !edges.clearOf({c.x, c.y - r}));
  }

  /// Gaps (gaps=visit): free sub-cells that the path, with its rooms, leaves uncovered (two of five
  /// points, the centre and four at r/2 from it, farther than r from every piece: estimated in
  /// doubles, it only chooses where to go). They lie in partially occupied mega-cells that no sweep
  /// reached (between obstacles closer than a mega-cell) or in free ones that none of the trees
  /// holds. Each 4-connected group of them is toured depth-first from the nearest, from centre to
  /// centre (each move in the union of two free sub-cells), as Full-STC goes through a partially
  /// occupied mega-cell; a dead end one sub-cell wide is left the way it was entered.
  /// `pinchedOnly` (gaps=auto): only the groups of at least two sub-cells (a niche of one is worth
  /// less than its reversal) that hold a pinched sub-cell, one squeezed between obstacle edges on
  /// two opposite sides: an edge within 2(ε + δ) of the middles of both its left and right sides,
  /// or of both its bottom and top (doubles; it only chooses where to go). That is a corridor or
  /// door exactly 2r wide (a grid map's one-pixel passage at r of half a
  /// pixel): C-free at r but not at r + ε + δ, the radius of the sweeps and the contour passes, so
  /// no sweep, pass or patch reaches it or what lies behind it. A sub-cell with an edge on one side
  /// only (an obstacle's side on the sub-cell grid) is not pinched: the contour pass runs beside it.
  /// The sub-cells 4-connected to `seed` that `ok(col, row)` accepts, breadth-first from it; each
  /// taken (the seed too) is set to `mark` in gap_, which `ok` reads to pass over those taken.
  template <class Ok>
  std::vector<int> groupOf(int seed, std::uint8_t mark, Ok ok) {
    const int sc = cells_.subCols();
    std::vector<int> group{seed};
    gap_[static_cast<std::size_t>(seed)] = mark;
    for (std::size_t head = 0; head < group.size(); ++head)
      for (int d = 0; d < 4; ++d) {
        const int c = group[head] % sc + graph::kDx[d], rr = group[head] / sc + graph::kDy[d];
        if (!cells_.insideSub(c, rr) || !ok(c, rr)) continue;
        gap_[static_cast<std::size_t>(rr) * sc + c] = mark;
        group.push_back(rr * sc + c);
      }
    return group;
  }

  void markGaps(const Path& path, bool pinchedOnly) {
    const CoverIndex index = coverIndexOf(path);
    gap_.assign(cells_.subCount(), 0);
    for (int row = 0; row < cells_.subRows(); ++row)
      for (int col = 0; col < cells_.subCols(); ++col) gap_[static_cast<std::size_t>(row) * cells_.subCols() + col] = gapAt(index, col, row);
    if (!pinchedOnly) return;
    const int sc = cells_.subCols();
    std::vector<std::uint8_t> keep(gap_.size(), 0);
    for (std::size_t k = 0; k < gap_.size(); ++k) {
      if (gap_[k] != 1) continue;   // 2: in a group seen
      const std::vector<int> group = groupOf(static_cast<int>(k), 2, [&](int c, int rr) { return gap_[static_cast<std::size_t>(rr) * sc + c] == 1; });
      if (group.size() >= 2 && std::any_of(group.begin(), group.end(), [&](int v) { return pinched(v); }))   // a niche of one: a reversal for 4r²
        for (int v : group) keep[static_cast<std::size_t>(v)] = 1;
    }
    gap_.swap(keep);
  }

  /// The closed depth-first walk over the group of gaps holding t, from t back to t; the group's
  /// gaps are taken.
  std::vector<CellIndex> gapWalk(int t) {
    const int sc = cells_.subCols();
    std::vector<CellIndex> walk{{t % sc, t / sc}};
    std::vector<std::pair<int, int>> stack{{t, 0}};
    gap_[static_cast<std::size_t>(t)] = 0;
    while (!stack.empty()) {
      const int v = stack.back().first, d = stack.back().second;
      if (d == 4) {
        stack.pop_back();
        if (!stack.empty()) walk.push_back({stack.back().first % sc, stack.back().first / sc});
        continue;
      }
      ++stack.back().second;
      const int c = v % sc + graph::kDx[d], r = v / sc + graph::kDy[d];
      if (!cells_.insideSub(c, r) || !gap_[static_cast<std::size_t>(r) * sc + c]) continue;
      gap_[static_cast<std::size_t>(r) * sc + c] = 0;
      walk.push_back({c, r});
      stack.push_back({r * sc + c, 0});
    }
    return walk;
  }

  /// One pass: every room found is toured unless its way leaves the path from the same sub-cell
  /// by the same first step as one toured before in this pass (coming back from one and going out
  /// to the other would reverse on the spot); the next pass finds it from the ways and rooms added.
  /// Returns whether a room was toured. With `joints` the ways may also leave the path at a joint
  /// (the end of a piece, a line or an arc, so that no piece is split) by a straight line to a free
  /// sub-cell's centre within 2D (checked exactly, as every way is), making a turn of at most 150°
  /// there and coming back: the contour passes go through every door of the start's component,
  /// also the doors no chain of free sub-cells passes.
  bool travelPass(Path& path, std::vector<std::uint8_t>& failed, bool gaps, bool joints) {
    const int sc = cells_.subCols(), sr = cells_.subRows();
    const double D = cells_.subSizeD(), tol = 1e-9 * std::max(1.0, D * std::max(sc, sr));
    auto index = [&](int c, int r) { return static_cast<std::size_t>(r) * sc + c; };
    // the sub-cells whose centre the path passes, with the segment and the point
    std::vector<std::int64_t> sourceOf(cells_.subCount(), -1);
    std::vector<Source> sources;
    std::vector<int> queue;
    auto addSource = [&](PointD p, std::size_t k) {
      CellIndex c;
      if (!cells_.locateSubD(p, c) || cells_.sub(c.col, c.row) != CellState::kFree) return;
      const PointD q = cells_.subCenterD(c.col, c.row);
      if (std::abs(q.x - p.x) > tol || std::abs(q.y - p.y) > tol) return;
      if (const std::int64_t was = sourceOf[index(c.col, c.row)]; was >= 0) {
        // online, a sub-cell the path passes again is left from its last pass, when the robot knows most
        if (sensor_) sources[static_cast<std::size_t>(was)] = {k, p};
        return;
      }
      sourceOf[index(c.col, c.row)] = static_cast<std::int64_t>(sources.size());
      sources.push_back({k, p});
      queue.push_back(static_cast<int>(index(c.col, c.row)));
    };
    // every centre an axis-parallel line passes through (lanes, and the straight parts of sweeps)
    const PointD c0 = cells_.subCenterD(0, 0);
    for (std::size_t k = 0; k < path.segments.size(); ++k) {
      const PathSegment& g = path.segments[k];
      // axis-parallel up to the rounding of a sweep's ends (an ulp)
      const bool horizontal = std::abs(g.from.y - g.to.y) <= tol, vertical = std::abs(g.from.x - g.to.x) <= tol;
      if (g.kind != PathSegment::Kind::kLine || horizontal == vertical) continue;
      const double fixed = horizontal ? g.from.y : g.from.x, origin = horizontal ? c0.y : c0.x, along0 = horizontal ? c0.x : c0.y;
      const double lane = std::round((fixed - origin) / D);
      if (std::abs(origin + lane * D - fixed) > tol) continue;
      const double a = horizontal ? g.from.x : g.from.y, b = horizontal ? g.to.x : g.to.y;
      const long first = static_cast<long>(std::ceil((std::min(a, b) - along0) / D - 1e-9)), last = static_cast<long>(std::floor((std::max(a, b) - along0) / D + 1e-9));
      for (long i = 0; i <= last - first; ++i) {
        const long c = a <= b ? first + i : last - i;   // in the line's direction
        const double at = std::min(std::max(along0 + static_cast<double>(c) * D, std::min(a, b)), std::max(a, b));
        // on the segment as it is: its end where the centre is one (up to tol), else the point
        // there (the two parts the split makes are checked exactly)
        const double t = a == b ? 0 : (at - a) / (b - a);
        const PointD on = std::abs(at - a) <= tol   ? g.from
                          : std::abs(at - b) <= tol ? g.to
                                                    : PointD{g.from.x + t * (g.to.x - g.from.x), g.from.y + t * (g.to.y - g.from.y)};
        addSource(on, k);
      }
    }
    if (joints) {
      // only towards the free sub-cells no chain from the lanes reaches (the search of the lanes'
      // pass just before, on the same path), each way's first line checked exactly here, so that
      // a blocked one leaves the sub-cell to another joint, and only towards those from which a room is reached (a pocket of free sub-cells among
      // obstacles, with no free mega-cell outside every tree, is no way anywhere: no exact checks)
      std::vector<std::uint8_t> leads(cells_.subCount(), 0);
      std::vector<int> stack;
      for (int row = 0; row < sr; ++row)
        for (int col = 0; col < sc; ++col) {
          const std::size_t m = megaIndex(col / 2, row / 2);
          if (cells_.sub(col, row) != CellState::kFree || laneReached_[index(col, row)] || leads[index(col, row)] || inTree_[m] || failed[m] ||
              cells_.mega(col / 2, row / 2) != CellState::kFree)
            continue;
          leads[index(col, row)] = 1;
          stack.assign(1, static_cast<int>(index(col, row)));
          while (!stack.empty()) {
            const int v = stack.back();
            stack.pop_back();
            for (int d = 0; d < 4; ++d) {
              const int c = v % sc + graph::kDx[d], r = v / sc + graph::kDy[d];
              if (!cells_.insideSub(c, r) || cells_.sub(c, r) != CellState::kFree || leads[index(c, r)]) continue;
              leads[index(c, r)] = 1;   // unreached too: the lanes' chains reach every sub-cell joined to them
              stack.push_back(static_cast<int>(index(c, r)));
            }
          }
        }
      const double reach = 2 * D;
      for (std::size_t k = 0; k + 1 < path.segments.size(); ++k) {
        if (path.segments[k].length() <= tol || path.segments[k + 1].length() <= tol) continue;   // a sliver's heading is noise
        const PointD p = path.segments[k].to;
        const PointD hin = unitHeading(path.segments[k], true), hout = unitHeading(path.segments[k + 1], false);
        CellIndex at;
        if (!cells_.locateSubD(p, at)) continue;
        for (int dr = -2; dr <= 2; ++dr)
          for (int dc = -2; dc <= 2; ++dc) {
            const int c = at.col + dc, r = at.row + dr;
            if (!cells_.insideSub(c, r) || cells_.sub(c, r) != CellState::kFree || !leads[index(c, r)] || sourceOf[index(c, r)] >= 0 ||
                banned_.count({p.x, p.y, static_cast<int>(index(c, r))}))
              continue;
            const PointD q = cells_.subCenterD(c, r);
            const double len = std::hypot(q.x - p.x, q.y - p.y);
            if (len > reach || len <= tol) continue;
            const PointD w{(q.x - p.x) / len, (q.y - p.y) / len};
            if (hin.x * w.x + hin.y * w.y < kReversalCos || -(w.x * hout.x + w.y * hout.y) < kReversalCos) continue;
            if (!clear(PathSegment::line(p, q))) continue;
            sourceOf[index(c, r)] = static_cast<std::int64_t>(sources.size());
            sources.push_back({k, p, true});
            queue.push_back(static_cast<int>(index(c, r)));
          }
      }
    }
    std::vector<int> parent(cells_.subCount(), -2);
    for (int v : queue) parent[static_cast<std::size_t>(v)] = -1;
    // online: the piece each search leaves the path from; it goes only where the robot knew by then
    std::vector<std::size_t> leftFrom;
    if (sensor_) {
      leftFrom.assign(cells_.subCount(), 0);
      for (int v : queue) leftFrom[static_cast<std::size_t>(v)] = sources[static_cast<std::size_t>(sourceOf[static_cast<std::size_t>(v)])].segment;
    }
    // excursions by segment: (where on it, the pieces)
    std::vector<std::vector<std::pair<PointD, std::vector<PathSegment>>>> at(path.segments.size());
    std::set<std::pair<int, int>> leaving;   // (source sub-cell, first step) of the ways taken
    std::vector<Excursion> pending;
    bool any = false;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const int v = queue[head];
      const int col = v % sc, row = v / sc;
      const std::size_t m = megaIndex(col / 2, row / 2);
      const bool target = gaps ? gap_[static_cast<std::size_t>(v)] != 0
                               : !inTree_[m] && !failed[m] && cells_.mega(col / 2, row / 2) == CellState::kFree;
      // a sub-cell a joint's line reaches may be in the room itself: the room's tour starts there
      // (the way ends at its centre, whereas a lane's source is on the path already)
      const bool fromJoint = parent[static_cast<std::size_t>(v)] == -1 && sources[static_cast<std::size_t>(sourceOf[static_cast<std::size_t>(v)])].joint;
      if ((parent[static_cast<std::size_t>(v)] >= 0 || fromJoint) && target) any = visitRoom(path, v, parent, sources, sourceOf, pending, leaving, failed, gaps) || any;
      for (int d = 0; d < 4; ++d) {
        const int c = col + graph::kDx[d], r = row + graph::kDy[d];
        if (!cells_.insideSub(c, r) || parent[index(c, r)] != -2) continue;
        if (sensor_ && knownAt_[megaIndex(c / 2, r / 2)] > leftFrom[static_cast<std::size_t>(v)]) continue;   // not known yet there
        if (cells_.sub(c, r) != CellState::kFree) continue;
        parent[index(c, r)] = v;
        if (sensor_) leftFrom[index(c, r)] = leftFrom[static_cast<std::size_t>(v)];
        queue.push_back(static_cast<int>(index(c, r)));
      }
    }
    if (!any) {
      // a room no chain from the lanes reaches (only then the joints' pass, which costs a pass)
      unreachedRooms_ = false;
      if (gaps || joints || sensor_) return false;
      laneReached_.assign(parent.size(), 0);
      for (std::size_t v = 0; v < parent.size(); ++v) {
        laneReached_[v] = parent[v] != -2;
        const int col = static_cast<int>(v) % sc, row = static_cast<int>(v) / sc;
        const std::size_t m = megaIndex(col / 2, row / 2);
        unreachedRooms_ = unreachedRooms_ || (!laneReached_[v] && cells_.sub(col, row) == CellState::kFree &&
                                              cells_.mega(col / 2, row / 2) == CellState::kFree && !inTree_[m] && !failed[m]);
      }
      return false;
    }
    ++passes_;
    std::vector<std::pair<const std::vector<CellIndex>*, Path*>> rooms;
    for (Excursion& x : pending)
      if (x.room) rooms.emplace_back(&x.walk, &x.tour);
    tourMany(rooms);   // the rooms' own sweeps (and pockets)
    for (Excursion& x : pending) {
      // a joint's line can run along the room's first or last piece the other way (a sweep
      // towards the joint): that way is left, the room is looked for again from another joint
      auto reverses = [](const PathSegment& a, const PathSegment& b) {
        const PointD u = unitHeading(a, true), v = unitHeading(b, false);
        return u.x * v.x + u.y * v.y < kReversalCos;
      };
      if (x.joint >= 0 && !x.tour.segments.empty() &&
          (reverses(x.there.back(), x.tour.segments.front()) || reverses(x.tour.segments.back(), x.back.front()))) {
        for (std::size_t m : x.marked) inTree_[m] = 0;
        banned_.insert({x.at.x, x.at.y, x.joint});
        --roomsJoined_;
        continue;
      }
      std::vector<PathSegment> pieces = std::move(x.there);
      pieces.insert(pieces.end(), x.tour.segments.begin(), x.tour.segments.end());
      pieces.insert(pieces.end(), x.back.begin(), x.back.end());
      at[x.segment].emplace_back(x.at, std::move(pieces));
    }
    std::vector<PathSegment> out;
    out.reserve(path.segments.size());
    for (std::size_t k = 0; k < path.segments.size(); ++k) {
      const PathSegment g = path.segments[k];
      if (at[k].empty()) {
        out.push_back(g);
        continue;
      }
      auto along = [&](PointD p) { return std::abs(p.x - g.from.x) + std::abs(p.y - g.from.y); };
      std::stable_sort(at[k].begin(), at[k].end(), [&](const auto& x, const auto& y) { return along(x.first) < along(y.first); });
      PointD from = g.from;
      if (g.kind != PathSegment::Kind::kLine) {   // ways from its end only (joints)
        out.push_back(g);
        for (const auto& [p, pieces] : at[k]) out.insert(out.end(), pieces.begin(), pieces.end());
        continue;
      }
      for (const auto& [p, pieces] : at[k]) {
        // the segment's parts before and after the point, as they will be, exactly clear (else
        // the excursion is left out: its room or gaps stay uncovered, the path stays valid)
        const bool before = p.x == from.x && p.y == from.y, after = p.x == g.to.x && p.y == g.to.y;
        if ((!before && !clear(PathSegment::line(from, p))) || (!after && !clear(PathSegment::line(p, g.to)))) {
          ++excursionsDropped_;
          continue;
        }
        if (!before) out.push_back(PathSegment::line(from, p));
        out.insert(out.end(), pieces.begin(), pieces.end());
        from = p;
      }
      if (!(from.x == g.to.x && from.y == g.to.y)) out.push_back(PathSegment::line(from, g.to));
    }
    path.segments.swap(out);
    return true;
  }

private:
  /// A room's walk `pw` (from ec back to ec) placed from ec's centre, the mega-cells it newly puts
  /// in a tree marked so and listed in `marked` (to be taken back if the room is left).
  PlacedWalk placeRoom(const std::vector<CellIndex>& pw, CellIndex ec, std::vector<std::size_t>& marked) {
    for (const CellIndex& c : pw)
      if (!inTree_[megaIndex(c.col / 2, c.row / 2)]) marked.push_back(megaIndex(c.col / 2, c.row / 2)), inTree_[marked.back()] = 1;
    return placeWalk(ctx_, pw, cells_.subCenter(ec.col, ec.row), false);
  }

  /// The way `there` joined to the placed tour `ps`: the tour's move from e's exact centre to its
  /// placed one (an ulp, or nothing) is left out, and the way ends where the tour starts.
  void joinWay(std::vector<PathSegment>& there, std::vector<PathSegment>& ps) const {
    while (ps.size() > 1 && ps.front().kind == PathSegment::Kind::kLine && ps.front().length() < 1e-9 * cells_.subSizeD()) ps.erase(ps.begin());
    there.back().to = ps.front().from;
  }

  bool visitRoom(const Path& path, int e, const std::vector<int>& parent, const std::vector<Source>& sources, const std::vector<std::int64_t>& sourceOf,
                 std::vector<Excursion>& pending, std::set<std::pair<int, int>>& leaving, std::vector<std::uint8_t>& failed,
                 bool gaps) {
    const int sc = cells_.subCols();
    std::vector<int> chain{e};   // e back to a source
    while (parent[static_cast<std::size_t>(chain.back())] >= 0) chain.push_back(parent[static_cast<std::size_t>(chain.back())]);
    const Source& src = sources[static_cast<std::size_t>(sourceOf[static_cast<std::size_t>(chain.back())])];
    const std::pair<int, int> leave{chain.back(), chain.size() > 1 ? chain[chain.size() - 2] : -1};
    if (leaving.count(leave)) return false;   // the next pass
    const CellIndex ec{e % sc, e / sc};
    const std::size_t room = megaIndex(ec.col / 2, ec.row / 2);
    std::size_t& left = gaps ? gapsLeft_ : roomsLeft_;
    std::vector<CellIndex> pw = gaps ? gapWalk(e) : pocketWalk_(ec);
    if (pw.empty() || !(pw.front() == ec) || !(pw.back() == ec) || (!gaps && pw.size() < 3)) {
      failed[room] = !gaps;
      ++left;
      return false;
    }
    // the way there: centres from the source's point to e's, straight runs merged
    std::vector<PointD> way{src.at};
    if (src.joint) way.push_back(cells_.subCenterD(chain.back() % sc, chain.back() / sc));
    for (std::size_t i = chain.size() - 1; i-- > 0;) way.push_back(cells_.subCenterD(chain[i] % sc, chain[i] / sc));
    std::vector<PathSegment> there = mergedLines(way);
    std::vector<std::size_t> marked;
    PlacedWalk placed;
    if (!gaps) {
      placed = placeRoom(pw, ec, marked);
    } else if (pw.size() == 1) {   // one gap: there and back
      placed.path.segments.push_back(PathSegment::line(way.back(), way.back()));
    } else {   // centre to centre, straight runs merged, each line checked exactly below
      placed.path.segments = linesThrough(pw);
      for (const PathSegment& g : placed.path.segments) placed.startClear = placed.startClear && clear(g);
    }
    bool ok = placed.unsafeCells.empty() && placed.startClear && !placed.path.segments.empty() && !there.empty();
    // the room's tour starts at e's centre and ends there as the walk places it (rounded towards
    // its mega-cell's centre, possibly an ulp away): the way there ends where the tour starts, the
    // way back starts where it ends, with no joint between
    std::vector<PathSegment> back;
    if (ok) {
      joinWay(there, placed.path.segments);
      for (std::size_t i = there.size(); i-- > 0;) back.push_back(PathSegment::line(there[i].to, there[i].from));
      back.front().from = placed.path.segments.back().to;
    }
    for (std::size_t i = 0; ok && i < there.size(); ++i) ok = clear(there[i]);
    if (ok) ok = clear(back.front());
    if (ok && !src.joint) {  // the path's piece split where the way leaves it
      const PathSegment& g = path.segments[src.segment];
      ok = clear(PathSegment::line(g.from, src.at)) && clear(PathSegment::line(src.at, g.to));
    }
    if (!ok) {
      for (std::size_t m : marked) inTree_[m] = 0;
      failed[room] = !gaps;
      ++left;
      return false;
    }
    leaving.insert(leave);
    if (pw.size() == 1) placed.path.segments.clear();
    pending.push_back({src.segment, src.at, std::move(there), std::move(back), std::move(pw), std::move(placed.path), !gaps,
                       src.joint ? chain.back() : -1, std::move(marked)});
    ++(gaps ? gapsJoined_ : roomsJoined_);
    return true;
  }

  const PlanningContext& ctx_;
  const CellGrid& cells_;
  ObstacleSensor* sensor_;
  OnlineSweeper* sweeper_;
  bool trace_, every_, throughRuns_, pockets_, needed_, onlineGaps_;
  ClearanceChecker& check_;
  PocketWalk pocketWalk_;
  std::vector<std::uint8_t> inTree_, swept_;
  std::vector<std::uint8_t> sensedFrom_, failedOnline_;   ///< online rooms: mega-cells sensed from (this pass), rooms failed
  std::vector<std::uint8_t> asked_;                       ///< online: mega-cells the sensor was asked from (ever)
  std::vector<std::size_t> knownAt_;   ///< online rooms: 1 + the first piece of the path along which each mega-cell was sensed
  std::vector<PathSegment> precovered_;
  std::set<std::array<int, 4>> runsDone_;
  std::size_t inserted_ = 0, rejected_ = 0, unreached_ = 0, shared_ = 0, arcs_ = 0, pocketsJoined_ = 0, pocketsLeft_ = 0;
  std::size_t traced_ = 0;  ///< sweeps (of any outcome) made by the direct trace
  std::size_t skipped_ = 0; ///< detours left out: what they would sweep was swept already
  std::size_t roomsFromEnd_ = 0;   ///< online: rooms reached from where the path ended (endSearch)
  std::size_t frontierTrips_ = 0;  ///< online: ways from the path's end to a frontier (endSearch)
  std::unique_ptr<EdgeIndex> pinchedEdges_;   ///< the obstacle edges, reach 2(ε + δ), for pinched()
  std::size_t detourEnd_ = 0;   ///< online: the path's length when a gap's walk or a frontier trip ended it
  std::vector<std::uint8_t> failedGapOnline_;   ///< online: pinched gaps whose visit was not exactly clear
  static constexpr std::size_t kFrontiersTried = 16;   ///< online: the nearest frontiers whose ways are checked, a search
  std::size_t roomsJoined_ = 0, roomsLeft_ = 0, gapsJoined_ = 0, gapsLeft_ = 0;
  std::vector<std::uint8_t> gap_;   ///< free sub-cells left uncovered, not yet visited
  std::size_t excursionsDropped_ = 0, passes_ = 0;
  bool unreachedRooms_ = false;   ///< the last pass from the lanes found no room, and a room is beyond their chains
  std::vector<std::uint8_t> laneReached_;   ///< that pass's search: the sub-cells a chain from the lanes reaches
  std::set<std::tuple<double, double, int>> banned_;   ///< (joint, sub-cell) whose way reversed into its room's tour
};

/// Segments by bucket (side 2r), for "does anything pass within r of this point" in doubles.
class SegmentBuckets {
public:
  /// A dense grid over the path's box (cells of 2r, coarser where that would exceed about 16
  /// million), pieces listed per cell in two passes (count, then fill): linear in the entries.
  SegmentBuckets(const Path& path, double r) : r_(r) {
    std::vector<BoxD> boxes(path.segments.size());
    BoxD all{0, 0, 0, 0};
    for (std::size_t i = 0; i < path.segments.size(); ++i) {
      const PathSegment& s = path.segments[i];
      BoxD b{std::min(s.from.x, s.to.x), std::min(s.from.y, s.to.y), std::max(s.from.x, s.to.x), std::max(s.from.y, s.to.y)};
      if (s.kind == PathSegment::Kind::kArc) {
        const double rho = std::hypot(s.from.x - s.center.x, s.from.y - s.center.y);
        b = {s.center.x - rho, s.center.y - rho, s.center.x + rho, s.center.y + rho};
      }
      const double reach = r * (1 + 1e-6);  // beyond covered()'s limit of r (1 + 1e-9): no bucket edge decides
      b = {b.xmin - reach, b.ymin - reach, b.xmax + reach, b.ymax + reach};
      boxes[i] = b;
      all = i == 0 ? b : BoxD{std::min(all.xmin, b.xmin), std::min(all.ymin, b.ymin), std::max(all.xmax, b.xmax), std::max(all.ymax, b.ymax)};
    }
    constexpr double kMaxCells = 16.0 * 1024 * 1024;
    const double w = all.xmax - all.xmin, h = all.ymax - all.ymin;
    cell_ = std::max({2 * r, std::sqrt(w * h / kMaxCells), std::max(w, h) / kMaxCells, 1e-300});
    x0_ = all.xmin, y0_ = all.ymin;
    nx_ = static_cast<long>(w / cell_) + 1, ny_ = static_cast<long>(h / cell_) + 1;
    start_.assign(static_cast<std::size_t>(nx_ * ny_) + 1, 0);
    auto each = [&](const BoxD& b, auto&& f) {
      for (long by = key(b.ymin, y0_, ny_); by <= key(b.ymax, y0_, ny_); ++by)
        for (long bx = key(b.xmin, x0_, nx_); bx <= key(b.xmax, x0_, nx_); ++bx) f(static_cast<std::size_t>(by * nx_ + bx));
    };
    for (const BoxD& b : boxes) each(b, [&](std::size_t c) { ++start_[c + 1]; });
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    pieces_.resize(start_.back());
    for (std::size_t i = 0; i < boxes.size(); ++i) each(boxes[i], [&](std::size_t c) { pieces_[fill[c]++] = i; });
  }
  bool covered(const Path& path, PointD w) const {
    return coveredExcept(path, w, {});
  }
  /// covered(), by the pieces not marked in `skip` (empty: none is).
  bool coveredExcept(const Path& path, PointD w, const std::vector<std::uint8_t>& skip) const {
    if (!(w.x >= x0_ && w.y >= y0_) || pieces_.empty()) return false;
    const long bx = static_cast<long>((w.x - x0_) / cell_), by = static_cast<long>((w.y - y0_) / cell_);
    if (bx >= nx_ || by >= ny_) return false;
    const std::size_t c = static_cast<std::size_t>(by * nx_ + bx);
    const double limit = r_ * (1 + 1e-9);
    for (std::size_t k = start_[c]; k < start_[c + 1]; ++k)
      if ((skip.empty() || !skip[pieces_[k]]) && withinReach(path.segments[pieces_[k]], w, limit)) return true;
    return false;
  }

private:
  long key(double v, double origin, long n) const {
    return std::min(n - 1, std::max(0L, static_cast<long>((v - origin) / cell_)));
  }
  double r_, cell_ = 1, x0_ = 0, y0_ = 0;
  long nx_ = 1, ny_ = 1;
  std::vector<std::size_t> start_, pieces_;  ///< the pieces of cell c: pieces_[start_[c] .. start_[c + 1])
};

/// Fills the outer corners of right-angle turns that nothing sweeps. At a turn at P from direction
/// u to v (both lines at least r long after the turn), the disc never reaches the corner
/// W = P + r·u − r·v of P's sub-cell nor the wedge around it (area r²(1 − π/4), 5.4 % of the
/// sub-cell), unless a neighbouring lane passes close by. Two ways reach W, and
/// both sweep the whole sub-cell: run on to P + r·u and cut back to P + r·v (needs room in the
/// cell ahead), or cut from P − r·u to P − r·v and go on from there (needs room on W's side). The
/// first whose new moves are exactly clear is taken; otherwise the turn stays. Whether W is swept
/// by some other piece is decided in doubles (it only decides whether to try).
void fillCorners(const PlanningContext& ctx, ClearanceChecker& check, Path& path, Plan& plan) {
  const double r = ctx.problem.robots.at(0).radius.get_d();
  const SegmentBuckets buckets(path, r);
  auto axisDir = [](const PathSegment& s, double& ux, double& uy, double& len) {
    if (s.kind != PathSegment::Kind::kLine) return false;
    const double dx = s.to.x - s.from.x, dy = s.to.y - s.from.y;
    if ((dx != 0) == (dy != 0)) return false;
    len = std::abs(dx + dy);
    ux = dx != 0 ? (dx > 0 ? 1 : -1) : 0;
    uy = dy != 0 ? (dy > 0 ? 1 : -1) : 0;
    return true;
  };
  std::vector<PathSegment> out;
  out.reserve(path.segments.size());
  std::size_t filled = 0, blocked = 0;
  for (std::size_t i = 0; i < path.segments.size(); ++i) {
    PathSegment next = path.segments[i];
    if (out.empty()) {
      out.push_back(next);
      continue;
    }
    PathSegment& prev = out.back();
    double ux, uy, lu, vx, vy, lv;
    if (!axisDir(prev, ux, uy, lu) || !axisDir(next, vx, vy, lv) || ux * vx + uy * vy != 0 || lu < r || lv < r) {
      out.push_back(next);
      continue;
    }
    const PointD P = next.from;
    // the wedge: the part of the outer quarter of P's sub-cell that the disc at P misses; some
    // other piece sweeps it when it sweeps its corner and three points along its inner rim
    bool swept = true;
    for (const auto& [a, b] : {std::pair{1.0, 1.0}, std::pair{1.0, 0.35}, std::pair{0.35, 1.0}, std::pair{0.75, 0.75}})
      swept = swept && buckets.covered(path, PointD{P.x + r * (a * ux - b * vx), P.y + r * (a * uy - b * vy)});
    if (swept) {
      out.push_back(next);
      continue;
    }
    const PointD ahead{P.x + r * ux, P.y + r * uy}, up{P.x + r * vx, P.y + r * vy};
    const PointD back{P.x - r * ux, P.y - r * uy}, below{P.x - r * vx, P.y - r * vy};
    if (pieceClear(check, PathSegment::line(P, ahead)) && pieceClear(check, PathSegment::line(ahead, up))) {
      prev.to = ahead;
      out.push_back(PathSegment::line(ahead, up));
      next.from = up;
      ++filled;
    } else if (pieceClear(check, PathSegment::line(back, below)) && pieceClear(check, PathSegment::line(below, P))) {
      prev.to = back;
      out.push_back(PathSegment::line(back, below));
      next.from = below;
      ++filled;
    } else {
      ++blocked;
    }
    out.push_back(next);
  }
  path.segments.swap(out);
  plan.statistics["corners_filled"] = static_cast<double>(filled);
  plan.statistics["corners_left"] = static_cast<double>(blocked);
}

/// Cuts the tips of thin fingers. Where U ∩ C-free narrows to a point (an obstacle edge almost
/// parallel to a lane, or a contour that touches the lane), its boundary runs in along one side and
/// back along the other, turning by 180° at the tip: a reversing spike; so does a lane that meets a
/// contour at a grazing angle. Any turn of more than 150° is a tip. The tip is cut where the two
/// sides are w = r/16 apart (found by stepping back s = w, 2w, … ≤ 4r along both), with a straight
/// cut across; the cut and the two shortened pieces are checked exactly, else the tip stays
/// (`tips_left`). The robot at the cut still sweeps r beyond it, so little of the finger is lost.
void cutTips(const PlanningContext& ctx, ClearanceChecker& check, Path& path, Plan& plan) {
  const double r = ctx.problem.robots.at(0).radius.get_d(), w = r / 16, tiny = 1e-9 * r;
  auto clear = [&](const PathSegment& p) { return pieceClear(check, p); };
  // One pass, linear in the path: `out` holds the pieces up to the current one (out.back()), `in`
  // the rest from `i`; a cut replaces the tail of `out` from the piece where it starts, and the
  // pieces of `in` up to the one where it ends, by the two shortened pieces and the cut.
  const std::vector<PathSegment>& in = path.segments;
  std::vector<PathSegment> out;
  std::vector<double> inLen(in.size()), outLen;  // the pieces' lengths, computed once
  for (std::size_t j = 0; j < in.size(); ++j) inLen[j] = in[j].length();
  out.reserve(in.size());
  outLen.reserve(in.size());
  std::size_t cut = 0, left = 0, i = 0;
  auto take = [&](std::size_t j) {
    out.push_back(in[j]);
    outLen.push_back(inLen[j]);
  };
  if (!in.empty()) take(i++);
  while (i < in.size()) {
    const PathSegment& prev = out.back();
    const PathSegment& next = in[i];
    if (outLen.back() < tiny || inLen[i] < tiny) {
      take(i++);
      continue;
    }
    const PointD u = unitHeading(prev, true), v = unitHeading(next, false);
    if (u.x * v.x + u.y * v.y >= kReversalCos) {   // not a reversal
      take(i++);
      continue;
    }
    bool done = false;
    for (double s = w; s <= 4 * r && !done; s *= 2) {
      // back from the tip along out.back(), …; forward along in[i], …
      std::ptrdiff_t k = static_cast<std::ptrdiff_t>(out.size()) - 1;
      double back = s;
      while (k >= 0 && outLen[static_cast<std::size_t>(k)] <= back) back -= outLen[static_cast<std::size_t>(k--)];
      std::size_t m = i;
      double fwd = s;
      while (m < in.size() && inLen[m] <= fwd) fwd -= inLen[m++];
      if (k < 0 || m >= in.size()) break;
      const PathSegment& pk = out[static_cast<std::size_t>(k)];
      const PointD A = pointAlong(pk, outLen[static_cast<std::size_t>(k)] - back, outLen[static_cast<std::size_t>(k)]),
                   B = pointAlong(in[m], fwd, inLen[m]);
      if (std::hypot(A.x - B.x, A.y - B.y) < w) continue;
      PathSegment before = pk, after = in[m];
      before.to = A;
      after.from = B;
      const PathSegment across = PathSegment::line(A, B);
      if (!clear(before) || !clear(across) || !clear(after)) continue;
      out.resize(static_cast<std::size_t>(k));
      outLen.resize(static_cast<std::size_t>(k));
      for (const PathSegment& p : {before, across, after}) {
        out.push_back(p);
        outLen.push_back(p.length());
      }
      i = m + 1;  // go on after the cut
      done = true;
    }
    (done ? cut : left) += 1;
    if (!done) take(i++);
  }
  path.segments.swap(out);
  plan.statistics["tips_cut"] = static_cast<double>(cut);
  plan.statistics["tips_left"] = static_cast<double>(left);
}


/// Spurs: a line X → T followed by a line T → Y back along it (a dead end left the way it was
/// entered: a room's or a sweep's way that starts where the tour turned, a gap's visit), a reversal
/// the robot stops and turns 180° for. Where what the stretch beyond the nearer end (X, or Y) sweeps
/// is swept by other pieces too (samples every r/4 along it at five offsets across and three beyond
/// T, in doubles: a gap's dead end is not, by the gap rule), and the turn that then takes its place
/// at the nearer end is no reversal, the stretch is left out: X → Y, one line on (checked exactly).
/// Pieces of any spur never count as covering another's (so no two spurs are dropped for each
/// other). Counted in `spurs_trimmed`.
void trimSpurs(const PlanningContext& ctx, ClearanceChecker& check, Path& path, Plan& plan) {
  const double r = ctx.problem.robots.at(0).radius.get_d(), tiny = 1e-9 * r;
  std::vector<PathSegment>& g = path.segments;
  auto heading = [](const PathSegment& p) { return PointD{p.to.x - p.from.x, p.to.y - p.from.y}; };
  auto spurAt = [&](std::size_t i) {   // the joint between g[i - 1] and g[i]
    const PathSegment &a = g[i - 1], &b = g[i];
    if (a.kind != PathSegment::Kind::kLine || b.kind != PathSegment::Kind::kLine) return false;
    const PointD u = heading(a), v = heading(b);
    const double lu = std::hypot(u.x, u.y), lv = std::hypot(v.x, v.y);
    if (lu < tiny || lv < tiny) return false;
    // opposite and on one line (up to rounding)
    return u.x * v.x + u.y * v.y < -(1 - 1e-12) * lu * lv;
  };
  std::vector<std::size_t> joints;
  std::vector<std::uint8_t> skip(g.size(), 0);
  for (std::size_t i = 1; i < g.size(); ++i)
    if (spurAt(i)) joints.push_back(i), skip[i - 1] = skip[i] = 1;
  if (joints.empty()) {
    plan.statistics["spurs_trimmed"] = 0;
    return;
  }
  const SegmentBuckets index(path, r);
  std::vector<std::uint8_t> drop(g.size(), 0);
  std::size_t trimmed = 0;
  for (std::size_t i : joints) {
    if (drop[i - 1] || drop[i]) continue;
    PathSegment &a = g[i - 1], &b = g[i];
    const PointD X = a.from, T = a.to, Y = b.to;
    const bool shortIn = std::hypot(X.x - T.x, X.y - T.y) <= std::hypot(Y.x - T.x, Y.y - T.y);
    const PointD E = shortIn ? X : Y;   // the stretch T..E is left out; the line on starts (ends) at E
    const PathSegment stay = PathSegment::line(X, Y);
    const double len = std::hypot(E.x - T.x, E.y - T.y);
    const PointD t{(E.x - T.x) / len, (E.y - T.y) / len};
    auto ok = [&](PointD q) { return withinReach(stay, q, r * (1 - 1e-6)) || index.coveredExcept(path, q, skip); };
    bool covered = true;
    const int n = std::max(1, static_cast<int>(std::ceil(len / (r / 4))));
    for (int k = 0; covered && k <= n; ++k) {
      const PointD q{T.x + t.x * len * k / n, T.y + t.y * len * k / n};
      for (double o : {-0.75, -0.375, 0.0, 0.375, 0.75}) covered = covered && ok(PointD{q.x - o * r * t.y, q.y + o * r * t.x});
    }
    for (double o : {-0.5, 0.0, 0.5}) covered = covered && ok(PointD{T.x - t.x * r * 0.75 - o * r * t.y, T.y - t.y * r * 0.75 + o * r * t.x});
    // the turn at E, onto the line on (off it): 180° less the turn there was; not a reversal. A
    // spur retraced to where it began (X = Y, up to rounding) goes: the turn is then the one
    // between the pieces before and after it.
    const PointD along{(Y.x - X.x), (Y.y - X.y)};
    const double la = std::hypot(along.x, along.y);
    const bool whole = la <= kJointGap;   // a step the validator takes as a joint (validate.h)
    if (!whole && la < tiny) continue;     // a line so short would be a sliver
    if (whole) {
      if (i >= 2 && i + 1 < g.size()) {
        const PointD h = unitHeading(g[i - 2], true), k = unitHeading(g[i + 1], false);
        if (h.x * k.x + h.y * k.y < kReversalCos) continue;
      }
    } else if (shortIn ? i >= 2 : i + 1 < g.size()) {
      const PointD h = shortIn ? unitHeading(g[i - 2], true) : unitHeading(g[i + 1], false);
      if ((h.x * along.x + h.y * along.y) / la < kReversalCos) continue;
    }
    if (!covered || !pieceClear(check, stay)) continue;
    a = stay;
    drop[i] = 1;
    drop[i - 1] = whole;   // the path's joint then steps from X to Y (at most kJointGap, checked above)
    ++trimmed;
  }
  std::vector<PathSegment> out;
  out.reserve(g.size());
  for (std::size_t i = 0; i < g.size(); ++i)
    if (!drop[i]) out.push_back(g[i]);
  g.swap(out);
  plan.statistics["spurs_trimmed"] = static_cast<double>(trimmed);
}

/// Slivers: lines shorter than 10^-9 r between two pieces, left where two pieces computed apart
/// meet (a sweep's end rounded from its exact point beside the lane it joins, an ulp away). Their
/// direction is noise: a heading change of up to 180° at each end that the robot would stop and
/// turn for (a reversal on the metrics). Each is merged into the line before it (that line then
/// ends where the sliver did), else into the line after it; the merged line is checked exactly.
/// One between two arcs, at most kJointGap long, goes: the joint steps over it. Else it stays
/// (`slivers_left`).
void dropSlivers(const PlanningContext& ctx, ClearanceChecker& check, Path& path, Plan& plan) {
  const double tiny = 1e-9 * ctx.problem.robots.at(0).radius.get_d();
  std::vector<PathSegment>& in = path.segments;
  std::vector<PathSegment> out;
  out.reserve(in.size());
  std::size_t merged = 0, left = 0;
  for (std::size_t i = 0; i < in.size(); ++i) {
    const PathSegment& g = in[i];
    const bool sliver = g.kind == PathSegment::Kind::kLine && !(g.from.x == g.to.x && g.from.y == g.to.y) && g.length() < tiny && !out.empty() && i + 1 < in.size();
    if (!sliver) {
      out.push_back(g);
      continue;
    }
    // `line` becomes a → b where it is a line and that is exactly clear
    auto absorb = [&](PathSegment& line, PointD a, PointD b) {
      if (line.kind != PathSegment::Kind::kLine || line.length() <= tiny) return false;
      const PathSegment longer = PathSegment::line(a, b);
      if (!pieceClear(check, longer)) return false;
      line = longer;
      return true;
    };
    if (absorb(out.back(), out.back().from, g.to) || absorb(in[i + 1], g.from, in[i + 1].to)) {
      ++merged;
      continue;
    }
    if (g.length() <= kJointGap && pieceClear(check, g)) {   // between two arcs: the joint steps over it
      ++merged;
      continue;
    }
    ++left;
    out.push_back(g);
  }
  in.swap(out);
  plan.statistics["slivers_merged"] = static_cast<double>(merged);
  plan.statistics["slivers_left"] = static_cast<double>(left);
}

/// The map's vertices up to which contours=auto passes the contours: the whole map's C-space they
/// need costs about 0.5 s at 9,000 pieces and 8 s at 90,000 (a 10^6-pixel map), more than the rest
/// of the plan there; real floor plans of 0.05 m pixels have 4,000-5,500 vertices.
constexpr std::size_t kAutoContourVertices = 20'000;

bool passContours(const PlanningContext& ctx, const ParamSet& params) {
  const std::string v = params.text("contours");
  if (v != "auto") return v == "pass";
  std::size_t n = 0;
  for (const Ring* ring : ctx.problem.workspace.rings()) n += ring->size();
  return n <= kAutoContourVertices;
}

/// Contour passes: the boundary loops of C-free (the walls' and each obstacle's C-space contour,
/// at radius r + ε + δ as the sweeps), each piece checked exactly at r; a loop with a failing piece
/// is left out (`contours_left`). `start` holds those of the start's component; `others` those of
/// the other components, which the path may reach through a gap exactly 2r wide (a door of a grid
/// map: closed at r + ε + δ), where the rooms pass takes it.
struct ContourLoops {
  std::vector<std::vector<PathSegment>> start, others;
  std::map<std::pair<double, double>, PathSegment> mitres;   ///< crossing of a mitred corner → the arc it replaced
};

/// Mitred corners (`loop_corners=mitre`, see the citation block): each arc of radius r (+ ε + δ)
/// and at most 120° between two lines at least r long (an obstacle's corner, not a scan's
/// staircase of arcs) becomes its two tangent lines to their crossing, which keep its headings at
/// both ends (the same turning, the same joints beside it), where both are exactly clear. The
/// arcs are kept by crossing in `mitres`, for putting back (restoreArcs).
void mitreLoop(ClearanceChecker& check, std::vector<PathSegment>& loop, double r, std::map<std::pair<double, double>, PathSegment>& mitres) {
  const std::size_t n = loop.size();
  if (n < 3) return;
  std::vector<PathSegment> out;
  out.reserve(n + 8);
  for (std::size_t i = 0; i < n; ++i) {
    const PathSegment& a = loop[i];
    out.push_back(a);
    const PathSegment &before = loop[(i + n - 1) % n], &after = loop[(i + 1) % n];
    if (a.kind != PathSegment::Kind::kArc || before.kind != PathSegment::Kind::kLine || after.kind != PathSegment::Kind::kLine ||
        before.length() < r || after.length() < r)
      continue;
    const PointD u = unitHeading(a, false), v = unitHeading(a, true);
    const double rho = std::hypot(a.from.x - a.center.x, a.from.y - a.center.y);
    // the headings' change; the arc's sweep where it turns the arc's way (an arc beyond 180° would
    // show as a turn the other way, and its tangents' crossing lies on the wrong side)
    const double signedTurn = std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y), turn = std::abs(signedTurn);
    if ((signedTurn > 0) != a.ccw || std::abs(rho - r) > 0.01 * r || turn < M_PI / 180 || turn > 2 * M_PI / 3) continue;
    const double bx = (a.from.x + a.to.x) / 2 - a.center.x, by = (a.from.y + a.to.y) / 2 - a.center.y, bn = std::hypot(bx, by);
    if (!(bn > 0)) continue;
    const double d = rho / std::cos(turn / 2);
    const PointD m{a.center.x + d * bx / bn, a.center.y + d * by / bn};
    const PathSegment l1 = PathSegment::line(a.from, m), l2 = PathSegment::line(m, a.to);
    if (mitres.count({m.x, m.y}) || !pieceClear(check, l1) || !pieceClear(check, l2)) continue;
    mitres.emplace(std::make_pair(m.x, m.y), a);
    out.back() = l1;
    out.push_back(l2);
  }
  loop.swap(out);
}

ContourLoops contourLoops(const PlanningContext& ctx, ClearanceChecker& check, const Path& path, Plan& plan, bool mitre) {
  const Workspace& w = ctx.problem.workspace;
  const Rational r = ctx.problem.robots.at(0).radius;
  const CSpace cs(w, Rational(r + slackOf(w)), 1e-6, ctx.threads);
  // the component of the first joint strictly inside it (a lane along a wall runs at exactly r)
  int comp = -1;
  for (std::size_t j = 0; comp < 0 && j < path.segments.size(); ++j) {
    const PointD s = path.segments[j].from;
    comp = cs.componentOf(Point{exactFromDouble(s.x), exactFromDouble(s.y)});
  }
  ContourLoops out;
  std::size_t left = 0;
  const std::vector<CurveRegion> regions = cs.components();
  for (std::size_t c = 0; c < regions.size(); ++c) {
    std::vector<const CurveLoop*> loops{&regions[c].outer};
    for (const CurveLoop& h : regions[c].holes) loops.push_back(&h);
    for (const CurveLoop* loop : loops) {
      bool ok = !loop->pieces.empty();
      for (std::size_t i = 0; ok && i < loop->pieces.size(); ++i) ok = pieceClear(check, loop->pieces[i]);
      if (!ok) {
        ++left;
        continue;
      }
      std::vector<PathSegment> pieces = loop->pieces;
      if (mitre) mitreLoop(check, pieces, r.get_d(), out.mitres);
      (static_cast<int>(c) == comp ? out.start : out.others).push_back(std::move(pieces));
    }
  }
  plan.statistics["contours_left"] = static_cast<double>(left);
  return out;
}

/// Each loop spliced into the path at the joint and loop vertex, in the direction, that add the
/// least turning (a joint on the loop in the loop's direction adds only the loop's own turning;
/// elsewhere a straight line there and back, checked exactly). Chosen in doubles: candidates within
/// 3r of a joint (or, with none there, each joint's nearest vertex) by the turning they add, the
/// first 64; if every line of those is blocked, the 256 joints nearest the loop (rings of 3r cells
/// grown from its vertices), nearest first. `nearOnly`: the loops of rooms behind gaps exactly 2r
/// wide, spliced only from a joint within 3r. `firstContact` (the online robot, with `nearOnly`):
/// at the first joint in path order within 3r of the loop, where it turns the least there, and
/// never with a turn of more than 150° (a reversal: the loop is left then): the robot goes round a
/// contour when it first comes to it, not where the whole path would turn least. `splicedLoops`:
/// the loops spliced (by an earlier call too, which this one skips); only these add to
/// `contours_turning_deg`.
void spliceLoops(const PlanningContext& ctx, ClearanceChecker& check, const std::vector<std::vector<PathSegment>>& loops, Path& path,
                 Plan& plan, bool nearOnly = false, bool firstContact = false, std::vector<std::uint8_t>* splicedLoops = nullptr) {
  const double r = ctx.problem.robots.at(0).radius.get_d();
  auto ang = [](PointD a, PointD b) { return std::acos(std::max(-1.0, std::min(1.0, a.x * b.x + a.y * b.y))); };
  std::size_t done = 0, left = 0;
  for (std::size_t li = 0; li < loops.size(); ++li) {
    if (splicedLoops && (*splicedLoops)[li]) continue;
    const std::vector<PathSegment>& pc = loops[li];
    const std::size_t n = pc.size();
    // vertex buckets (side 3r)
    const double cell = 3 * r;
    std::map<std::pair<long, long>, std::vector<std::size_t>> bucket;
    auto keyOf = [&](PointD p) { return std::pair<long, long>{static_cast<long>(std::floor(p.x / cell)), static_cast<long>(std::floor(p.y / cell))}; };
    for (std::size_t v = 0; v < n; ++v) bucket[keyOf(pc[v].from)].push_back(v);
    struct Cand {
      double cost;
      std::size_t j, v;
      bool fwd;
      bool operator<(const Cand& o) const { return std::tie(cost, j, v, fwd) < std::tie(o.cost, o.j, o.v, o.fwd); }
    };
    std::vector<Cand> cand;
    auto consider = [&](std::size_t j, std::size_t v) {
      const PointD c = path.segments[j].from, q = pc[v].from;
      const PointD hin = unitHeading(path.segments[j - 1], true), hout = unitHeading(path.segments[j], false);
      double d = std::hypot(q.x - c.x, q.y - c.y);
      if (d <= kJointGap) d = 0;   // the same point up to rounding: no line, whose direction would be noise
      for (bool fwd : {true, false}) {
        const PointD l0 = fwd ? unitHeading(pc[v], false) : PointD{-unitHeading(pc[(v + n - 1) % n], true).x, -unitHeading(pc[(v + n - 1) % n], true).y};
        const PointD l1 = fwd ? unitHeading(pc[(v + n - 1) % n], true) : PointD{-unitHeading(pc[v], false).x, -unitHeading(pc[v], false).y};
        double t[4];
        int k = 0;
        if (d == 0) {
          t[k++] = ang(hin, l0), t[k++] = ang(l1, hout);
        } else {   // a line there and back, however short: its direction is what the robot turns to
          const PointD u{(q.x - c.x) / d, (q.y - c.y) / d}, mu{-u.x, -u.y};
          t[k++] = ang(hin, u), t[k++] = ang(u, l0), t[k++] = ang(l1, mu), t[k++] = ang(mu, hout);
        }
        double cost = d / r * 0.2;
        for (int i = 0; i < k; ++i) cost += t[i] + (t[i] > 150 * M_PI / 180 ? 10 : 0);
        cand.push_back({cost, j, v, fwd});
      }
    };
    for (std::size_t j = 1; j < path.segments.size(); ++j) {
      const auto [kx, ky] = keyOf(path.segments[j].from);
      for (long dx = -1; dx <= 1; ++dx)
        for (long dy = -1; dy <= 1; ++dy) {
          auto it = bucket.find({kx + dx, ky + dy});
          if (it == bucket.end()) continue;
          for (std::size_t v : it->second) consider(j, v);
        }
    }
    if (cand.empty() && nearOnly) continue;   // a component the path does not reach
    // the nearest vertex of each joint (of the given joints)
    auto nearestOf = [&](const std::vector<std::size_t>& joints) {
      for (std::size_t j : joints) {
        std::size_t bv = 0;
        double best = 1e300;
        for (std::size_t v = 0; v < n; ++v) {
          const double d = std::hypot(pc[v].from.x - path.segments[j].from.x, pc[v].from.y - path.segments[j].from.y);
          if (d < best) best = d, bv = v;
        }
        consider(j, bv);
      }
    };
    if (cand.empty()) {   // no joint near: every joint
      std::vector<std::size_t> all(path.segments.size() - 1);
      std::iota(all.begin(), all.end(), std::size_t{1});
      nearestOf(all);
    }
    // the first of up to 64 candidates whose line is exactly clear; `perJoint`: the 8 that turn
    // least at each joint, the joints in the order given, up to 1024 lines checked (online: the loop
    // is spliced at the first joint in path order where a line is clear, however many joints before
    // it have none; a big loop has a dozen vertices within 3r of a joint, many across an obstacle)
    auto splice = [&](const std::vector<Cand>& order, bool perJoint = false) {
      std::size_t tried = 0, total = 0;
      for (std::size_t k = 0; k < order.size() && total < 1024; ++k) {
        if (perJoint && k > 0 && order[k].j != order[k - 1].j) tried = 0;
        if (tried++ >= (perJoint ? 8u : 64u)) {
          if (!perJoint) break;
          continue;
        }
        ++total;
        const Cand& x = order[k];
        const PointD c = path.segments[x.j].from, q = pc[x.v].from;
        const bool line = std::hypot(q.x - c.x, q.y - c.y) > kJointGap;
        if (!(q.x == c.x && q.y == c.y) && !check.clear(c, q)) continue;   // a line, or the joint's step (validate.h)
        std::vector<PathSegment> ins;
        if (line) ins.push_back(PathSegment::line(c, q));
        for (std::size_t i = 0; i < n; ++i)
          ins.push_back(x.fwd ? pc[(x.v + i) % n] : coverkit::reversedPiece(pc[(x.v + n - 1 - i) % n]));
        if (line) ins.push_back(PathSegment::line(q, c));
        path.segments.insert(path.segments.begin() + static_cast<std::ptrdiff_t>(x.j), ins.begin(), ins.end());
        return true;
      }
      return false;
    };
    if (firstContact) {   // online: the first joint in path order; none with a reversal (the loop is left)
      cand.erase(std::remove_if(cand.begin(), cand.end(), [](const Cand& c) { return c.cost >= 10; }), cand.end());
      std::sort(cand.begin(), cand.end(), [](const Cand& a, const Cand& b) { return std::make_pair(a.j, a) < std::make_pair(b.j, b); });
    } else {
      std::sort(cand.begin(), cand.end());
    }
    bool spliced = splice(cand, firstContact);
    if (!spliced && !nearOnly) {
      // every line of the cheapest was blocked (the joints that turn least may lie across an
      // obstacle): the nearest joints first, whose lines are the likeliest to be clear
      // each joint's distance in cells to the loop's nearest vertex: rings of cells (Chebyshev)
      // grown from the loop's vertices over the box of the path and the loop
      double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
      auto grow = [&](PointD p) { x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y); };
      for (const PathSegment& p : pc) grow(p.from);
      for (const PathSegment& p : path.segments) grow(p.from);
      const double side = std::max({3 * r, (x1 - x0) / 2048, (y1 - y0) / 2048});
      const long gx = static_cast<long>((x1 - x0) / side) + 1, gy = static_cast<long>((y1 - y0) / side) + 1;
      auto cellOf = [&](PointD p) { return std::min(gy - 1, static_cast<long>((p.y - y0) / side)) * gx + std::min(gx - 1, static_cast<long>((p.x - x0) / side)); };
      std::vector<int> ring(static_cast<std::size_t>(gx * gy), -1);
      std::vector<long> queue;
      for (const PathSegment& p : pc) {
        const long k = cellOf(p.from);
        if (ring[static_cast<std::size_t>(k)] < 0) ring[static_cast<std::size_t>(k)] = 0, queue.push_back(k);
      }
      for (std::size_t q = 0; q < queue.size(); ++q) {
        const long k = queue[q], i = k % gx, j = k / gx;
        for (long dj = -1; dj <= 1; ++dj)
          for (long di = -1; di <= 1; ++di) {
            if (i + di < 0 || i + di >= gx || j + dj < 0 || j + dj >= gy) continue;
            const std::size_t m = static_cast<std::size_t>((j + dj) * gx + i + di);
            if (ring[m] < 0) ring[m] = ring[static_cast<std::size_t>(k)] + 1, queue.push_back(static_cast<long>(m));
          }
      }
      std::vector<std::pair<int, std::size_t>> byRing;   // (rings, joint): the nearest 256 joints
      for (std::size_t j = 1; j < path.segments.size(); ++j) byRing.emplace_back(ring[static_cast<std::size_t>(cellOf(path.segments[j].from))], j);
      const std::size_t keep = std::min<std::size_t>(256, byRing.size());
      std::partial_sort(byRing.begin(), byRing.begin() + static_cast<std::ptrdiff_t>(keep), byRing.end());
      std::vector<std::size_t> joints;
      for (std::size_t i = 0; i < keep; ++i) joints.push_back(byRing[i].second);
      cand.clear();
      nearestOf(joints);
      auto dist = [&](const Cand& x) { return std::hypot(pc[x.v].from.x - path.segments[x.j].from.x, pc[x.v].from.y - path.segments[x.j].from.y); };
      std::sort(cand.begin(), cand.end(), [&](const Cand& a, const Cand& b) { return std::make_pair(dist(a), a) < std::make_pair(dist(b), b); });
      spliced = splice(cand);
    }
    if (spliced) ++done; else ++left;
    if (splicedLoops) {   // called again for the loops still left (online): each loop counted once, when spliced
      if (!spliced) continue;
      (*splicedLoops)[li] = 1;
    }
    double turn = 0;   // the loop's own turning: its joints and its arcs
    for (std::size_t i = 0; i < n; ++i) {
      turn += std::abs(coverkit::turnAt(pc[i], pc[(i + 1) % n]));
      if (pc[i].kind == PathSegment::Kind::kArc) turn += pc[i].length() / std::hypot(pc[i].from.x - pc[i].center.x, pc[i].from.y - pc[i].center.y);
    }
    plan.statistics["contours_turning_deg"] += turn * 180 / M_PI;
  }
  plan.statistics["contours_passed"] += static_cast<double>(done);
  plan.statistics["contours_unspliced"] += static_cast<double>(left);
}

/// Mitred corners, second half: a mitred corner whose two lines are still side by side in the path
/// gets its arc back where the lines sweep less than r²/8 that no other piece of the path (nor the
/// arc) does (estimated in doubles from samples every r/8 round the crossing: it decides only which
/// corners stay sharp, never safety; the arc was checked exactly as a piece of its loop). A corner
/// kept costs a stop, or a smaller fillet, so it is kept only where it sweeps something. Where a
/// splice or a sweep's joint now lies at the crossing (the lanes of a grid-aligned map cross there),
/// the lines stay.
void restoreArcs(const PlanningContext& ctx, const std::map<std::pair<double, double>, PathSegment>& mitres, Path& path, Plan& plan) {
  if (mitres.empty()) return;
  const double r = ctx.problem.robots.at(0).radius.get_d();
  auto mitreAt = [&](std::size_t i) -> const PathSegment* {   // the arc, where segments i, i + 1 are a mitred corner
    if (i + 1 >= path.segments.size()) return nullptr;
    const PathSegment &l1 = path.segments[i], &l2 = path.segments[i + 1];
    if (l1.kind != PathSegment::Kind::kLine || l2.kind != PathSegment::Kind::kLine || !(l1.to.x == l2.from.x && l1.to.y == l2.from.y)) return nullptr;
    const auto it = mitres.find({l1.to.x, l1.to.y});
    if (it == mitres.end()) return nullptr;
    const PathSegment& a = it->second;
    return a.from.x == l1.from.x && a.from.y == l1.from.y && a.to.x == l2.to.x && a.to.y == l2.to.y ? &a : nullptr;
  };
  const Box eb = ctx.problem.workspace.bbox();
  CoverIndex index(r, BoxD{eb.xmin.get_d(), eb.ymin.get_d(), eb.xmax.get_d(), eb.ymax.get_d()});
  std::vector<const PathSegment*> arcAt(path.segments.size(), nullptr);
  for (std::size_t i = 0; i < path.segments.size(); ++i) {
    if (const PathSegment* a = mitreAt(i)) {
      arcAt[i] = a;
      index.add(*a);
      ++i;
      continue;
    }
    index.add(path.segments[i]);
  }
  const double step = r / 8;
  const long k = static_cast<long>(std::ceil(2 * r / step));
  std::vector<PathSegment> out;
  out.reserve(path.segments.size());
  std::size_t restored = 0;
  for (std::size_t i = 0; i < path.segments.size(); ++i) {
    if (!arcAt[i]) {
      out.push_back(path.segments[i]);
      continue;
    }
    const PathSegment &l1 = path.segments[i], &l2 = path.segments[i + 1];
    long open = 0;
    for (long iy = -k; iy <= k; ++iy)
      for (long ix = -k; ix <= k; ++ix) {
        const PointD q{l1.to.x + static_cast<double>(ix) * step, l1.to.y + static_cast<double>(iy) * step};
        if ((withinReach(l1, q, r) || withinReach(l2, q, r)) && !index.covered(q)) ++open;
      }
    if (static_cast<double>(open) * step * step >= r * r / 8) {
      out.push_back(l1);
      out.push_back(l2);
    } else {
      out.push_back(*arcAt[i]);
      ++restored;
    }
    ++i;
  }
  path.segments.swap(out);
  plan.statistics["contour_corners_mitred"] = static_cast<double>(mitres.size());
  plan.statistics["contour_corners_restored"] = static_cast<double>(restored);
}

/// Robot centres (sampled every h) reached from the path's own: their area, and the area of those
/// that nothing sweeps after the circles. An estimate, for decisions about coverage only.
struct SampledSweep {
  double reached = 0, open = 0;
};
/// What an online robot knew (Refiner::knownBefore): box b lies in mega-cells it had sensed before
/// piece `when` began. Empty offline.
using KnownBefore = std::function<bool(const BoxD& b, std::size_t when)>;

/// Patches (ours): the places no sweep, pass or lane reaches. The sweeps stay inside their
/// rectangles and the passes within 2r of a contour, so a pocket of C-free between obstacles that
/// stand more than 4r apart across partially occupied mega-cells (large robots among obstacles
/// about a mega-cell in size) is left. Robot centres are sampled every r/2 over the map; those at
/// least 1.02 r from every edge (doubles) that the path's own centres reach through such samples
/// and that lie farther than r from every piece are grouped 4-connected; each group of at least
/// `minArea` r² gets circles. Candidates: circles tangent to a piece of the path (a line, or an arc
/// at the target's projection on it) within 8r of a target, of radius the piece's distance to the
/// target or half of it, that run the piece's way at the tangent point; the targets are the open
/// centre nearest the group's centroid and up to three more, each the open centre farthest from
/// those before (a long or L-shaped group's arms). The candidate that sweeps the most open centres
/// is tried first (then the nearest piece, the full radius before half); its two halves checked
/// exactly (ClearanceChecker), else the next, and none that sweeps less than half of `minArea` r².
/// The robot runs round the circle and on along the piece: 360° of turning, no corner, nothing the
/// piece swept lost. A group gets up to 3 + (its area / 8r²) circles, at most 16; after each, what
/// it still has open is split again into 4-connected parts, each patched on its own. The samples
/// decide only where to try, never safety.
///
/// minArea = +inf makes no circle and only estimates (the statistics are then not written). Online
/// (`known` set): only samples whose reach lies in sensed mega-cells, and only circles tangent to
/// piece j whose every obstacle within r lies in mega-cells sensed before piece j began (the pieces
/// a circle is made of count as the piece it left).
SampledSweep patchBlobs(const PlanningContext& ctx, ClearanceChecker& check, Path& path, Plan& plan, double minArea,
                        const KnownBefore& known = {}) {
  const double r = ctx.problem.robots.at(0).radius.get_d();
  const Box eb = ctx.problem.workspace.bbox();
  const BoxD box{eb.xmin.get_d(), eb.ymin.get_d(), eb.xmax.get_d(), eb.ymax.get_d()};
  const double W = box.xmax - box.xmin, H = box.ymax - box.ymin;
  const double h = std::max(r / 2, std::sqrt(W * H / (4.0 * 1024 * 1024)));
  const long nx = std::max(1L, static_cast<long>(W / h)), ny = std::max(1L, static_cast<long>(H / h));
  auto at = [&](long i, long j) { return PointD{box.xmin + (i + 0.5) * h, box.ymin + (j + 0.5) * h}; };
  const EdgeIndex edges(ctx.problem.workspace, 1.02 * r, box);
  CoverIndex index(r, box);
  for (const PathSegment& p : path.segments) index.add(p);
  // 0: not reached, 1: a free centre the path's centres reach, covered; 2: the same, uncovered
  std::vector<std::uint8_t> state(static_cast<std::size_t>(nx * ny), 0), isFree(static_cast<std::size_t>(nx * ny), 0);
  const std::size_t ever = path.segments.size();
  std::vector<std::size_t> when(path.segments.size());   // online: the piece each piece counts as
  std::iota(when.begin(), when.end(), std::size_t{0});
  for (long j = 0; j < ny; ++j)
    for (long i = 0; i < nx; ++i) {
      const PointD c = at(i, j);
      isFree[static_cast<std::size_t>(j * nx + i)] =
          edges.clearOf(c) && (!known || known(BoxD{c.x - 1.02 * r, c.y - 1.02 * r, c.x + 1.02 * r, c.y + 1.02 * r}, ever));
    }
  std::vector<long> queue;
  for (long k = 0; k < nx * ny; ++k)
    if (isFree[static_cast<std::size_t>(k)] && index.covered(at(k % nx, k / nx))) state[static_cast<std::size_t>(k)] = 1, queue.push_back(k);
  auto neighbours = [&](long k, auto&& f) {
    const long i = k % nx, j = k / nx;
    if (i > 0) f(k - 1);
    if (i + 1 < nx) f(k + 1);
    if (j > 0) f(k - nx);
    if (j + 1 < ny) f(k + nx);
  };
  for (std::size_t q = 0; q < queue.size(); ++q)
    neighbours(queue[q], [&](long n) {
      if (state[static_cast<std::size_t>(n)] || !isFree[static_cast<std::size_t>(n)]) return;
      state[static_cast<std::size_t>(n)] = index.covered(at(n % nx, n / nx)) ? 1 : 2;
      queue.push_back(n);
    });
  // groups of uncovered reached centres
  std::vector<std::vector<long>> groups;
  std::vector<std::uint8_t> seen(state.size(), 0);
  for (long k = 0; k < nx * ny; ++k) {
    if (state[static_cast<std::size_t>(k)] != 2 || seen[static_cast<std::size_t>(k)]) continue;
    std::vector<long> g{k};
    seen[static_cast<std::size_t>(k)] = 1;
    for (std::size_t q = 0; q < g.size(); ++q)
      neighbours(g[q], [&](long n) {
        if (state[static_cast<std::size_t>(n)] == 2 && !seen[static_cast<std::size_t>(n)]) seen[static_cast<std::size_t>(n)] = 1, g.push_back(n);
      });
    if (static_cast<double>(g.size()) * h * h >= minArea * r * r) groups.push_back(std::move(g));
  }
  // A group gets up to 3 + (its area / 8r²) circles in all, at most 16. After a circle, what is
  // left of the group open is split again into 4-connected parts, each of at least `minArea` r²
  // patched on its own with the circles left (and no more than its own area gives; depth first, so
  // a group that stays whole gets its circles one after the other, aimed at what the ones before
  // left): a circle through an open area's middle may cut it in two, and the middle of the two
  // halves together then lies on the circle.
  std::size_t made = 0, left = 0;
  std::vector<std::uint32_t> mark(state.size(), 0);
  std::uint32_t token = 0;
  std::vector<std::pair<std::vector<long>, int>> work;   // (cells, rounds left), a stack
  auto budget = [&](std::size_t cells) { return std::min(16, 3 + static_cast<int>(static_cast<double>(cells) * h * h / (8 * r * r))); };
  for (auto it = groups.rbegin(); it != groups.rend(); ++it) work.emplace_back(std::move(*it), budget(it->size()));
  while (!work.empty()) {
    const std::vector<long> g = std::move(work.back().first);
    const int rounds = work.back().second;
    work.pop_back();
    std::vector<PointD> open;
    std::vector<long> openCells;
    for (long k : g)
      if (!index.covered(at(k % nx, k / nx))) open.push_back(at(k % nx, k / nx)), openCells.push_back(k);
    if (static_cast<double>(open.size()) * h * h < minArea * r * r) continue;
    PointD m{0, 0};
    for (const PointD& p : open) m.x += p.x / static_cast<double>(open.size()), m.y += p.y / static_cast<double>(open.size());
    // targets: the open centre nearest the centroid, then up to three more, each the open centre
    // farthest from the ones before (an L-shaped or ring-shaped group's arms)
    std::vector<PointD> targets;
    {
      PointD c = open.front();
      for (const PointD& p : open)
        if (std::hypot(p.x - m.x, p.y - m.y) < std::hypot(c.x - m.x, c.y - m.y)) c = p;
      targets.push_back(c);
      std::vector<double> dist(open.size());
      for (std::size_t i = 0; i < open.size(); ++i) dist[i] = std::hypot(open[i].x - c.x, open[i].y - c.y);
      for (int t = 0; t < 3; ++t) {
        const std::size_t far = static_cast<std::size_t>(std::max_element(dist.begin(), dist.end()) - dist.begin());
        if (dist[far] < 2 * r) break;
        targets.push_back(open[far]);
        for (std::size_t i = 0; i < open.size(); ++i) dist[i] = std::min(dist[i], std::hypot(open[i].x - open[far].x, open[i].y - open[far].y));
      }
    }
    struct Cand {
      double gain, cost;
      std::size_t j;
      PointD a, o;   // the tangent point on piece j, the circle's centre
      bool operator<(const Cand& x) const { return std::make_tuple(-gain, cost, j) < std::make_tuple(-x.gain, x.cost, x.j); }
    };
    std::vector<Cand> cand, small;   // small: 0.3 of the distance, tried only where no other is clear
    auto addCircles = [&](std::size_t j, PointD f, PointD n, double d) {   // tangent at f, towards n
      for (double k : {1.0, 0.5, 0.3}) {
        const double rho = k * d;
        const PointD o{f.x + rho * n.x, f.y + rho * n.y};
        std::size_t gain = 0;   // open centres the circle sweeps
        for (const PointD& p : open)
          if (std::abs(std::hypot(p.x - o.x, p.y - o.y) - rho) <= r) ++gain;
        (k < 0.5 ? small : cand).push_back({static_cast<double>(gain), d / r + (k < 1 ? 0.5 : 0), j, f, o});
      }
    };
    for (const PointD& c : targets)
      for (std::size_t j = 0; j < path.segments.size(); ++j) {
        const PathSegment& s = path.segments[j];
        if (s.kind == PathSegment::Kind::kLine) {
          const double dx = s.to.x - s.from.x, dy = s.to.y - s.from.y, len = std::hypot(dx, dy);
          if (len < r / 2) continue;
          const double ux = dx / len, uy = dy / len;
          const double t = (c.x - s.from.x) * ux + (c.y - s.from.y) * uy;
          const double side = (c.y - s.from.y) * ux - (c.x - s.from.x) * uy;   // > 0: c left of the line
          const double d = std::abs(side);
          if (t < r / 8 || t > len - r / 8 || d < r / 2 || d > 8 * r) continue;
          addCircles(j, PointD{s.from.x + t * ux, s.from.y + t * uy}, PointD{side > 0 ? -uy : uy, side > 0 ? ux : -ux}, d);
        } else {   // tangent to an arc at c's projection on it, where that lies r/8 inside its ends
          const double R = std::hypot(s.from.x - s.center.x, s.from.y - s.center.y);
          const double vx = c.x - s.center.x, vy = c.y - s.center.y, L = std::hypot(vx, vy);
          if (R < r / 2 || L == 0) continue;
          const double d = std::abs(L - R);
          if (d < r / 2 || d > 8 * r) continue;
          const double sweep = s.length() / R, margin = r / 8 / R;
          double at = std::atan2(vy, vx) - std::atan2(s.from.y - s.center.y, s.from.x - s.center.x);
          if (!s.ccw) at = -at;
          at = std::fmod(at + 4 * M_PI, 2 * M_PI);
          if (at < margin || at > sweep - margin) continue;
          const PointD f{s.center.x + R * vx / L, s.center.y + R * vy / L};
          addCircles(j, f, PointD{(c.x - f.x) / d, (c.y - f.y) / d}, d);
        }
      }
    std::sort(cand.begin(), cand.end());
    std::sort(small.begin(), small.end());
    bool done = false;
    std::vector<const Cand*> order;   // the 32 best of the larger circles, then of the small ones
    for (const std::vector<Cand>* list : {&cand, &small})
      for (std::size_t k = 0; k < list->size() && k < 32; ++k) {
        if ((*list)[k].gain * h * h < minArea * r * r / 2) break;   // sweeps too little of what is open
        order.push_back(&(*list)[k]);
      }
    for (std::size_t k = 0; k < order.size() && !done; ++k) {
      const Cand& x = *order[k];
      const PathSegment s = path.segments[x.j];
      // the circle runs the way the piece heads at the tangent point a: counter-clockwise where its
      // centre lies left of that heading
      const bool line = s.kind == PathSegment::Kind::kLine;
      const PointD head = line ? PointD{s.to.x - s.from.x, s.to.y - s.from.y}
                               : (s.ccw ? PointD{-(x.a.y - s.center.y), x.a.x - s.center.x} : PointD{x.a.y - s.center.y, -(x.a.x - s.center.x)});
      const bool ccw = head.x * (x.o.y - x.a.y) - head.y * (x.o.x - x.a.x) > 0;
      const double reach = std::hypot(x.o.x - x.a.x, x.o.y - x.a.y) + 1.02 * r;   // the circle's and the robot's
      if (known && !known(BoxD{x.o.x - reach, x.o.y - reach, x.o.x + reach, x.o.y + reach}, when[x.j])) continue;
      const PointD far{2 * x.o.x - x.a.x, 2 * x.o.y - x.a.y};
      const PathSegment half1 = PathSegment::arc(x.a, far, x.o, ccw), half2 = PathSegment::arc(far, x.a, x.o, ccw);
      if (!pieceClear(check, half1) || !pieceClear(check, half2)) continue;
      const PathSegment before = line ? PathSegment::line(s.from, x.a) : PathSegment::arc(s.from, x.a, s.center, s.ccw);
      const PathSegment after = line ? PathSegment::line(x.a, s.to) : PathSegment::arc(x.a, s.to, s.center, s.ccw);
      if (!line && (!pieceClear(check, before) || !pieceClear(check, after))) continue;   // a's rounding
      std::vector<PathSegment> ins{before, half1, half2, after};
      index.add(half1);
      index.add(half2);
      path.segments.erase(path.segments.begin() + static_cast<std::ptrdiff_t>(x.j));
      path.segments.insert(path.segments.begin() + static_cast<std::ptrdiff_t>(x.j), ins.begin(), ins.end());
      const std::size_t w = when[x.j];
      when.insert(when.begin() + static_cast<std::ptrdiff_t>(x.j), ins.size() - 1, w);
      done = true;
    }
    if (!done) {
      ++left;
      continue;
    }
    ++made;
    if (rounds <= 1) continue;
    // what is still open, in 4-connected parts; pushed in reverse so the first part comes first
    const std::uint32_t openMark = ++token;
    for (long k : openCells)
      if (!index.covered(at(k % nx, k / nx))) mark[static_cast<std::size_t>(k)] = openMark;
    // each part keeps the group's order of cells (a group left whole is aimed at as before)
    std::vector<long> stack;
    std::size_t nParts = 0;
    for (long k : openCells) {
      if (mark[static_cast<std::size_t>(k)] != openMark) continue;
      const std::uint32_t partMark = ++token;
      ++nParts;
      mark[static_cast<std::size_t>(k)] = partMark;
      stack.assign(1, k);
      while (!stack.empty()) {
        const long q = stack.back();
        stack.pop_back();
        neighbours(q, [&](long n) {
          if (mark[static_cast<std::size_t>(n)] == openMark) mark[static_cast<std::size_t>(n)] = partMark, stack.push_back(n);
        });
      }
    }
    std::vector<std::vector<long>> parts(nParts);
    for (long k : openCells)
      if (mark[static_cast<std::size_t>(k)] > openMark) parts[mark[static_cast<std::size_t>(k)] - openMark - 1].push_back(k);
    for (auto it = parts.rbegin(); it != parts.rend(); ++it)
      if (static_cast<double>(it->size()) * h * h >= minArea * r * r) work.emplace_back(std::move(*it), std::min(rounds - 1, budget(it->size())));
  }
  if (std::isfinite(minArea)) {
    plan.statistics["patches"] = static_cast<double>(made);
    plan.statistics["patches_left"] = static_cast<double>(left);
  }
  SampledSweep out;
  for (long k = 0; k < nx * ny; ++k) {
    if (!state[static_cast<std::size_t>(k)]) continue;
    out.reached += h * h;
    if (state[static_cast<std::size_t>(k)] == 2 && !index.covered(at(k % nx, k / nx))) out.open += h * h;
  }
  return out;
}

/// Taut stretches (ours): a contour of a grid map's obstacle is a staircase of pixels, and its
/// C-space contour a scallop of arcs about the stair's corners meeting in notches: about 30° of
/// turning a pixel each way (ros/depot.yaml at r = 0.25: 2.8 × Full-STC's total turning) for a wall
/// that is straight at the robot's scale. Where a stretch of up to 32 pieces stays within `tau` of
/// the line between its ends (every line's ends and an arc's points every eighth of its angle; in
/// doubles), the line turns less than the stretch with its two joints, and the line is exactly
/// clear (ClearanceChecker), the line replaces it: the longest such stretch from each joint (grown
/// piece by piece until a point strays: linear in the path). What
/// the stretch swept and the line does not lies within `tau` of it. A line whose joint would turn by
/// more than 150° (a reversal: a U-turn narrower than 2 tau) is not taken.
void pullTaut(const PlanningContext& ctx, ClearanceChecker& check, Path& path, Plan& plan, double tau) {
  const std::vector<PathSegment>& in = path.segments;
  constexpr std::size_t kWindow = 32;
  std::vector<PathSegment> out;
  out.reserve(in.size());
  std::size_t taken = 0, replaced = 0;
  auto arcAngle = [](const PathSegment& p) {
    return p.kind == PathSegment::Kind::kArc ? p.length() / std::hypot(p.from.x - p.center.x, p.from.y - p.center.y) : 0.0;
  };
  std::vector<PointD> pts;
  std::size_t i = 0;
  while (i < in.size()) {
    const PointD A = in[i].from;
    // the pieces i .. j-1 as points, grown one piece at a time; the longest j that qualifies first
    pts.clear();
    std::vector<std::size_t> ok;   // j with every point within tau of A → B
    double inner = 0;              // the stretch's own turning (joints inside it and arcs)
    std::vector<double> innerAt;
    for (std::size_t j = i + 1; j <= in.size() && j <= i + kWindow; ++j) {
      const PathSegment& p = in[j - 1];
      if (j > i + 1) inner += std::abs(turnAt(in[j - 2], p));
      inner += arcAngle(p);
      innerAt.push_back(inner);
      if (p.kind == PathSegment::Kind::kArc) {
        const double a0 = std::atan2(p.from.y - p.center.y, p.from.x - p.center.x), rho = std::hypot(p.from.x - p.center.x, p.from.y - p.center.y);
        const double sweep = arcAngle(p) * (p.ccw ? 1 : -1);
        for (int k = 1; k < 8; ++k) pts.push_back({p.center.x + rho * std::cos(a0 + sweep * k / 8), p.center.y + rho * std::sin(a0 + sweep * k / 8)});
      }
      pts.push_back(p.to);
      if (j < i + 2) continue;
      const PointD B = p.to;
      const double dx = B.x - A.x, dy = B.y - A.y, len = std::hypot(dx, dy);
      if (len <= tau) continue;
      bool within = true;
      for (const PointD& q : pts) {
        const double t = ((q.x - A.x) * dx + (q.y - A.y) * dy) / (len * len);
        const double e = t < 0 ? std::hypot(q.x - A.x, q.y - A.y) : t > 1 ? std::hypot(q.x - B.x, q.y - B.y)
                                                                         : std::abs((q.x - A.x) * dy - (q.y - A.y) * dx) / len;
        if (e > tau) {
          within = false;
          break;
        }
      }
      if (!within) break;   // the longest stretch from A that stays within tau: no longer one is tried
      ok.push_back(j);
    }
    bool done = false;
    for (auto it = ok.rbegin(); it != ok.rend() && !done; ++it) {
      const std::size_t j = *it;
      const PathSegment line = PathSegment::line(A, in[j - 1].to);
      double before = innerAt[j - i - 1], after = 0, worst = 0;
      if (!out.empty()) {
        const double t = std::abs(turnAt(out.back(), line));
        before += std::abs(turnAt(out.back(), in[i])), after += t, worst = std::max(worst, t);
      }
      if (j < in.size()) {
        const double t = std::abs(turnAt(line, in[j]));
        before += std::abs(turnAt(in[j - 1], in[j])), after += t, worst = std::max(worst, t);
      }
      if (after >= before - 1e-9 || std::cos(worst) < kReversalCos || !pieceClear(check, line)) continue;
      out.push_back(line);
      ++taken;
      replaced += j - i;
      i = j;
      done = true;
    }
    if (!done) out.push_back(in[i++]);
  }
  path.segments.swap(out);
  plan.statistics["taut_lines"] = static_cast<double>(taken);
  plan.statistics["taut_pieces_replaced"] = static_cast<double>(replaced);
}

void refine(const PlanningContext& ctx, const std::vector<CellIndex>& walk, const ParamSet& params, Path& path, Plan& plan,
            bool online, PocketWalk pocketWalk) {
  const auto t = Clock::now();
  ClearanceChecker check(ctx.problem.workspace, ctx.problem.robots.at(0).radius);
  std::unique_ptr<ObstacleSensor> sensor;
  std::unique_ptr<OnlineSweeper> sweeper;
  if (online) {
    const Rational r = ctx.problem.robots.at(0).radius;
    sensor = std::make_unique<ObstacleSensor>(ctx.problem.workspace, ctx.cells);
    sweeper = std::make_unique<OnlineSweeper>(ctx.problem.workspace, Rational(r + slackOf(ctx.problem.workspace)), 2 * ctx.cells.subSizeD(),
                                              1e-6, params.text("sweeps") == "trace");
  }
  Refiner refiner(ctx, params, check, std::move(pocketWalk), sensor.get(), sweeper.get());
  ContourLoops loops;
  if (!online && passContours(ctx, params)) loops = contourLoops(ctx, check, path, plan, params.text("loop_corners") == "mitre");
  for (const auto& l : loops.start) refiner.precover(l);
  refiner.tour(walk, path);
  if (!loops.start.empty()) spliceLoops(ctx, check, loops.start, path, plan);
  if (!online && params.text("rooms") == "travel") {
    const auto t2 = Clock::now();
    refiner.travel(path, params.text("gaps"));
    plan.timings.emplace_back("rooms and gaps", std::chrono::duration<double>(Clock::now() - t2).count());
  }
  if (online) {
    // the contour loops the path comes to, then the rooms the robot knows from its path, and again
    // from what the rooms' tours and the loops spliced into them came to, until nothing changes
    const auto t2 = Clock::now();
    ContourLoops l;
    if (passContours(ctx, params)) l = contourLoops(ctx, check, path, plan, false);
    l.start.insert(l.start.end(), l.others.begin(), l.others.end());
    std::vector<std::uint8_t> spliced(l.start.size(), 0);
    const bool rooms = params.text("rooms") == "travel";
    for (std::size_t before = static_cast<std::size_t>(-1); before != path.segments.size();) {
      before = path.segments.size();
      if (!l.start.empty()) spliceLoops(ctx, check, l.start, path, plan, true, true, &spliced);
      if (rooms) refiner.travelOnline(path, passContours(ctx, params));
      if (l.start.empty()) break;   // no loops: the rooms pass has done all it can
    }
    plan.statistics["contours_passed"] = static_cast<double>(std::count(spliced.begin(), spliced.end(), std::uint8_t{1}));
    plan.statistics["contours_unspliced"] = static_cast<double>(spliced.size()) - plan.statistics["contours_passed"];
    plan.timings.emplace_back("contours and rooms", std::chrono::duration<double>(Clock::now() - t2).count());
    // the patches, from what the robot had sensed before each piece a circle leaves from
    if (!l.start.empty() && params.text("patches") != "none") {
      refiner.senseAll(path);
      patchBlobs(ctx, check, path, plan, params.number("patches"),
                 [&](const BoxD& b, std::size_t when) { return refiner.knownBefore(b, when); });
      refiner.senseAll(path);   // along the circles: only mega-cells not asked from before
    }
  }
  // the loops of the rooms reached through gaps exactly 2r wide, from a joint within 3r of them
  if (!loops.start.empty() && !loops.others.empty()) spliceLoops(ctx, check, loops.others, path, plan, true);
  if (!online && !loops.start.empty()) restoreArcs(ctx, loops.mitres, path, plan);
  double unswept = 0;   // the share of the coverable region left unswept, estimated (fill_below)
  // offline (online: above, from what the robot sensed; it has no fill_below); without the patches
  // the sampling runs only where corners=auto reads its estimate
  const bool patches = !online && params.text("patches") != "none";
  const bool estimate = !online && params.text("corners") == "auto" && params.number("fill_below") > 0;
  if (!loops.start.empty() && (patches || estimate)) {
    const SampledSweep e = patchBlobs(ctx, check, path, plan, patches ? params.number("patches") : std::numeric_limits<double>::infinity());
    double band = 0;   // the coverable band between C-free and the obstacles: r along every loop
    for (const auto& l : loops.start)
      for (const PathSegment& p : l) band += p.length();
    band *= ctx.problem.robots.at(0).radius.get_d();
    unswept = e.open / (e.reached + band);
    plan.statistics["unswept_share_estimate"] = unswept;
  }
  refiner.report(plan);
  if (sensor) plan.statistics["obstacle_sensor_queries"] = static_cast<double>(sensor->queries());
  dropSlivers(ctx, check, path, plan);
  cutTips(ctx, check, path, plan);
  trimSpurs(ctx, check, path, plan);
  if (!online && params.number("taut") > 0) pullTaut(ctx, check, path, plan, params.number("taut") * ctx.problem.robots.at(0).radius.get_d());
  const std::string corners = params.text("corners");
  if (corners == "fill" || (corners == "auto" && (loops.start.empty() || 1 - unswept < params.number("fill_below"))))
    fillCorners(ctx, check, path, plan);
  plan.timings.emplace_back("sweeps", std::chrono::duration<double>(Clock::now() - t).count());
}

const char* kNoTreeClaim = "swept the C-space contours of the start's component of C-free and what the rooms, gaps and patches reach";

/// Without a tree (StcSkeleton::planWithoutTree: the start's mega-cell is not free, as for a large
/// robot on a small map: ros/turtlebot3_world.yaml at r = 0.5 has no free mega-cell, nor has a 16 m
/// world of 25 discs at r = 1). The path begins with a line from the start, r/4 along the first
/// axis direction (+x, +y, −x, −y) in which it is exactly clear, in two halves so that the loops
/// have a joint to be spliced at, and refine() does the rest with an empty walk: the contour passes
/// of the start's component of C-free, the rooms (with no tree, every free mega-cell the path's
/// sub-cells reach is one), the gaps, the patches. False, and the plan stays invalid_start, when
/// the contour passes are off (contours=none, or auto on a map above its limit: nothing would be
/// covered), or no such line is clear with its middle (the joint) in a component of C-free at
/// r + ε + δ (a start in a corridor exactly 2r wide: no loop is its component's).
bool planFromStart(const PlanningContext& ctx, const ParamSet& params, const Point& start, Plan& plan, bool online, PocketWalk pocketWalk) {
  if (!passContours(ctx, params)) return false;
  const Workspace& w = ctx.problem.workspace;
  const Rational r = ctx.problem.robots.at(0).radius;
  const PointD s{start.x.get_d(), start.y.get_d()};
  const CSpace slack(w, Rational(r + slackOf(w)), 1e-6, ctx.threads);
  ClearanceChecker check(w, r);
  const double q = r.get_d() / 4;
  for (const PointD& d : {PointD{1, 0}, PointD{0, 1}, PointD{-1, 0}, PointD{0, -1}}) {
    const PointD m{s.x + d.x * q / 2, s.y + d.y * q / 2}, e{s.x + d.x * q, s.y + d.y * q};
    // the joint m strictly inside a component (contourLoops finds the start's component from it)
    if (slack.componentOf(Point{exactFromDouble(m.x), exactFromDouble(m.y)}) < 0) continue;
    if (!pieceClear(check, PathSegment::line(s, m)) || !pieceClear(check, PathSegment::line(m, e))) continue;
    Path& path = plan.paths.at(0);
    path.start = s;
    path.segments = {PathSegment::line(s, m), PathSegment::line(m, e)};
    refine(ctx, {}, params, path, plan, online, std::move(pocketWalk));
    plan.status = PlanStatus::kExactSolution;
    plan.message = "no free mega-cell at the start: " + std::string(kNoTreeClaim);
    return true;
  }
  return false;
}

const char* kClaim =
    "covered every sub-cell of the start's component of free mega-cells and swept the C-space contour of the partially "
    "occupied mega-cells beside it and of the runs of them beyond, touring the free mega-cells those cut off where a sweep "
    "reached them";

}  // namespace

bool SmoothStcPlanner::planWithoutTree(const PlanningContext& ctx, const ParamSet& params, const Point& start, Plan& plan) const {
  const graph::GridGraph g = buildGraph(ctx);
  return planFromStart(ctx, params, start, plan, false, [&](CellIndex s) { return tourOfComponent(ctx, g, s, params); });
}

std::string SmoothStcPlanner::description() const {
  return "Smooth-STC (Pham, Moore & Truong 2019), offline: STC over the free mega-cells; each partially occupied "
         "mega-cell beside the tree, and the run of them beyond, is swept along the exact C-space contour (segments and "
         "arcs); free mega-cells cut off by them are toured with their own trees";
}

std::vector<ParamSpec> SmoothStcPlanner::params() const {
  std::vector<ParamSpec> p = StcSkeleton::params();
  for (ParamSpec& e : p)
    if (e.name == "tree") {   // long straight branches: fewer turns (docs/smooth-stc.md)
      e.defaultValue = "auto";
      e.range += "|longest_runs|auto";
      e.help += "; longest_runs: kruskal_straight with vertical branches where a column run of free mega-cells is more "
                "than twice as long as the row run; auto (Smooth-STC's default): whichever of kruskal_straight and "
                "longest_runs (and kruskal_straight's columns-first twin) the tour turns least around";
    }
  for (const ParamSpec& e : entryParam()) {
    p.push_back(e);
    if (e.name == "corners") {   // the contour passes sweep most corners' wedges: see the citation block
      p.back().defaultValue = "auto";
      p.back().range = "auto|fill|keep";
      p.back().help += "; auto: keep where the contours are passed and the path sweeps at least fill_below of the coverable "
                       "region, fill where not";
    }
  }
  p.push_back({"fill_below", ParamType::kDouble, "0.99", "0:1",
               "with corners=auto and the contour passes: fill the corners where the path (with its patches) sweeps less "
               "than this share of the coverable region, estimated from robot centres sampled every r/2 and r along every "
               "contour loop (statistic unswept_share_estimate); 0: never"});
  p.push_back({"rooms", ParamType::kChoice, "travel", "travel|leave",
               "free mega-cells that no tour or sweep reaches (behind a door narrower than a mega-cell): travelled to "
               "along free sub-cells and toured with their own trees (travel), or left (leave, the paper's)"});
  p.push_back({"gaps", ParamType::kChoice, "auto", "auto|leave|visit",
               "with rooms=travel, free sub-cells the path still leaves uncovered (between obstacles closer than a "
               "mega-cell): travelled to and toured depth-first, each group from its nearest sub-cell, each dead end "
               "left the way it was entered, a reversal (visit), or left (leave); auto: visit only the groups of at least "
               "two that hold a sub-cell squeezed between obstacles on two opposite sides (a corridor or door exactly 2r "
               "wide, which the sweeps and contour passes at r + eps cannot enter), leave the rest"});
  p.push_back({"contours", ParamType::kChoice, "auto", "auto|pass|none",
               "one pass along every boundary loop of the start's component of C-free (the walls' and each obstacle's "
               "C-space contour), spliced into the path where it adds the least turning, counted before the detours are "
               "chosen (pass); none (the paper's); auto: pass on maps of at most 20000 vertices (the whole map's C-space "
               "it needs takes longer than the plan beyond)"});
  p.push_back({"loop_corners", ParamType::kChoice, "mitre", "mitre|arc",
               "with the contour passes: the loop's arc round an obstacle's corner (at most 120 degrees, between lines at "
               "least r long) becomes the two tangent lines to their crossing, which sweep the corner's whole square, and "
               "gets its arc back after the tour where that sweeps less than r^2/8 more (mitre); or the C-space contour's "
               "arc (arc)"});
  p.push_back(patchesParam("each circle checked exactly"));
  p.push_back({"taut", ParamType::kDouble, "0.0625", "0:1",
               "stretches of the path (a grid map's staircase contours: scallops of arcs) that stay within this many r of "
               "the line between their ends are replaced by the line where it turns less and is exactly clear; 0: none"});
  p.push_back({"detours", ParamType::kChoice, "needed", "needed|every",
               "sweeps that leave the tour and come back (two corners, 180 degrees more turning): only where they sweep "
               "at least r^2 that the tour and the other sweeps do not (needed), or every one (the paper's)"});
  p.push_back({"post", ParamType::kChoice, "fillet", "fillet|none",
               "what follows the plan in the pipeline (coverkit plan, experiments, Python): the fillet processor, corners "
               "to tangent arcs where exactly clear and what they swept stays swept but for a rim of r/100 (fillet, as --post fillet:rim=0.01), or nothing (none, the paper's "
               "corners)"});
  return p;
}

std::vector<std::string> SmoothStcPlanner::postProcessing(const ParamSet& params) const {
  if (params.text("post") == "fillet") return {"fillet:rim=0.01"};   // rim: see the citation block
  return {};
}

Capabilities SmoothStcPlanner::capabilities() const {
  Capabilities c;
  c.output = "lines+arcs";
  return c;
}


void SmoothStcPlanner::refinePath(const PlanningContext& ctx, const std::vector<CellIndex>& walk, const ParamSet& params, Path& path,
                                  Plan& plan) const {
  const graph::GridGraph g = buildGraph(ctx);
  refine(ctx, walk, params, path, plan, false, [&](CellIndex s) { return tourOfComponent(ctx, g, s, params); });
}

std::string SmoothStcPlanner::coverageClaim() const { return kClaim; }

namespace {

/// The right-angle turns of the circumnavigation around `t`: at each corner of each node where its
/// two arms there are both tree edges (a concave corner of the tour) or neither is (a convex one);
/// where one is, the tour goes straight on.
std::size_t tourTurns(const graph::GridGraph& g, const graph::SpanningTree& t) {
  std::size_t n = 0;
  for (std::size_t v = 0; v < g.size(); ++v) {
    if (!t.contains(static_cast<int>(v))) continue;
    const unsigned m = t.edges[v];
    for (int d = 0; d < 4; ++d) n += (m >> d & 1) == (m >> ((d + 1) & 3) & 1);
  }
  return n;
}

}  // namespace

graph::SpanningTree SmoothStcPlanner::growTree(const graph::GridGraph& g, int root, const ParamSet& params, int rootFirst) const {
  if (params.text("tree") != "auto") return StcSkeleton::growTree(g, root, params, rootFirst);
  // kruskal_straight, its columns-first twin, longest_runs: the first that turns least
  std::array<graph::SpanningTree, 3> trees{graph::buildTree(g, root, graph::TreeStrategy::kKruskalStraight),
                                           graph::kruskalTreeWeighted(g, root, [](int, int d) { return d == graph::kEast; }),
                                           graph::buildTree(g, root, graph::TreeStrategy::kLongestRuns)};
  std::size_t best = 0, turns = tourTurns(g, trees[0]);
  for (std::size_t i = 1; i < trees.size(); ++i)
    if (const std::size_t t = tourTurns(g, trees[i]); t < turns) best = i, turns = t;
  return std::move(trees[best]);
}

std::string SmoothStcOnlinePlanner::description() const {
  return "Smooth-STC (Pham, Moore & Truong 2019), online: the Spiral-STC robot senses its four neighbouring "
         "mega-cells and sweeps the exact C-space contour of each partially occupied one it meets";
}

std::vector<ParamSpec> SmoothStcOnlinePlanner::params() const {
  std::vector<ParamSpec> p = SpiralStcPlanner::params();
  for (const ParamSpec& e : entryParam()) p.push_back(e);
  p.push_back({"contours", ParamType::kChoice, "auto", "auto|pass|none",
               "one pass along each boundary loop of C-free (a wall's or an obstacle's C-space contour) that the path "
               "comes within 3r of, from the first joint there in path order, followed with the sensor (pass); none "
               "(the paper's); auto: pass on maps of at most 20000 vertices"});
  p.push_back({"rooms", ParamType::kChoice, "travel", "travel|leave",
               "free mega-cells that no tour or sweep reaches, once the robot knows them (sensed from where it has "
               "been): after its tour it goes from room to room along known free sub-cells and tours each with its "
               "own tree (travel), or leaves them (leave, the paper's); with the contour passes and no room known, it "
               "goes to the nearest frontier (a known free sub-cell beside a mega-cell it has not sensed) and looks again"});
  p.push_back({"gaps", ParamType::kChoice, "auto", "auto|leave",
               "with rooms=travel and the contour passes, from the end of the path: the nearest free sub-cell left "
               "uncovered that is squeezed between obstacles on two opposite sides (a corridor exactly 2r wide) and its "
               "group, visited depth-first (auto), or left (leave)"});
  p.push_back(patchesParam("each circle checked exactly against the obstacles of mega-cells sensed before the piece it "
                           "leaves from"));
  return p;
}

Capabilities SmoothStcOnlinePlanner::capabilities() const {
  Capabilities c = SpiralStcPlanner::capabilities();
  c.output = "lines+arcs";
  return c;
}


void SmoothStcOnlinePlanner::refinePath(const PlanningContext& ctx, const std::vector<CellIndex>& walk, const ParamSet& params,
                                        Path& path, Plan& plan) const {
  const graph::GridGraph g = buildGraph(ctx);
  refine(ctx, walk, params, path, plan, true, [&](CellIndex s) { return tourFrom(ctx, g, s, params); });
}

std::string SmoothStcOnlinePlanner::coverageClaim() const { return kClaim; }

bool SmoothStcOnlinePlanner::planWithoutTree(const PlanningContext& ctx, const ParamSet& params, const Point& start, Plan& plan) const {
  const graph::GridGraph g = buildGraph(ctx);
  return planFromStart(ctx, params, start, plan, true, [&](CellIndex s) { return tourFrom(ctx, g, s, params); });
}

}  // namespace coverkit::planners
