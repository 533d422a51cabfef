// slvs.h uses memset without including <cstring>.
#include <cstring>
// clang-format off
#include <slvs.h>
// clang-format on

#include <cmath>
#include <map>
#include <tuple>
#include <vector>

#include "peers.hpp"

namespace relpos::compare {
namespace {

constexpr Slvs_hGroup kFixed = 1, kSolved = 2;  // group 2 is solved; group 1 is constant
using K = FeatureKind;

class Builder {
 public:
  explicit Builder(const Isometry3d& X0) {
    origin_ = point3(kSolved, X0.translation());
    normal_ = normal3(kSolved, Quaterniond(X0.linear()));
    frame_ = add(Slvs_MakeWorkplane(next_e_++, kSolved, origin_, normal_));
  }

  // A point of the mobile object (its frame's coordinates), tied rigidly to the frame.
  Slvs_hEntity bodyPoint(const Vector3d& p, const Isometry3d& X0) {
    const auto key = std::make_tuple(p.x(), p.y(), p.z());
    auto it = body_.find(key);
    if (it != body_.end()) return it->second;
    const Slvs_hEntity P = point3(kSolved, X0 * p);
    const Slvs_hParam u = param(kFixed, p.x()), v = param(kFixed, p.y());
    const Slvs_hEntity Q = add(Slvs_MakePoint2d(next_e_++, kSolved, frame_, u, v));
    constrain(SLVS_C_POINTS_COINCIDENT, frame_, 0, P, Q, 0, 0);
    constrain(SLVS_C_PT_PLANE_DISTANCE, SLVS_FREE_IN_3D, p.z(), P, 0, frame_, 0);
    return body_[key] = P;
  }
  Slvs_hEntity bodySegment(const Vector3d& p, const Vector3d& d, const Isometry3d& X0) {
    return segment(kSolved, bodyPoint(p, X0), bodyPoint(p + d.normalized(), X0));
  }
  Slvs_hEntity fixedPoint(const Vector3d& q) { return point3(kFixed, q); }
  Slvs_hEntity fixedSegment(const Vector3d& q, const Vector3d& d) {
    return segment(kFixed, fixedPoint(q), fixedPoint(q + d.normalized()));
  }
  Slvs_hEntity fixedPlane(const Vector3d& q, const Vector3d& n) {
    const Vector3d N = n.normalized(), U = anyPerpendicular(N), V = N.cross(U);
    double w, x, y, z;
    Slvs_MakeQuaternion(U.x(), U.y(), U.z(), V.x(), V.y(), V.z(), &w, &x, &y, &z);
    const Slvs_hEntity o = fixedPoint(q);
    const Slvs_hEntity nn = normal3(kFixed, Quaterniond(w, x, y, z));
    return add(Slvs_MakeWorkplane(next_e_++, kFixed, o, nn));
  }
  Slvs_hEntity freePoint(const Vector3d& start) { return point3(kSolved, start); }

  // A body segment parallel to fixed direction d (either way). libslvs 3.1 aborts on a PARALLEL
  // constraint in 3-D ("Expected constraint to generate a single equation"), so: perpendicular to
  // two fixed directions spanning the plane across d (well conditioned, unlike ANGLE = 0).
  void parallelTo(Slvs_hEntity body_segment, const Vector3d& d) {
    const Vector3d n = d.normalized(), u = anyPerpendicular(n), v = n.cross(u);
    constrain(SLVS_C_PERPENDICULAR, 0, 0, 0, 0, body_segment, fixedSegment(Vector3d::Zero(), u));
    constrain(SLVS_C_PERPENDICULAR, 0, 0, 0, 0, body_segment, fixedSegment(Vector3d::Zero(), v));
  }

  void constrain(int type, Slvs_hEntity wrkpl, double val, Slvs_hEntity a, Slvs_hEntity b,
                 Slvs_hEntity ea, Slvs_hEntity eb) {
    cons_.push_back(Slvs_MakeConstraint(next_c_++, kSolved, type, wrkpl, val, a, b, ea, eb));
  }

  PeerResult solve() {
    Slvs_System sys{};
    sys.param = params_.data();
    sys.params = static_cast<int>(params_.size());
    sys.entity = entities_.data();
    sys.entities = static_cast<int>(entities_.size());
    sys.constraint = cons_.data();
    sys.constraints = static_cast<int>(cons_.size());
    std::vector<Slvs_hConstraint> failed(cons_.size() + 1);
    sys.failed = failed.data();
    sys.faileds = static_cast<int>(failed.size());
    sys.calculateFaileds = 0;
    Slvs_Solve(&sys, kSolved);
    PeerResult r;
    r.converged = sys.result == SLVS_RESULT_OKAY;
    r.dof = sys.dof;
    const Slvs_Entity& o = entity(origin_);
    const Slvs_Entity& n = entity(normal_);
    r.pose.translation() = Vector3d(val(o.param[0]), val(o.param[1]), val(o.param[2]));
    r.pose.linear() =
        Quaterniond(val(n.param[0]), val(n.param[1]), val(n.param[2]), val(n.param[3]))
            .normalized()
            .toRotationMatrix();
    return r;
  }

 private:
  Slvs_hParam param(Slvs_hGroup g, double v) {
    params_.push_back(Slvs_MakeParam(next_p_, g, v));
    return next_p_++;
  }
  Slvs_hEntity add(const Slvs_Entity& e) {
    entities_.push_back(e);
    return e.h;
  }
  Slvs_hEntity point3(Slvs_hGroup g, const Vector3d& p) {
    const Slvs_hParam x = param(g, p.x()), y = param(g, p.y()), z = param(g, p.z());
    return add(Slvs_MakePoint3d(next_e_++, g, x, y, z));
  }
  Slvs_hEntity normal3(Slvs_hGroup g, const Quaterniond& q) {
    const Slvs_hParam w = param(g, q.w()), x = param(g, q.x()), y = param(g, q.y()),
                      z = param(g, q.z());
    return add(Slvs_MakeNormal3d(next_e_++, g, w, x, y, z));
  }
  Slvs_hEntity segment(Slvs_hGroup g, Slvs_hEntity a, Slvs_hEntity b) {
    return add(Slvs_MakeLineSegment(next_e_++, g, SLVS_FREE_IN_3D, a, b));
  }
  const Slvs_Entity& entity(Slvs_hEntity h) const { return entities_[h - 1]; }
  double val(Slvs_hParam h) const { return params_[h - 1].val; }

  std::vector<Slvs_Param> params_;
  std::vector<Slvs_Entity> entities_;
  std::vector<Slvs_Constraint> cons_;
  Slvs_hParam next_p_ = 1;
  Slvs_hEntity next_e_ = 1;
  Slvs_hConstraint next_c_ = 1;
  Slvs_hEntity origin_ = 0, normal_ = 0, frame_ = 0;
  std::map<std::tuple<double, double, double>, Slvs_hEntity> body_;
};

constexpr double kDeg = 180.0 / 3.14159265358979323846;

// States one input constraint; false (with why) when SolveSpace has no way to say it.
bool state(Builder& b, const InputConstraint& c, const Feature& F, const Isometry3d& X0,
           std::string* why) {
  const Feature& M = c.mobile;
  const std::string& t = c.type;
  auto unsupported = [&](const char* what) {
    *why = what;
    return false;
  };
  const bool F_line = F.kind == K::kLine, M_line = M.kind == K::kLine;
  auto body = [&]() { return b.bodyPoint(M.point, X0); };
  auto bodyDir = [&]() { return b.bodySegment(M.point, M.direction, X0); };
  auto fixedDir = [&]() { return b.fixedSegment(F.point, F.direction); };
  if (t == "coincident" || t == "distance") {
    const double v = t == "distance" ? c.value : 0.0;
    if (M.kind == K::kPoint && F.kind == K::kPoint) {
      if (v == 0)
        b.constrain(SLVS_C_POINTS_COINCIDENT, 0, 0, body(), b.fixedPoint(F.point), 0, 0);
      else
        b.constrain(SLVS_C_PT_PT_DISTANCE, 0, v, body(), b.fixedPoint(F.point), 0, 0);
      return true;
    }
    if (M.kind == K::kPoint && F_line) {
      if (v == 0)
        b.constrain(SLVS_C_PT_ON_LINE, 0, 0, body(), 0, fixedDir(), 0);
      else
        b.constrain(SLVS_C_PT_LINE_DISTANCE, 0, v, body(), 0, fixedDir(), 0);
      return true;
    }
    if (M.kind == K::kPoint && F.kind == K::kPlane) {
      b.constrain(SLVS_C_PT_PLANE_DISTANCE, 0, v, body(), 0, b.fixedPlane(F.point, F.direction), 0);
      return true;
    }
    if (F.kind == K::kPlane && M.kind == K::kPlane) {
      b.parallelTo(b.bodySegment(M.point, M.direction, X0), F.direction);
      b.constrain(SLVS_C_PT_PLANE_DISTANCE, 0, v, body(), 0, b.fixedPlane(F.point, F.direction), 0);
      return true;
    }
    if (F_line && M_line && (c.parallel || t == "coincident")) {
      b.parallelTo(bodyDir(), F.direction);
      b.constrain(v == 0 ? SLVS_C_PT_ON_LINE : SLVS_C_PT_LINE_DISTANCE, 0, v, body(), 0, fixedDir(),
                  0);
      return true;
    }
    if (F_line && M_line && v == 0) {  // skew distance 0: the lines meet at a free point
      const Slvs_hEntity x = b.freePoint(F.point);
      b.constrain(SLVS_C_PT_ON_LINE, 0, 0, x, 0, fixedDir(), 0);
      b.constrain(SLVS_C_PT_ON_LINE, 0, 0, x, 0, bodyDir(), 0);
      return true;
    }
    return unsupported("this distance/coincidence has no SolveSpace constraint");
  }
  // Directions: line directions, plane normals.
  const bool F_dir = F_line || F.kind == K::kPlane, M_dir = M_line || M.kind == K::kPlane;
  if (!F_dir || !M_dir) return unsupported("no direction to constrain");
  const bool mixed = (F.kind == K::kPlane) != (M.kind == K::kPlane);  // line vs plane normal
  if (t == "parallel" || t == "perpendicular") {
    if ((t == "parallel") != mixed)
      b.parallelTo(bodyDir(), F.direction);
    else
      b.constrain(SLVS_C_PERPENDICULAR, 0, 0, 0, 0, bodyDir(), fixedDir());
    return true;
  }
  if (t == "angle") {
    const double a = mixed ? 90.0 - c.value * kDeg : c.value * kDeg;  // line-plane: elevation
    b.constrain(SLVS_C_ANGLE, 0, a, 0, 0, bodyDir(), fixedDir());
    return true;
  }
  return unsupported("no SolveSpace constraint for this type");
}

}  // namespace

PeerResult solveWithSolveSpace(const Problem& p) {
  const Isometry3d& X0 = p.mobile.pose;
  Builder b(X0);
  for (const auto& c : p.constraints) {
    if (isRange(c)) {
      PeerResult r;
      r.unsupported = "a range (SolveSpace has no inequalities)";
      return r;
    }
    std::string why;
    if (!state(b, c, c.fixed.placed(p.fixed.pose), X0, &why)) {
      PeerResult r;
      r.unsupported = c.type + ": " + why;
      return r;
    }
  }
  return b.solve();
}

}  // namespace relpos::compare
