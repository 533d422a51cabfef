#include "reference_comparison.hpp"

#include <sstream>

#include "relpos/core/manifold.hpp"
#include "solve_helpers.hpp"

namespace relpos::test {
namespace {

const Feature* mobileLine(const Problem& p) {
  for (const InputConstraint& c : p.constraints)
    if (c.mobile.kind == FeatureKind::kLine) return &c.mobile;
  return nullptr;
}

std::string str(std::size_t i) { return std::to_string(i); }

// The four-spheres problem: each solution is a world line, its poses a 2-DOF set (the spin about
// it and the slide along it). The mobile line is directed, the distances do not see a direction:
// each tangent line carries both directions, which no connected 2-DOF branch holds together — 12
// lines as 24 directed branches, or fewer if a branch covers both; every pose must be on one.
void compareLines(const Problem& p, const Solution& s, const ReferenceRoots& ref,
                  std::vector<std::string>* out) {
  const Feature* line = mobileLine(p);
  if (!line) return out->push_back("no mobile line");
  const Isometry3d flip = lineFlip(p);
  for (std::size_t i = 0; i < ref.poses.size(); ++i) {
    if (!someBranchContains(s, ref.poses[i], 1e-6))
      out->push_back("reference line " + str(i) + " at " + poseText(ref.poses[i]) +
                     " is on no branch");
    if (!someBranchContains(s, ref.poses[i] * flip, 1e-6))
      out->push_back("reference line " + str(i) + ", reversed, is on no branch");
  }
  std::vector<WorldLine> directed, undirected;
  for (std::size_t i = 0; i < s.branches.size(); ++i) {
    if (s.branches[i].manifold->dof() != 2)
      out->push_back("branch " + str(i) + " has " + str(s.branches[i].manifold->dof()) +
                     " DOF, not 2");
    const Isometry3d X = branchPose(s.branches[i]);
    const Feature f = line->placed(X);
    const WorldLine d{f.point - f.point.dot(f.direction) * f.direction, f.direction};
    for (std::size_t j = 0; j < directed.size(); ++j)
      if (lineDistance(d, directed[j]) <= 1e-6)
        out->push_back("branches " + str(j) + " and " + str(i) + " are the same directed line");
    directed.push_back(d);
    const WorldLine u = undirectedLine(p, X);
    bool seen = false;
    for (const WorldLine& w : undirected) seen = seen || lineDistance(u, w) < 1e-6;
    if (!seen) undirected.push_back(u);
  }
  if (undirected.size() != ref.poses.size())
    out->push_back(str(undirected.size()) + " distinct lines, the reference has " +
                   str(ref.poses.size()));
}

}  // namespace

Isometry3d branchPose(const Branch& b) { return b.manifold->pose(referenceParams(*b.manifold)); }

Isometry3d lineFlip(const Problem& p) {
  const Feature* line = mobileLine(p);
  Isometry3d flip = Isometry3d::Identity();
  if (!line) return flip;
  flip.linear() = Eigen::AngleAxisd(kPi, line->direction.unitOrthogonal()).toRotationMatrix();
  flip.translation() = line->point - flip.linear() * line->point;
  return flip;
}

std::vector<std::string> compareWithReference(const Problem& p, const Solution& s,
                                              const ReferenceRoots& ref, bool line_quotient) {
  std::vector<std::string> out;
  std::string where;
  const double worst = worstSampledViolation(p, s, 8, 7, &where);
  if (!(worst < 1e-7))
    out.push_back("a branch pose violates a constraint by " + std::to_string(worst) + ": " + where);
  if (line_quotient) {
    compareLines(p, s, ref, &out);
    return out;
  }
  if (s.branches.size() != ref.poses.size())
    out.push_back(str(s.branches.size()) + " branches, the reference has " + str(ref.poses.size()) +
                  " roots");
  for (std::size_t i = 0; i < ref.poses.size(); ++i)
    if (!someBranchContains(s, ref.poses[i], 1e-6))
      out.push_back("reference root " + str(i) + " at " + poseText(ref.poses[i]) +
                    " is on no branch");
  for (std::size_t i = 0; i < s.branches.size(); ++i) {
    if (s.branches[i].manifold->dof() != 0)
      out.push_back("branch " + str(i) + " has " + str(s.branches[i].manifold->dof()) + " DOF");
    for (std::size_t j = 0; j < i; ++j)
      if (poseDistance(branchPose(s.branches[i]), branchPose(s.branches[j])) <= 1e-6)
        out.push_back("branches " + str(j) + " and " + str(i) + " are the same pose");
  }
  return out;
}

}  // namespace relpos::test
