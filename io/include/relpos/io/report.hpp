#pragma once
// The result of docs/spec.md §2 as C++ values: what relpos::evaluate (report/) computes from a
// solved problem and what the result writer serialises. Nothing here runs a branch's code: a Report
// is plain data, to hand to a controller, a planner export or bindings. Reused across problems (a
// batch worker keeps one) it keeps its buffers' capacity.
#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "relpos/core/manifold.hpp"
#include "relpos/core/solution.hpp"
#include "relpos/core/solver.hpp"

namespace relpos {

// A pose of a branch: its parameters and X_WM(θ).
struct SamplePose {
  Params parameters{};
  Isometry3d pose = Isometry3d::Identity();
};

// The mobile object touching one object of the collision scene.
struct Contact {
  std::string object;
  double depth;  // penetration depth; negative: the missing distance to the clearance
};

// One branch's collision verdict (docs/spec.md §2 "Collision fields").
struct CollisionReport {
  bool nearest_collides = false;
  std::vector<Contact> nearest_contacts;
  bool has_nearest_free = false;
  NearestPose nearest_free;         // when has_nearest_free
  std::string nearest_free_reason;  // otherwise: why there is none
  std::vector<SamplePose> free_samples;
  int blocked_samples = 0;
};

// What one parameter moves, in world terms (docs/spec.md §2.5, since issue 17): the motion of
// X_WM(θ) as that parameter alone changes, at the branch's nearest pose. Every such motion is a
// screw (Chasles): a rotation when it does not advance along its axis, a translation when it does
// not turn.
struct ParameterMotion {
  // kNone: the pose does not move (a degenerate parameter, e.g. the turn about a circle of
  // radius 0); kUnknown: a plugin's pose function threw beside the nearest pose.
  enum class Type : unsigned char { kNone, kRotation, kTranslation, kScrew, kUnknown };
  Type type = Type::kNone;
  Vector3d axis{0, 0, 0};    // unit: the axis of a rotation or screw, a translation's direction
  Vector3d point{0, 0, 0};   // rotation, screw: the point of the axis nearest the mobile origin
  double pitch = 0.0;        // screw: length advanced along the axis per radian turned
  double rate = 0.0;         // radians (rotation, screw) or length (translation) per unit of θ_i
  int constraint = -1;       // a range parameter: the input constraint whose range it spans
  std::string constraint_id;  // and that constraint's id ("" when it has none)
};
const char* toString(ParameterMotion::Type t);

struct BranchReport {
  int dof = 0;
  int rotational_dof = -1;  // -1 for a mixed manifold (written as null), with translational_dof
  int translational_dof = -1;
  std::string manifold;   // Manifold::describe()
  bool exact = true;      // Branch::exact: a closed form; false: found numerically, `certified`
  Certificate certified;  // Branch::certified (zero for an exact branch)
  std::array<Parameter, kMaxDof> parameters{};
  std::array<ParameterMotion, kMaxDof> motions{};
  NearestPose nearest;           // the branch's pose nearest the initial pose
  std::size_t first_sample = 0;  // its samples: Report::samples[first_sample, + sample_count)
  std::size_t sample_count = 0;
};

struct Report {
  std::string name;
  Status status = Status::kNotSolved;
  bool complete = false;           // Solution::complete: proven that no solution is missing
  bool isolated_complete = false;  // Solution::isolated_complete: no isolated solution missing
  std::string message;  // the solution's, with the user's constraint ids next to the conflicts
  std::vector<BranchReport> branches;
  std::vector<SamplePose> samples;  // every branch's, in branch order (BranchReport::first_sample)
  int best = -1;                    // the branch whose nearest pose is nearest; -1: none
  std::vector<int> conflicts;
  std::vector<int> redundant;
  // Solution::rules (ids) and the table naming them, shared with the Solution: the names stay
  // valid as long as the Report, whatever becomes of the Solution and the Registry.
  std::vector<RuleCaseId> rules;
  std::shared_ptr<const RuleNames> rule_names;
  const char* ruleName(std::size_t i) const { return rule_names->name(rules[i]); }
  double solve_us = 0.0;

  // Collision fields, when evaluated against a scene.
  bool collision_checked = false;
  std::vector<std::string> checked_against;
  double clearance = 0.0;
  std::vector<CollisionReport> collision;  // per branch
  int collision_free_branches = 0;

  const SamplePose* samplesOf(std::size_t b) const {
    return samples.data() + branches[b].first_sample;
  }
};

}  // namespace relpos
