#pragma once
// Which method of the bad-manifold plugin's manifold misbehaves: the constraint's value.
namespace manifold_throws {

enum Mode : int {
  kTypeNameThrows,
  kDofThrows,
  kParameterThrows,
  kPoseThrows,
  kProjectThrows,
  kDescribeThrows,
  kClosedFormParamsThrows,
  kPoseWithTailThrows,
  kTooManyDof,              // dof() is 7: more parameters than a pose has room for
  kUnnamedParameter,        // parameter(0).name is null
  kNoManifold,              // the matcher appends a branch without a manifold
  kPoseThrowsAwayFromZero,  // passes the solver's check at θ = 0, throws anywhere else
  kStrayBranch,  // a first matcher leaves a branch whose describe() throws and passes; the
                 // second emits a good one
  kWellBehaved,
};

}  // namespace manifold_throws
