// Spec parsing (docs/spec.md §1). Collects every problem it finds rather than stopping at the
// first, so a user fixes a spec in one round. The text is read by simdjson (json_read.hpp); the
// checks here walk its document.
#include <string.h>  // memmem (glibc)

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "json_read.hpp"
#include "relpos/io/spec_reader.hpp"
#include "spec_document.hpp"
#include "suggest.hpp"
#include "utf8.hpp"

namespace relpos {
namespace {

namespace dom = simdjson::dom;
using detail::FeatureNames;
using detail::Json;
using detail::Path;

// A unit vector along v (not zero), without overflow or underflow: v is first scaled by its
// largest component, so the squares summed lie in [1, 3] whatever v's magnitude (1e200 or 1e-300).
template <int N>
Eigen::Matrix<double, N, 1> unitAlong(const Eigen::Matrix<double, N, 1>& v) {
  const Eigen::Matrix<double, N, 1> s = v / v.cwiseAbs().maxCoeff();
  return s / s.norm();
}

class Parser {
 public:
  Parser(const Registry& reg, ParseResult& out) : reg_(reg), out_(out) {}

  // Every message is on one line: echoed names, ids and keys are escaped here.
  void error(const Path& path, const std::string& msg) {
    out_.errors.push_back({detail::escapeForMessage(path.str()), detail::escapeForMessage(msg)});
  }
  void warn(const Path& path, const std::string& msg) {
    out_.warnings.push_back({detail::escapeForMessage(path.str()), detail::escapeForMessage(msg)});
  }

  // The members of an object the checks know, found in one pass over it that also warns about
  // the others: result[k] is the member named known[k], or nothing. (One pass, then O(1)
  // access: looking each key up would scan the members again for every key.) A key seen twice
  // is only noted here (see keysChecked).
  // `unknown_error`: the message that makes an unknown member an error rather than a warning
  // (a pose's: a mistyped key there would silently leave the identity).
  template <std::size_t N>
  std::array<Json, N> fields(const Json& obj, const Path& path,
                             const std::array<std::string_view, N>& known,
                             const char* unknown_error = nullptr) {
    std::array<Json, N> found;
    if (!obj.is_object()) return found;
    std::vector<std::string_view> unknown;  // (allocates only when there are some)
    for (auto it = obj.object().begin(); it != obj.object().end(); ++it) {
      const std::string_view key = it.key();
      std::size_t k = 0;
      while (k < N && known[k] != key) ++k;
      if (k < N) {
        if (found[k].present())
          saw_duplicate_ = true;  // the first one counts
        else
          found[k] = Json(it.value());
        continue;
      }
      const Path field(path, key);
      const std::string hint =
          detail::didYouMean(key, std::vector<std::string_view>(known.begin(), known.end()));
      if (unknown_error)
        error(field, unknown_error + hint);
      else
        warn(field, "unknown field (ignored)" + hint);
      unknown.push_back(key);
      const Json value(it.value());
      if (value.is_object() || value.is_array())
        unvisited_.push_back({value, field.str(), field.depth()});
    }
    if (unknown.size() > 1) {
      std::sort(unknown.begin(), unknown.end());
      saw_duplicate_ =
          saw_duplicate_ || std::adjacent_find(unknown.begin(), unknown.end()) != unknown.end();
    }
    return found;
  }

  // Duplicate keys and nesting beyond the reader's limit, in what `fields` did not see: the
  // values of unknown fields. Everything else of a spec without errors went through `fields`,
  // the feature loop or a one-member feature object, so a duplicate there has been noted; when
  // there are errors (or a noted duplicate), the checks may have stopped short of some value,
  // and the whole document is walked instead. False when the document is too deep.
  bool keysChecked(const Json& root) {
    if (!out_.errors.empty() || saw_duplicate_)
      return detail::checkKeys(root.element(), "", 0, &out_.errors);
    for (const Unvisited& u : unvisited_)
      if (!detail::checkKeys(u.value.element(), u.path, u.depth, &out_.errors)) return false;
    return true;
  }

  // A finite number (the check alone: callers build the path only for the message). The reader
  // refuses numbers beyond a double's range, so a number is always finite; the check stays.
  static bool finiteNumber(const Json& j, double* v) {
    if (!j.is_number()) return false;
    *v = j.number();
    return std::isfinite(*v);
  }

  bool number(const Json& j, const Path& path, double* v) {
    if (finiteNumber(j, v)) return true;
    error(path, j.is_number() ? std::string("not a finite number")
                              : std::string("expected a number, got ") + j.type_name());
    return false;
  }

  bool vec(const Json& j, const Path& path, int n, double* v) {
    if (!j.is_array() || j.size() != static_cast<std::size_t>(n)) {
      error(path, "expected an array of " + std::to_string(n) + " numbers");
      return false;
    }
    bool ok = true;
    std::size_t i = 0;
    for (dom::element e : j.array()) {
      const Json x(e);
      if (!finiteNumber(x, &v[i])) ok = number(x, Path(path, i), &v[i]) && ok;
      ++i;
    }
    return ok;
  }

  bool vec3(const Json& j, const Path& path, Vector3d* v) {
    double a[3];
    if (!vec(j, path, 3, a)) return false;
    *v = Vector3d(a[0], a[1], a[2]);
    return true;
  }

  // A direction is a direction whatever its length (1e-13 or 1e200): only [0, 0, 0] has none.
  bool direction(const Json& d, const Path& path, Vector3d* v) {
    if (!d.present()) {
      error(path, "missing");
      return false;
    }
    if (!vec3(d, path, v)) return false;
    if (v->isZero(0.0)) {
      error(path, "zero-length direction");
      return false;
    }
    *v = unitAlong(*v);
    return true;
  }

  bool point(const Json& p, const Path& path, Vector3d* v) {
    if (!p.present()) {
      error(path, "missing");
      return false;
    }
    return vec3(p, path, v);
  }

  double angleUnit() const { return deg_ ? kPi / 180.0 : 1.0; }

  void units(const Json& j) {
    if (!j.is_object()) return error("units", "expected an object");
    enum { kLength, kAngle };
    const auto f = fields<2>(j, "units", {"length", "angle"});
    if (f[kLength].present() && !f[kLength].is_string()) error("units.length", "expected a string");
    const Json& a = f[kAngle];
    if (a.present()) {
      if (a == "deg")
        deg_ = true;
      else if (!(a == "rad"))
        error("units.angle", "expected \"rad\" or \"deg\"");
    }
  }

  bool matrixPose(const Json& m, const Path& mp, Isometry3d* X) {
    if (!m.is_array() || m.size() != 4) {
      error(mp, "expected 4 rows of 4 numbers");
      return false;
    }
    Eigen::Matrix4d M;
    std::size_t r = 0;
    for (dom::element row_element : m.array()) {
      double row[4];
      if (!vec(Json(row_element), Path(mp, r), 4, row)) return false;
      for (int c = 0; c < 4; ++c) M(static_cast<Eigen::Index>(r), c) = row[c];
      ++r;
    }
    const Matrix3d R = M.topLeftCorner<3, 3>();
    // A rotation's entries lie in [-1, 1]: checking that first keeps R^T R from overflowing.
    const bool rigid = R.cwiseAbs().maxCoeff() <= 1.0 + 1e-6 &&
                       (R.transpose() * R - Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-6 &&
                       std::abs(R.determinant() - 1.0) < 1e-6 &&
                       (M.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() < 1e-12;
    if (!rigid) {
      error(mp,
            "not a rigid transform (rotation must be orthonormal with determinant +1, "
            "last row [0, 0, 0, 1])");
      return false;
    }
    // Re-orthonormalise so later maths sees an exact rotation.
    X->linear() = Quaterniond(R).normalized().toRotationMatrix();
    X->translation() = M.topRightCorner<3, 1>();
    return true;
  }

  bool pose(const Json& j, const Path& path, Isometry3d* X) {
    *X = Isometry3d::Identity();
    if (!j.is_object()) {
      error(path, "expected a pose object");
      return false;
    }
    enum { kPosition, kOrientation, kRpy, kMatrix };
    const auto f = fields<4>(j, path, {"position", "orientation", "rpy", "matrix"},
                             "unknown pose field (a pose has \"position\", \"orientation\", "
                             "\"rpy\" or \"matrix\")");
    const Json &position = f[kPosition], &orientation = f[kOrientation], &rpy = f[kRpy],
               &matrix = f[kMatrix];
    if (matrix.present()) {
      if (position.present() || orientation.present() || rpy.present()) {
        error(path, "give either \"matrix\" or \"position\"/\"orientation\"/\"rpy\", not both");
        return false;
      }
      return matrixPose(matrix, Path(path, "matrix"), X);
    }
    bool ok = true;
    if (position.present()) {
      Vector3d p;
      if (vec3(position, Path(path, "position"), &p))
        X->translation() = p;
      else
        ok = false;
    }
    if (orientation.present() && rpy.present()) {
      error(path, "give either \"orientation\" or \"rpy\", not both");
      return false;
    }
    if (orientation.present()) {
      double q[4];
      if (!vec(orientation, Path(path, "orientation"), 4, q)) return false;
      // Like a direction: any length but zero (normalised without overflow).
      const Eigen::Vector4d xyzw(q[0], q[1], q[2], q[3]);
      if (xyzw.isZero(0.0)) {
        error(Path(path, "orientation"), "zero quaternion");
        return false;
      }
      const Eigen::Vector4d u = unitAlong(xyzw);
      X->linear() = Quaterniond(u[3], u[0], u[1], u[2]).toRotationMatrix();
    }
    if (rpy.present()) {
      double r[3];
      if (!vec(rpy, Path(path, "rpy"), 3, r)) return false;
      const double k = angleUnit();
      X->linear() = (Eigen::AngleAxisd(r[2] * k, Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(r[1] * k, Vector3d::UnitY()) *
                     Eigen::AngleAxisd(r[0] * k, Vector3d::UnitX()))
                        .toRotationMatrix();
    }
    return ok;
  }

  bool feature(const Json& j, const Path& path, Feature* f) {
    if (!j.is_object() || j.size() != 1) {
      error(path,
            "expected an object with exactly one of \"point\", \"line\", \"plane\", "
            "\"cylinder\"");
      return false;
    }
    const auto member = j.object().begin();
    const std::string_view kind = member.key();
    const Json b(member.value());
    const Path bp(path, kind);
    Vector3d p, d;
    if (kind == "point") {
      if (!vec3(b, bp, &p)) return false;
      *f = Feature::makePoint(p);
      return true;
    }
    if (kind != "line" && kind != "plane" && kind != "cylinder") {
      error(bp, "unknown feature kind '" + std::string(kind) +
                    "' (expected point, line, plane or cylinder)");
      return false;
    }
    if (!b.is_object()) {
      error(bp, "expected an object");
      return false;
    }
    const std::string_view dir_key = kind == "plane" ? "normal" : "direction";
    enum { kPoint, kDirection, kRadius };
    std::array<Json, 3> fb;
    if (kind == "cylinder") {
      fb = fields<3>(b, bp, {"point", "direction", "radius"});
    } else {
      const auto two = fields<2>(b, bp, {"point", dir_key});
      fb[kPoint] = two[kPoint], fb[kDirection] = two[kDirection];
    }
    bool ok = point(fb[kPoint], Path(bp, "point"), &p);
    ok = direction(fb[kDirection], Path(bp, dir_key), &d) && ok;
    if (kind == "cylinder") {
      double r = 0;
      const Json& radius = fb[kRadius];
      if (!radius.present()) {
        error(Path(bp, "radius"), "missing");
        ok = false;
      } else if (number(radius, Path(bp, "radius"), &r) && r <= 0) {
        error(Path(bp, "radius"), "radius must be positive");
        ok = false;
      }
      if (ok) *f = Feature::makeCylinder(p, d, r);
      return ok;
    }
    if (ok) *f = kind == "line" ? Feature::makeLine(p, d) : Feature::makePlane(p, d);
    return ok;
  }

  // `names` (when given) receives the features' names, for resolve().
  void object(const Json& j, const Path& path, ObjectSpec* o, bool features_required,
              FeatureNames* names) {
    if (!j.is_object()) return error(path, "expected an object");
    enum { kName, kPose, kFeatures, kMesh, kClearance, kMeshScale };
    const auto f =
        fields<6>(j, path, {"name", "pose", "features", "mesh", "clearance", "mesh_scale"});
    o->name = path.str();
    const Json& name = f[kName];
    if (name.present()) {
      if (name.is_string())
        o->name = std::string(name.string());
      else
        error(Path(path, "name"), "expected a string");
    }
    if (f[kPose].present()) pose(f[kPose], Path(path, "pose"), &o->pose);
    const Json& mesh = f[kMesh];
    if (mesh.present()) {
      if (mesh.is_string())
        o->mesh = std::string(mesh.string());
      else
        error(Path(path, "mesh"), "expected a file name");
    }
    const Json& scale = f[kMeshScale];
    if (scale.present()) {
      const Path at(path, "mesh_scale");
      double k = 1.0;
      if (number(scale, at, &k) && !(k > 0.0))
        error(at, "must be > 0 (a mesh in millimetres in a spec in metres: 0.001)");
      else
        o->mesh_scale = k;
    }
    const Json& clearance = f[kClearance];
    if (clearance.present()) {
      const Path at(path, "clearance");
      double c = 0.0;
      if (path.str() == "mobile")
        warn(at, "ignored: give the clearance on the objects the mobile object keeps away from");
      else if (number(clearance, at, &c) && c < 0)
        error(at, "must be >= 0");
      else
        o->clearance = c;
    }
    const Json& fs = f[kFeatures];
    if (!fs.present()) {
      if (features_required) error(Path(path, "features"), "missing");
      return;
    }
    if (!fs.is_object()) return error(Path(path, "features"), "expected an object");
    const Path features_path(path, "features");
    FeatureNames local;
    FeatureNames& index = names != nullptr ? *names : local;
    o->features.reserve(fs.size());
    for (auto it = fs.object().begin(); it != fs.object().end(); ++it) {
      Feature feat;
      // A name twice is a duplicate key (reported by keysChecked); the first one counts.
      if (!feature(Json(it.value()), Path(features_path, it.key()), &feat)) continue;
      if (index.add(it.key(), o->features.size()))
        o->features.push_back({std::string(it.key()), feat});
      else
        saw_duplicate_ = true;
    }
    // "c.axis" names the axis of a cylinder "c": a feature of that name beside it is ambiguous.
    static constexpr std::string_view kAxis = ".axis";
    for (const NamedFeature& nf : o->features) {
      const std::string_view n = nf.name;
      if (n.size() <= kAxis.size() || n.substr(n.size() - kAxis.size()) != kAxis) continue;
      const std::size_t* base = index.find(n.substr(0, n.size() - kAxis.size()));
      if (base != nullptr && o->features[*base].feature.kind == FeatureKind::kCylinder)
        error(Path(features_path, n), "ambiguous name: '" + nf.name +
                                          "' is also the axis of the cylinder '" +
                                          o->features[*base].name + "'");
    }
  }

  // Resolves a feature name, including "name.axis" for a cylinder's axis.
  bool resolve(const Json& j, const Path& path, const ObjectSpec& o, const FeatureNames& names,
               const char* role, std::string* name, Feature* f) {
    if (!j.is_string()) {
      error(path, "expected a feature name");
      return false;
    }
    const std::string_view wanted = j.string();
    *name = std::string(wanted);
    if (const std::size_t* x = names.find(wanted)) {
      *f = o.features[*x].feature;
      return true;
    }
    static constexpr std::string_view kAxis = ".axis";
    if (wanted.size() > kAxis.size() && wanted.substr(wanted.size() - kAxis.size()) == kAxis) {
      const std::string_view base = wanted.substr(0, wanted.size() - kAxis.size());
      if (const std::size_t* x = names.find(base)) {
        const Feature& b = o.features[*x].feature;
        if (b.kind == FeatureKind::kCylinder) {
          *f = b.axis();
          return true;
        }
        error(path, "'" + std::string(base) + "' is a " + toString(b.kind) +
                        ", only a cylinder has an axis");
        return false;
      }
    }
    std::vector<std::string_view> known;
    for (const NamedFeature& nf : o.features) known.push_back(nf.name);
    error(path, "no feature '" + *name + "' on " + role + " object '" + o.name +
                    "' (it has: " + featureList(o) + ")" + detail::didYouMean(*name, known));
    return false;
  }

  // The names of an object's features for a message: the first kListed, then how many more.
  static std::string featureList(const ObjectSpec& o) {
    constexpr std::size_t kListed = 20;
    if (o.features.empty()) return "no features";
    std::string have;
    for (std::size_t i = 0; i < o.features.size() && i < kListed; ++i)
      have += (i == 0 ? "" : ", ") + o.features[i].name;
    if (o.features.size() > kListed)
      have += " and " + std::to_string(o.features.size() - kListed) + " more";
    return have;
  }

  // Parses one constraint; its problems mention the user's "id" when it has one.
  void constraint(const Json& j, const Path& path, const Problem& pb, InputConstraint* c,
                  bool* ok_out) {
    const std::size_t first_error = out_.errors.size();
    constraintFields(j, path, pb, c, ok_out);
    if (!c->id.empty())
      for (std::size_t i = first_error; i < out_.errors.size(); ++i)
        out_.errors[i].message += " (constraint id '" + detail::escapeForMessage(c->id) + "')";
  }

  void constraintFields(const Json& j, const Path& path, const Problem& pb, InputConstraint* c,
                        bool* ok_out) {
    *ok_out = false;
    if (!j.is_object()) return error(path, "expected an object");
    enum { kType, kFixed, kMobile, kValue, kMin, kMax, kOrientation, kParallel, kId };
    const auto f = fields<9>(
        j, path,
        {"type", "fixed", "mobile", "value", "min", "max", "orientation", "parallel", "id"});
    bool ok = true;
    const Json& id = f[kId];
    if (id.present()) {
      if (id.is_string()) {
        c->id = std::string(id.string());
      } else {
        error(Path(path, "id"), "expected a string");
        ok = false;
      }
    }
    const ConstraintType* type = nullptr;
    const Json& type_json = f[kType];
    if (!type_json.present()) {
      error(Path(path, "type"), "missing");
      ok = false;
    } else if (!type_json.is_string()) {
      error(Path(path, "type"), "expected a string");
      ok = false;
    } else {
      c->type = std::string(type_json.string());
      type = reg_.constraintType(c->type);
      if (!type) {
        std::vector<std::string_view> names;
        for (const ConstraintType& t : reg_.constraintTypes()) names.push_back(t.name);
        const std::string near = detail::closestName(c->type, names);
        error(Path(path, "type"),
              "unknown constraint type '" + c->type + "' (" +
                  (near.empty() ? std::string("load the plugin that provides it")
                                : "did you mean '" + near + "'? else load the plugin that provides it") +
                  ")");
        ok = false;
      }
    }
    const Json &fixed = f[kFixed], &mobile = f[kMobile];
    if (!fixed.present()) {
      error(Path(path, "fixed"), "missing");
      ok = false;
    }
    if (!mobile.present()) {
      error(Path(path, "mobile"), "missing");
      ok = false;
    }
    bool have_f = fixed.present() && resolve(fixed, Path(path, "fixed"), pb.fixed, fixed_names_,
                                             "fixed", &c->fixed_name, &c->fixed);
    bool have_m = mobile.present() && resolve(mobile, Path(path, "mobile"), pb.mobile,
                                              mobile_names_, "mobile", &c->mobile_name, &c->mobile);
    ok = ok && have_f && have_m;
    if (type && have_f && have_m && !type->accepts_pair(c->fixed.kind, c->mobile.kind)) {
      std::string acc;
      for (const auto& p : type->accepts)
        acc +=
            (acc.empty() ? "" : ", ") + std::string(toString(p.fixed)) + "-" + toString(p.mobile);
      error(path, "constraint type '" + c->type + "' does not accept " + toString(c->fixed.kind) +
                      "-" + toString(c->mobile.kind) + " features (fixed-mobile; accepts: " + acc +
                      ")");
      ok = false;
    }
    // Values, in the unit of what the type's value measures.
    const bool takes_value = type && (type->takes_value || type->value_kind != ValueKind::kNone);
    const double k = type && type->value_kind == ValueKind::kAngle ? angleUnit() : 1.0;
    bool vals_ok = true;
    auto num = [&](int field, const char* key, double* v) {
      const Json& x = f[field];
      if (!x.present()) return false;
      if (!number(x, Path(path, key), v)) {
        vals_ok = false;
        return false;
      }
      *v *= k;
      return true;
    };
    double v;
    if (num(kValue, "value", &v)) c->has_value = true, c->value = c->min = c->max = v;
    bool has_min = num(kMin, "min", &c->min), has_max = num(kMax, "max", &c->max);
    if (c->has_value && (has_min || has_max)) {
      error(path, "give either \"value\" or \"min\"/\"max\", not both");
      vals_ok = false;
    }
    if (takes_value && !c->has_value && !has_min && !has_max && vals_ok) {
      error(Path(path, "value"), "missing (a '" + c->type +
                                     "' constraint needs \"value\" or "
                                     "\"min\"/\"max\")");
      vals_ok = false;
    }
    if (type && !takes_value) {
      const std::pair<int, const char*> values[] = {
          {kValue, "value"}, {kMin, "min"}, {kMax, "max"}};
      for (const auto& [field, key] : values)
        if (f[field].present()) warn(Path(path, key), "ignored: '" + c->type + "' takes no value");
      c->has_value = true;
      c->value = c->min = c->max = 0.0;
    }
    if (has_min && has_max && c->min > c->max) {
      error(path, "min " + num2s(c->min / k) + " is greater than max " + num2s(c->max / k));
      vals_ok = false;
    }
    const Json& o = f[kOrientation];
    if (o.present() && type && !type->takes_orientation) {
      warn(Path(path, "orientation"), "ignored: '" + c->type + "' takes no orientation");
    } else if (o.present()) {
      if (o == "aligned")
        c->orientation = Orientation::kAligned;
      else if (o == "opposed")
        c->orientation = Orientation::kOpposed;
      else if (o == "either")
        c->orientation = Orientation::kEither;
      else {
        error(Path(path, "orientation"), "expected \"aligned\", \"opposed\" or \"either\"");
        vals_ok = false;
      }
    }
    const Json& parallel = f[kParallel];
    if (parallel.present()) {
      if (!parallel.is_boolean()) {
        error(Path(path, "parallel"), "expected true or false");
        vals_ok = false;
      } else {
        c->parallel = parallel.boolean();
        if (!(type && readsParallel(*type, c->fixed.kind, c->mobile.kind)))
          warn(Path(path, "parallel"), "only meaningful for a " + parallelUses() + " (ignored)");
      }
    }
    if (ok && vals_ok && type && type->check) {
      std::vector<std::string> problems;
      type->checkValues(*c, problems);  // what a plugin's check throws is one more problem
      for (const auto& p : problems) {
        // "field: message" -> path.field: message
        auto colon = p.find(": ");
        if (colon == std::string::npos)
          error(path, p);
        else
          error(Path(path, p.substr(0, colon)), p.substr(colon + 2));
        vals_ok = false;
      }
    }
    *ok_out = ok && vals_ok;
  }

  static bool readsParallel(const ConstraintType& t, FeatureKind fixed, FeatureKind mobile) {
    return std::any_of(t.parallel_on.begin(), t.parallel_on.end(), [&](const FeaturePair& p) {
      return p.fixed == fixed && p.mobile == mobile;
    });
  }

  // Where "parallel" means something, from the registered types: "line-line distance" for the
  // built-ins.
  std::string parallelUses() const {
    std::string uses;
    for (const ConstraintType& t : reg_.constraintTypes())
      for (const FeaturePair& p : t.parallel_on)
        uses += (uses.empty() ? "" : " or ") + std::string(toString(p.fixed)) + "-" +
                toString(p.mobile) + " " + t.name;
    return uses.empty() ? "constraint type that reads it" : uses;
  }

  static std::string num2s(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
  }

  // False when the document nests too deeply to be read.
  bool document(const Json& j) {
    checks(j);
    if (!keysChecked(j)) return false;
    if (out_.errors.empty()) out_.problem = std::move(problem_);
    return true;
  }

  // "allowed_contacts": names of the fixed object or of obstacles (docs/spec.md §5.2).
  void allowedContacts(const Json& j, Problem& pb) {
    if (!j.is_array()) return error("allowed_contacts", "expected an array of object names");
    std::vector<std::string_view> known{pb.fixed.name};
    for (const ObjectSpec& o : pb.obstacles) known.push_back(o.name);
    const Path list("allowed_contacts");
    std::size_t i = 0;
    for (dom::element e : j.array()) {
      const Json name(e);
      const Path at(list, i++);
      if (!name.is_string()) {
        error(at, "expected an object name (string)");
        continue;
      }
      const std::string_view n = name.string();
      if (std::find(known.begin(), known.end(), n) == known.end()) {
        std::string names;
        for (std::string_view k : known) names += (names.empty() ? "" : ", ") + std::string(k);
        error(at, "no object '" + std::string(n) + "' (the fixed object and the obstacles: " +
                      names + ")" + detail::didYouMean(n, known));
        continue;
      }
      pb.allowed_contacts.emplace_back(n);
    }
  }

  void checks(const Json& j) {
    if (!j.is_object()) return error("", "the spec must be a JSON object");
    enum {
      kRelpos,
      kName,
      kUnits,
      kFixed,
      kMobile,
      kObstacles,
      kConstraints,
      kPlugins,
      kAllowedContacts
    };
    const auto f = fields<9>(j, "",
                             {"relpos", "name", "units", "fixed", "mobile", "obstacles",
                              "constraints", "plugins", "allowed_contacts"});
    const Json& version = f[kRelpos];
    if (version.present() && !(version.is_number() && version.number() == 1))
      error("relpos", "unsupported format version (this relpos reads version 1)");
    const Json& name = f[kName];
    if (name.present()) {
      if (name.is_string())
        out_.name = std::string(name.string());
      else
        error("name", "expected a string");
    }
    Problem& pb = problem_;
    pb.name = out_.name;
    if (f[kUnits].present()) units(f[kUnits]);
    pb.angles_in_degrees = deg_;
    const Json &fixed = f[kFixed], &mobile = f[kMobile], &obstacles = f[kObstacles],
               &plugins = f[kPlugins], &constraints = f[kConstraints];
    if (!fixed.present()) error("fixed", "missing");
    if (!mobile.present()) error("mobile", "missing");
    if (!constraints.present()) error("constraints", "missing");
    if (fixed.present()) object(fixed, "fixed", &pb.fixed, true, &fixed_names_);
    if (mobile.present()) object(mobile, "mobile", &pb.mobile, true, &mobile_names_);
    if (obstacles.present()) {
      const Path obstacles_path("obstacles");
      if (!obstacles.is_array()) {
        error("obstacles", "expected an array");
      } else {
        std::size_t i = 0;
        for (dom::element e : obstacles.array()) {
          ObjectSpec o;
          object(Json(e), Path(obstacles_path, i++), &o, false, nullptr);
          pb.obstacles.push_back(o);
        }
      }
    }
    if (f[kAllowedContacts].present()) allowedContacts(f[kAllowedContacts], pb);
    if (plugins.present()) {  // loaded by the caller before parsing (specPluginPaths)
      if (!plugins.is_array()) {
        error("plugins", "expected an array of plugin paths");
      } else {
        const Path plugins_path("plugins");
        std::size_t i = 0;
        for (dom::element e : plugins.array()) {
          if (!Json(e).is_string()) error(Path(plugins_path, i), "expected a path (string)");
          ++i;
        }
      }
    }
    if (constraints.present()) {
      const Path constraints_path("constraints");
      if (!constraints.is_array()) {
        error("constraints", "expected an array");
      } else {
        if (constraints.size() == 0)
          warn("constraints", "no constraints: every pose is a solution");
        pb.constraints.reserve(constraints.size());
        std::size_t i = 0;
        for (dom::element e : constraints.array()) {
          InputConstraint c;
          bool ok = false;
          constraint(Json(e), Path(constraints_path, i++), pb, &c, &ok);
          if (ok) pb.constraints.push_back(std::move(c));
        }
      }
    }
  }

 private:
  // A value the checks did not look into, for keysChecked.
  struct Unvisited {
    Json value;
    std::string path;
    std::size_t depth;
  };

  const Registry& reg_;
  ParseResult& out_;
  bool deg_ = false;
  FeatureNames fixed_names_, mobile_names_;
  Problem problem_;
  bool saw_duplicate_ = false;
  std::vector<Unvisited> unvisited_;
};

std::string readFile(const std::string& file, std::string* error) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) {
    *error = "is a directory, not a spec file";
    return {};
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    *error = std::string("cannot read the file (") + std::strerror(errno) + ")";
    return {};
  }
  std::stringstream ss;
  ss << in.rdbuf();
  if (in.bad()) {
    *error = std::string("cannot read the file (") + std::strerror(errno) + ")";
    return {};
  }
  return ss.str();
}

}  // namespace

ParseResult parseSpec(std::string_view text, const Registry& registry,
                      const std::string& default_name) {
  ParseResult out;
  out.name = detail::toValidUtf8(default_name);
  detail::JsonRead doc = detail::readJson(text);
  out.errors = std::move(doc.errors);
  // (A problem only if there is no error.)
  if (doc.root && !Parser(registry, out).document(Json(*doc.root))) {
    ParseResult deep;  // too deep: refused as a whole, like malformed JSON
    deep.name = std::move(out.name);
    deep.errors = detail::tooDeep(text);
    return deep;
  }
  return out;
}

ParseResult parseSpecFile(const std::string& file, const Registry& registry) {
  std::string base = file.substr(file.find_last_of('/') + 1);
  auto dot = base.rfind('.');
  if (dot != std::string::npos && dot > 0) base = base.substr(0, dot);
  std::string error;
  const std::string text = readFile(file, &error);
  if (!error.empty()) {
    ParseResult out;
    out.name = detail::toValidUtf8(base);
    out.errors.push_back({"", error});
    return out;
  }
  return parseSpec(text, registry, base);
}

bool mentionsPlugins(std::string_view text) {
  // glibc's memmem (vectorised two-way search): ~10 GB/s, where find() stops at every quote of
  // the document and a Horspool search reaches ~3 GB/s.
  static constexpr std::string_view key = "\"plugins\"";
  if (text.size() < key.size()) return false;  // (an empty view may have no data at all)
  return ::memmem(text.data(), text.size(), key.data(), key.size()) != nullptr;
}

std::vector<std::string> specPluginPathsInText(std::string_view text, const std::string& dir) {
  std::vector<std::string> out;
  if (!mentionsPlugins(text)) return out;  // most specs: no need to parse
  const detail::JsonRead doc = detail::readJson(text);
  if (!doc.root) return out;  // parseSpec reports why
  const Json plugins = Json(*doc.root)["plugins"];
  if (!plugins.is_array()) return out;
  const std::string prefix = dir.empty() || dir.back() == '/' ? dir : dir + "/";
  for (dom::element e : plugins.array()) {
    const Json p(e);
    if (!p.is_string()) continue;
    const std::string_view path = p.string();
    out.push_back(!path.empty() && path[0] == '/' ? std::string(path) : prefix + std::string(path));
  }
  return out;
}

std::vector<std::string> specPluginPaths(const std::string& file) {
  std::string error;
  const std::string text = readFile(file, &error);
  if (!error.empty()) return {};
  const std::string::size_type slash = file.find_last_of('/');
  return specPluginPathsInText(text, slash == std::string::npos ? "" : file.substr(0, slash));
}

std::string formatDiagnostic(const std::string& file, const Diagnostic& d) {
  return detail::escapeForMessage(file + ": " + (d.path.empty() ? "" : d.path + ": ") + d.message);
}

}  // namespace relpos
