// A manifold that throws from the method the constraint's value names (manifold_throws.hpp), or
// is unusable without throwing, emitted by this plugin's matcher for the type `bad-manifold`:
// the solve (for the cheap methods it checks) or whatever runs the manifold's code after it (the
// result writer's nearest-pose search and samples, the collision filter) must answer
// `unhandled` naming this plugin.
#include "manifold_throws.hpp"

#include <limits>
#include <stdexcept>

#include "relpos/core/branch_sink.hpp"
#include "relpos/core/plugin_api.hpp"
#include "relpos/core/solution.hpp"

namespace manifold_throws {
using namespace relpos;

// The context of the callbacks: the registry's index of this plugin's kind.
std::uint16_t kindOf(const void* context) { return *static_cast<const std::uint16_t*>(context); }
constexpr double kInf = std::numeric_limits<double>::infinity();

void throwIf(bool yes, const char* method) {
  if (yes) throw std::runtime_error(std::string(method) + " blew up");
}

// A slide along x: θ is the offset.
class BadManifold final : public ManifoldBase<BadManifold> {
 public:
  explicit BadManifold(int mode) : mode_(mode) {}
  const char* typeName() const override {
    throwIf(mode_ == kTypeNameThrows, "typeName");
    return "Bad";
  }
  int dof() const override {
    throwIf(mode_ == kDofThrows, "dof");
    return mode_ == kTooManyDof ? kMaxDof + 1 : 1;
  }
  int rotationalDof() const override { return 0; }
  int translationalDof() const override { return 1; }
  Parameter parameter(int) const override {
    throwIf(mode_ == kParameterThrows, "parameter");
    Parameter p;
    p.name = mode_ == kUnnamedParameter ? nullptr : "slide";
    p.kind = ParamKind::kLength;
    p.min = -kInf;
    p.max = kInf;
    return p;
  }
  Isometry3d pose(const Params& theta) const override {
    throwIf(mode_ == kPoseThrows, "pose");
    throwIf(mode_ == kPoseThrowsAwayFromZero && theta[0] != 0.0, "pose away from zero");
    Isometry3d X = Isometry3d::Identity();
    X.translation().x() = theta[0];
    return X;
  }
  Params project(const Isometry3d& X) const override {
    throwIf(mode_ == kProjectThrows, "project");
    Params t{};
    t[0] = mode_ == kPoseThrowsAwayFromZero ? 0.0 : X.translation().x();
    return t;
  }
  std::string describe() const override {
    throwIf(mode_ == kDescribeThrows, "describe");
    return "separable Bad";
  }
  unsigned closedFormParams() const override {
    throwIf(mode_ == kClosedFormParamsThrows, "closedFormParams");
    return mode_ == kPoseWithTailThrows ? 1u : 0u;  // the nearest-pose search calls it then
  }
  Isometry3d poseWithTail(const Isometry3d& X, Params* theta) const override {
    throwIf(mode_ == kPoseWithTailThrows, "poseWithTail");
    return Manifold::poseWithTail(X, theta);
  }

 private:
  int mode_;
};

void decompose(const InputConstraint& c, const Feature&, SourceMask s, Decomposition& out,
               const void* context) {
  Fundamental f;
  f.kind = FundamentalKind::kCustom;
  f.custom = kindOf(context);
  f.lo = f.hi = c.value;
  f.sources = s;
  out.addAlternative().push_back(f);
}

bool ours(const ConstraintSet& set, const void* context) {
  const auto& ts = set.translational;
  return ts.size() == 1 && ts[0].kind == FundamentalKind::kCustom &&
         ts[0].custom == kindOf(context);
}

MatchResult match(MatchContext& ctx, const void* context) {
  if (!ours(ctx.set, context)) return MatchResult::kNoMatch;
  const int mode = static_cast<int>(ctx.set.translational[0].lo);
  const bool added =
      mode == kNoManifold
          ? ctx.branches.add(Branch{})
          : ctx.branches.add<BadManifold>(mode == kStrayBranch ? kWellBehaved : mode);
  return added ? MatchResult::kMatched : MatchResult::kOverflow;
}

// Runs before match(): for kStrayBranch, appends a branch and still says it does not match.
MatchResult leaveAStray(MatchContext& ctx, const void* context) {
  if (ours(ctx.set, context) && ctx.set.translational[0].lo == kStrayBranch)
    ctx.branches.add<BadManifold>(kTooManyDof);
  return MatchResult::kNoMatch;
}

double residual(const Fundamental&, const Isometry3d&, const void*) { return 0.0; }

void registerAll(Registry& registry) {
  const std::uint16_t* kind = registry.keep(
      registry.addCustomKind({"bad-manifold", "leads to the bad manifold", &residual}));
  ConstraintType t;
  t.name = "bad-manifold";
  t.accepts = {{FeatureKind::kPoint, FeatureKind::kPoint}};
  t.takes_value = true;
  t.decompose = &decompose;
  t.context = kind;
  registry.addConstraintType(t);
  registry.addManifold({"Bad", "misbehaves as the constraint's value says", ""});
  registry.addMatcher({"bad-manifold-stray", &leaveAStray, kind});
  registry.addMatcher({"bad-manifold", &match, kind});
}
}  // namespace manifold_throws

RELPOS_PLUGIN(manifold_throws::registerAll)
