#pragma once
// Whether a continuation step went back along the path already traced.
//
// The tangent predictor's orientation can flip at a kink of a nonsmooth system
// (the stick-slip corners of many friction contacts), at once or over a few
// tiny steps: LOCA then walks back along the branch it came from and may report
// the range as finished without ever passing the kink. A step is taken for such
// a retrace when it lands on a segment of the path already traced (within a
// tenth of the longer of the two) moving against it (by more than 120
// degrees). A true fold, even taken with a large step, lands on the fold's
// other half, about a step or more away from the traced one.
#include <vector>

#include "cyclone/continuation/ArclengthContinuation.hpp"

namespace cyclone::continuation {

/// Distance between two points in (x, p).
double turnStep(const BranchPoint& a, const BranchPoint& b);

/// Cosine of the turn between the steps a -> b and b -> c in (x, p).
double turnCosine(const BranchPoint& a, const BranchPoint& b, const BranchPoint& c);

/// True when the step b -> c is more than kJumpRatio times as long as a -> b in
/// (x, p). LOCA's adaptive arclength step grows by at most 1.5x per step
/// (aggressiveness 0.5), and a corrector that stays near its predictor makes a
/// chord about as long as the step; a chord five times the last one means
/// Newton converged onto another branch (seen on an 8-sector friction disc: the
/// mean normal displacement fell 5x in one step while the frequency went 18 Hz
/// back).
constexpr double kJumpRatio = 5.0;
bool branchJump(const BranchPoint& a, const BranchPoint& b, const BranchPoint& c);

/// path: the points traced so far, oldest first (the last 50 segments are
/// searched); c: the new point after path.back(). -1 if c continues the
/// branch; otherwise the index in path of the last point that still moved
/// forward along the retraced segment (the kink: the points after it went back).
int retracedFrom(const std::vector<const BranchPoint*>& path, const BranchPoint& c);

/// True when c, the point after path.back(), lies on a segment of the path
/// traced before (within a tenth of the longer of the step and the segment; the
/// last segment, which c continues, excepted) at a place more than
/// kLandingArclengthRatio times the regular step back along the path (the
/// longer of c's step and the last 9 steps), whichever way c moves. A step back
/// at a kink lands about a step behind along the path, or inside the cluster of
/// creeping steps there (the retrace check's business); a path does not come
/// back onto itself otherwise. LOCA's corrector can, from the far side of a
/// kink where the tangent is poor (a chord of a tenth or less of the path's length in
/// between; docs/decisions.md, "LOCA's jump checks"), then go forward along the old path
/// again. Screens the steps over a kink (ArclengthContinuation.cpp: bridgeKink).
constexpr double kLandingArclengthRatio = 2.0;
bool landsOnTracedPath(const std::vector<const BranchPoint*>& path, const BranchPoint& c);

}  // namespace cyclone::continuation
