// The mixed-manifold matcher (Somani 004 §IV-A): sets whose constraints cannot be split into a
// rotational and a translational part. Today: one line-line distance (skew, or a cylinder-line
// tangency) on its own.
#include "relpos/core/solution.hpp"
#include "relpos/manifolds/builtin.hpp"
#include "relpos/manifolds/line_distance.hpp"

namespace relpos::manifolds {
namespace {

MatchResult matchMixed(MatchContext& ctx) {
  const auto& ts = ctx.set.translational;
  if (!ctx.set.rotational.empty() || ts.size() != 1 || ts[0].kind != FundamentalKind::kLineLine)
    return MatchResult::kNoMatch;
  if (ctx.out.branches.size() >= 64) return MatchResult::kOverflow;
  ctx.out.branches.emplace_back();
  ctx.out.branches.back().manifold.emplace<LineDistanceManifold>(ts[0]);
  return MatchResult::kMatched;
}

}  // namespace

void registerMixedManifolds(Registry& registry) {
  registry.addManifold(
      {"mixed/LineDistance",
       "5 DOF (6 with a range): a mobile line at a skew distance from a fixed line, "
       "as a chain Rz Tz Tx Rx Tz Rz (Somani 004 §IV-A)"});
  registry.addMatcher({"mixed", &matchMixed});
}

}  // namespace relpos::manifolds
