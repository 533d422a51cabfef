// Spec parsing (SPEC.md §1). Collects every problem it finds rather than stopping at the first,
// so a user fixes a spec in one round.
#include <string.h>  // memmem (glibc)

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string_view>

#include "fast_json.hpp"
#include "relpos/core/spec_io.hpp"

namespace relpos {
namespace {

// ordered_json keeps the spec's own order of features (messages list them as the user wrote them).
using json = nlohmann::ordered_json;

// A JSON path ("constraints[2].fixed"), spelled out only when a message needs it: each level
// holds its parent and its key or index, so descending into a valid spec builds no strings.
class Path {
 public:
  Path(const char* root_key) : key_(root_key) {}  // NOLINT: "" is the document itself
  Path(const Path& parent, std::string_view key) : parent_(&parent), key_(key) {}
  Path(const Path& parent, std::size_t index) : parent_(&parent), index_(index), indexed_(true) {}
  std::string str() const {
    std::string s = parent_ != nullptr ? parent_->str() : std::string();
    if (indexed_) return s + "[" + std::to_string(index_) + "]";
    if (!s.empty()) s += '.';
    return s.append(key_);
  }

 private:
  const Path* parent_ = nullptr;
  std::string_view key_;
  std::size_t index_ = 0;
  bool indexed_ = false;
};

// The checks, over either document type: nlohmann's, or FastJson's for the common case.
template <typename Json>
class Parser {
 public:
  using json = Json;

  Parser(const Registry& reg, ParseResult& out) : reg_(reg), out_(out) {}

  void error(const Path& path, const std::string& msg) { out_.errors.push_back({path.str(), msg}); }
  void warn(const Path& path, const std::string& msg) {
    out_.warnings.push_back({path.str(), msg});
  }

  void unknownFields(const json& obj, const Path& path,
                     std::initializer_list<std::string_view> known) {
    if (!obj.is_object()) return;
    for (auto it = obj.begin(); it != obj.end(); ++it) {
      const std::string_view key = it.key();
      bool ok = false;
      for (std::string_view k : known) ok = ok || key == k;
      if (!ok) warn(Path(path, key), "unknown field (ignored)");
    }
  }

  // A finite number (the check alone: callers build the path only for the message).
  static bool finiteNumber(const json& j, double* v) {
    if (!j.is_number()) return false;
    *v = j.template get<double>();
    return std::isfinite(*v);
  }

  bool number(const json& j, const Path& path, double* v) {
    if (finiteNumber(j, v)) return true;
    error(path, j.is_number() ? std::string("not a finite number")
                              : std::string("expected a number, got ") + j.type_name());
    return false;
  }

  bool vec(const json& j, const Path& path, int n, double* v) {
    if (!j.is_array() || static_cast<int>(j.size()) != n) {
      error(path, "expected an array of " + std::to_string(n) + " numbers");
      return false;
    }
    bool ok = true;
    for (int i = 0; i < n; ++i)
      if (!finiteNumber(j[i], &v[i]))
        ok = number(j[i], Path(path, static_cast<std::size_t>(i)), &v[i]) && ok;
    return ok;
  }

  bool vec3(const json& j, const Path& path, Vector3d* v) {
    double a[3];
    if (!vec(j, path, 3, a)) return false;
    *v = Vector3d(a[0], a[1], a[2]);
    return true;
  }

  bool direction(const json& parent, const Path& path, const char* key, Vector3d* v) {
    if (!parent.contains(key)) {
      error(Path(path, key), "missing");
      return false;
    }
    if (!vec3(parent[key], Path(path, key), v)) return false;
    if (v->norm() < 1e-12) {
      error(Path(path, key), "zero-length direction");
      return false;
    }
    v->normalize();
    return true;
  }

  bool point(const json& parent, const Path& path, const char* key, Vector3d* v) {
    if (!parent.contains(key)) {
      error(Path(path, key), "missing");
      return false;
    }
    return vec3(parent[key], Path(path, key), v);
  }

  double angleUnit() const { return deg_ ? kPi / 180.0 : 1.0; }

  void units(const json& j) {
    if (!j.is_object()) return error("units", "expected an object");
    unknownFields(j, "units", {"length", "angle"});
    if (j.contains("length") && !j["length"].is_string())
      error("units.length", "expected a string");
    if (j.contains("angle")) {
      const json& a = j["angle"];
      if (a == "deg")
        deg_ = true;
      else if (a != "rad")
        error("units.angle", "expected \"rad\" or \"deg\"");
    }
  }

  bool pose(const json& j, const Path& path, Isometry3d* X) {
    *X = Isometry3d::Identity();
    if (!j.is_object()) {
      error(path, "expected a pose object");
      return false;
    }
    unknownFields(j, path, {"position", "orientation", "rpy", "matrix"});
    bool ok = true;
    if (j.contains("matrix")) {
      if (j.contains("position") || j.contains("orientation") || j.contains("rpy")) {
        error(path, "give either \"matrix\" or \"position\"/\"orientation\"/\"rpy\", not both");
        return false;
      }
      const json& m = j["matrix"];
      const Path mp(path, "matrix");
      if (!m.is_array() || m.size() != 4) {
        error(mp, "expected 4 rows of 4 numbers");
        return false;
      }
      Eigen::Matrix4d M;
      for (int r = 0; r < 4; ++r) {
        double row[4];
        if (!vec(m[r], Path(mp, static_cast<std::size_t>(r)), 4, row)) return false;
        for (int c = 0; c < 4; ++c) M(r, c) = row[c];
      }
      Matrix3d R = M.topLeftCorner<3, 3>();
      bool rigid = (R.transpose() * R - Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-6 &&
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
    if (j.contains("position")) {
      Vector3d p;
      if (vec3(j["position"], Path(path, "position"), &p))
        X->translation() = p;
      else
        ok = false;
    }
    if (j.contains("orientation") && j.contains("rpy")) {
      error(path, "give either \"orientation\" or \"rpy\", not both");
      return false;
    }
    if (j.contains("orientation")) {
      double q[4];
      if (!vec(j["orientation"], Path(path, "orientation"), 4, q)) return false;
      Quaterniond quat(q[3], q[0], q[1], q[2]);
      if (quat.norm() < 1e-12) {
        error(Path(path, "orientation"), "zero quaternion");
        return false;
      }
      X->linear() = quat.normalized().toRotationMatrix();
    }
    if (j.contains("rpy")) {
      double r[3];
      if (!vec(j["rpy"], Path(path, "rpy"), 3, r)) return false;
      const double k = angleUnit();
      X->linear() = (Eigen::AngleAxisd(r[2] * k, Vector3d::UnitZ()) *
                     Eigen::AngleAxisd(r[1] * k, Vector3d::UnitY()) *
                     Eigen::AngleAxisd(r[0] * k, Vector3d::UnitX()))
                        .toRotationMatrix();
    }
    return ok;
  }

  bool feature(const json& j, const Path& path, Feature* f) {
    if (!j.is_object() || j.size() != 1) {
      error(path,
            "expected an object with exactly one of \"point\", \"line\", \"plane\", "
            "\"cylinder\"");
      return false;
    }
    const std::string kind(j.begin().key());
    const json& b = j.begin().value();
    const Path bp(path, kind);
    Vector3d p, d;
    if (kind == "point") {
      if (!vec3(b, bp, &p)) return false;
      *f = Feature::makePoint(p);
      return true;
    }
    if (kind != "line" && kind != "plane" && kind != "cylinder") {
      error(bp, "unknown feature kind '" + kind + "' (expected point, line, plane or cylinder)");
      return false;
    }
    if (!b.is_object()) {
      error(bp, "expected an object");
      return false;
    }
    const char* dir_key = kind == "plane" ? "normal" : "direction";
    if (kind == "cylinder")
      unknownFields(b, bp, {"point", "direction", "radius"});
    else
      unknownFields(b, bp, {"point", dir_key});
    bool ok = point(b, bp, "point", &p);
    ok = direction(b, bp, dir_key, &d) && ok;
    if (kind == "cylinder") {
      double r = 0;
      if (!b.contains("radius")) {
        error(Path(bp, "radius"), "missing");
        ok = false;
      } else if (number(b["radius"], Path(bp, "radius"), &r) && r <= 0) {
        error(Path(bp, "radius"), "radius must be positive");
        ok = false;
      }
      if (ok) *f = Feature::makeCylinder(p, d, r);
      return ok;
    }
    if (ok) *f = kind == "line" ? Feature::makeLine(p, d) : Feature::makePlane(p, d);
    return ok;
  }

  void object(const json& j, const Path& path, ObjectSpec* o, bool features_required) {
    if (!j.is_object()) return error(path, "expected an object");
    unknownFields(j, path, {"name", "pose", "features", "mesh"});
    o->name = path.str();
    if (j.contains("name")) {
      if (j["name"].is_string())
        o->name = j["name"].template get<std::string>();
      else
        error(Path(path, "name"), "expected a string");
    }
    if (j.contains("pose")) pose(j["pose"], Path(path, "pose"), &o->pose);
    if (j.contains("mesh")) {
      if (j["mesh"].is_string())
        o->mesh = j["mesh"].template get<std::string>();
      else
        error(Path(path, "mesh"), "expected a file name");
    }
    if (!j.contains("features")) {
      if (features_required) error(Path(path, "features"), "missing");
      return;
    }
    const json& fs = j["features"];
    if (!fs.is_object()) return error(Path(path, "features"), "expected an object");
    o->features.reserve(fs.size());
    for (auto it = fs.begin(); it != fs.end(); ++it) {
      Feature f;
      if (feature(it.value(), Path(Path(path, "features"), it.key()), &f))
        o->features.push_back({std::string(it.key()), f});
    }
  }

  // Resolves a feature name, including "name.axis" for a cylinder's axis.
  bool resolve(const json& j, const Path& path, const ObjectSpec& o, const char* role,
               std::string* name, Feature* f) {
    if (!j.is_string()) {
      error(path, "expected a feature name");
      return false;
    }
    *name = j.template get<std::string>();
    if (const Feature* x = o.find(*name)) {
      *f = *x;
      return true;
    }
    const std::string suffix = ".axis";
    if (name->size() > suffix.size() &&
        name->compare(name->size() - suffix.size(), suffix.size(), suffix) == 0) {
      const std::string base = name->substr(0, name->size() - suffix.size());
      if (const Feature* x = o.find(base)) {
        if (x->kind == FeatureKind::kCylinder) {
          *f = x->axis();
          return true;
        }
        error(path, "'" + base + "' is a " + toString(x->kind) + ", only a cylinder has an axis");
        return false;
      }
    }
    std::string have;
    for (const auto& nf : o.features) have += (have.empty() ? "" : ", ") + nf.name;
    error(path, "no feature '" + *name + "' on " + role + " object '" + o.name +
                    "' (it has: " + (have.empty() ? "no features" : have) + ")");
    return false;
  }

  // Parses one constraint; its problems mention the user's "id" when it has one.
  void constraint(const json& j, const Path& path, const Problem& pb, InputConstraint* c,
                  bool* ok_out) {
    const std::size_t first_error = out_.errors.size();
    constraintFields(j, path, pb, c, ok_out);
    if (!c->id.empty())
      for (std::size_t i = first_error; i < out_.errors.size(); ++i)
        out_.errors[i].message += " (constraint id '" + c->id + "')";
  }

  void constraintFields(const json& j, const Path& path, const Problem& pb, InputConstraint* c,
                        bool* ok_out) {
    *ok_out = false;
    if (!j.is_object()) return error(path, "expected an object");
    unknownFields(
        j, path,
        {"type", "fixed", "mobile", "value", "min", "max", "orientation", "parallel", "id"});
    bool ok = true;
    if (j.contains("id")) {
      if (j["id"].is_string()) {
        c->id = j["id"].template get<std::string>();
      } else {
        error(Path(path, "id"), "expected a string");
        ok = false;
      }
    }
    const ConstraintType* type = nullptr;
    if (!j.contains("type")) {
      error(Path(path, "type"), "missing");
      ok = false;
    } else if (!j["type"].is_string()) {
      error(Path(path, "type"), "expected a string");
      ok = false;
    } else {
      c->type = j["type"].template get<std::string>();
      type = reg_.constraintType(c->type);
      if (!type) {
        error(Path(path, "type"),
              "unknown constraint type '" + c->type + "' (load the plugin that provides it)");
        ok = false;
      }
    }
    for (const char* role : {"fixed", "mobile"}) {
      if (!j.contains(role)) {
        error(Path(path, role), "missing");
        ok = false;
      }
    }
    bool have_f = j.contains("fixed") && resolve(j["fixed"], Path(path, "fixed"), pb.fixed, "fixed",
                                                 &c->fixed_name, &c->fixed);
    bool have_m = j.contains("mobile") && resolve(j["mobile"], Path(path, "mobile"), pb.mobile,
                                                  "mobile", &c->mobile_name, &c->mobile);
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
    // Values.
    const bool angle_type = c->type == "angle";
    const double k = angle_type ? angleUnit() : 1.0;
    bool vals_ok = true;
    auto num = [&](const char* key, double* v) {
      if (!j.contains(key)) return false;
      if (!number(j[key], Path(path, key), v)) {
        vals_ok = false;
        return false;
      }
      *v *= k;
      return true;
    };
    double v;
    if (num("value", &v)) c->has_value = true, c->value = c->min = c->max = v;
    bool has_min = num("min", &c->min), has_max = num("max", &c->max);
    if (c->has_value && (has_min || has_max)) {
      error(path, "give either \"value\" or \"min\"/\"max\", not both");
      vals_ok = false;
    }
    if (type && type->takes_value && !c->has_value && !has_min && !has_max && vals_ok) {
      error(Path(path, "value"), "missing (a '" + c->type +
                                     "' constraint needs \"value\" or "
                                     "\"min\"/\"max\")");
      vals_ok = false;
    }
    if (type && !type->takes_value) {
      for (const char* key : {"value", "min", "max"})
        if (j.contains(key)) warn(Path(path, key), "ignored: '" + c->type + "' takes no value");
      c->has_value = true;
      c->value = c->min = c->max = 0.0;
    }
    if (has_min && has_max && c->min > c->max) {
      error(path, "min " + num2s(c->min / k) + " is greater than max " + num2s(c->max / k));
      vals_ok = false;
    }
    if (j.contains("orientation")) {
      const json& o = j["orientation"];
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
    if (j.contains("parallel")) {
      if (!j["parallel"].is_boolean()) {
        error(Path(path, "parallel"), "expected true or false");
        vals_ok = false;
      } else {
        c->parallel = j["parallel"].template get<bool>();
        if (!(c->type == "distance" && c->fixed.kind == FeatureKind::kLine &&
              c->mobile.kind == FeatureKind::kLine))
          warn(Path(path, "parallel"), "only meaningful for a line-line distance (ignored)");
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

  static std::string num2s(double v) {
    std::ostringstream os;
    os << v;
    return os.str();
  }

  void document(const json& j, const std::string& default_name) {
    if (!j.is_object()) return error("", "the spec must be a JSON object");
    unknownFields(
        j, "",
        {"relpos", "name", "units", "fixed", "mobile", "obstacles", "constraints", "plugins"});
    if (j.contains("relpos") && j["relpos"] != 1)
      error("relpos", "unsupported format version (this relpos reads version 1)");
    Problem pb;
    pb.name = default_name;
    if (j.contains("name")) {
      if (j["name"].is_string())
        pb.name = j["name"].template get<std::string>();
      else
        error("name", "expected a string");
    }
    if (j.contains("units")) units(j["units"]);
    for (const char* role : {"fixed", "mobile", "constraints"})
      if (!j.contains(role)) error(role, "missing");
    if (j.contains("fixed")) object(j["fixed"], "fixed", &pb.fixed, true);
    if (j.contains("mobile")) object(j["mobile"], "mobile", &pb.mobile, true);
    if (j.contains("obstacles")) {
      const json& obs = j["obstacles"];
      const Path obstacles_path("obstacles");
      if (!obs.is_array())
        error("obstacles", "expected an array");
      else
        for (std::size_t i = 0; i < obs.size(); ++i) {
          ObjectSpec o;
          object(obs[i], Path(obstacles_path, i), &o, false);
          pb.obstacles.push_back(o);
        }
    }
    if (j.contains("plugins")) {  // loaded by the caller before parsing (specPluginPaths)
      if (!j["plugins"].is_array())
        error("plugins", "expected an array of plugin paths");
      else
        for (std::size_t i = 0; i < j["plugins"].size(); ++i)
          if (!j["plugins"][i].is_string())
            error(Path(Path("plugins"), i), "expected a path (string)");
    }
    if (j.contains("constraints")) {
      const json& cs = j["constraints"];
      const Path constraints_path("constraints");
      if (!cs.is_array()) {
        error("constraints", "expected an array");
      } else {
        if (cs.empty()) warn("constraints", "no constraints: every pose is a solution");
        pb.constraints.reserve(cs.size());
        std::size_t i = 0;
        for (auto it = cs.begin(); it != cs.end(); ++it, ++i) {
          InputConstraint c;
          bool ok = false;
          constraint(*it, Path(constraints_path, i), pb, &c, &ok);
          if (ok) pb.constraints.push_back(std::move(c));
        }
      }
    }
    if (out_.errors.empty()) out_.problem = std::move(pb);
  }

 private:
  const Registry& reg_;
  ParseResult& out_;
  bool deg_ = false;
};

// Line and column of a byte offset (1-based), for parse errors.
void lineColumn(const std::string& text, std::size_t byte, std::size_t* line, std::size_t* col) {
  *line = 1;
  *col = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n')
      ++*line, *col = 1;
    else
      ++*col;
  }
}

}  // namespace

ParseResult parseSpec(const std::string& text, const Registry& registry,
                      const std::string& default_name) {
  // Most specs are plain: read them without building nlohmann's document (fast_json.hpp).
  thread_local detail::FastJson doc;
  if (doc.parse(text)) {
    ParseResult out;
    Parser<detail::FastJson::Ref>(registry, out).document(doc.root(), default_name);
    return out;
  }
  return detail::parseSpecWithNlohmann(text, registry, default_name);
}

namespace detail {

ParseResult parseSpecWithNlohmann(const std::string& text, const Registry& registry,
                                  const std::string& default_name) {
  ParseResult out;
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    std::size_t line, col;
    lineColumn(text, e.byte > 0 ? e.byte - 1 : 0, &line, &col);
    std::string what = e.what();
    auto p = what.find("parse error");
    out.errors.push_back({"", "malformed JSON at line " + std::to_string(line) + ", column " +
                                  std::to_string(col) + ": " +
                                  (p == std::string::npos ? what : what.substr(p))});
    return out;
  } catch (const json::exception& e) {  // e.g. a number too large for a double
    std::string what = e.what();
    auto p = what.find("] ");
    out.errors.push_back(
        {"", "malformed JSON: " + (p == std::string::npos ? what : what.substr(p + 2))});
    return out;
  }
  Parser<json>(registry, out).document(j, default_name);
  return out;
}

}  // namespace detail

ParseResult parseSpecFile(const std::string& file, const Registry& registry) {
  std::ifstream in(file, std::ios::binary);
  if (!in) {
    ParseResult out;
    out.errors.push_back({"", "cannot read the file"});
    return out;
  }
  std::stringstream ss;
  ss << in.rdbuf();
  std::string base = file.substr(file.find_last_of('/') + 1);
  auto dot = base.rfind('.');
  if (dot != std::string::npos && dot > 0) base = base.substr(0, dot);
  return parseSpec(ss.str(), registry, base);
}

bool mentionsPlugins(std::string_view text) {
  // glibc's memmem (vectorised two-way search): ~10 GB/s, where find() stops at every quote of
  // the document and a Horspool search reaches ~3 GB/s.
  static constexpr std::string_view key = "\"plugins\"";
  return ::memmem(text.data(), text.size(), key.data(), key.size()) != nullptr;
}

std::vector<std::string> specPluginPathsInText(const std::string& text, const std::string& dir) {
  std::vector<std::string> out;
  if (!mentionsPlugins(text)) return out;  // most specs: no need to parse
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("plugins") || !j["plugins"].is_array())
    return out;
  const std::string prefix = dir.empty() || dir.back() == '/' ? dir : dir + "/";
  for (const auto& p : j["plugins"])
    if (p.is_string()) {
      const std::string path = p.get<std::string>();
      out.push_back(!path.empty() && path[0] == '/' ? path : prefix + path);
    }
  return out;
}

std::vector<std::string> specPluginPaths(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return {};
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string::size_type slash = file.find_last_of('/');
  return specPluginPathsInText(ss.str(), slash == std::string::npos ? "" : file.substr(0, slash));
}

std::string formatDiagnostic(const std::string& file, const Diagnostic& d) {
  return file + ": " + (d.path.empty() ? "" : d.path + ": ") + d.message;
}

}  // namespace relpos
