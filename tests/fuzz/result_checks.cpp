#include "result_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>

#include "evaluator.hpp"
#include "relpos/core/manifold.hpp"

namespace relpos::fuzz {
namespace {

using json = nlohmann::json;

// The constraint types whose value and bounds are lengths (the rest: angles, or none).
bool lengthValued(const std::string& type) { return type == "distance" || type == "thread"; }

void scaleFeature(Feature& f, double s) {
  f.point /= s;
  f.radius /= s;
}

void scaleObject(ObjectSpec& o, double s) {
  o.pose.translation() /= s;
  for (NamedFeature& f : o.features) scaleFeature(f.feature, s);
}

std::string fmt(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// A result document's reader: each finding names the JSON pointer of what is wrong.
class ResultReader {
 public:
  ResultReader(const Problem& problem, const ResultExpectation& expect, Findings& out)
      : problem_(problem),
        expect_(expect),
        out_(out),
        size_(problemSize(problem)),
        scaled_(scaledProblem(problem, size_)) {}

  void read(const std::string& text) {
    if (!isValidUtf8(text)) return bad("", "the result is not valid UTF-8");
    if (expect_.one_line && text.find('\n') != std::string::npos)
      return bad("", "the result line holds a newline");
    const json j = json::parse(text, nullptr, false);
    if (j.is_discarded()) return bad("", "the result is not one JSON document");
    if (!j.is_object()) return bad("", "the result is not a JSON object");
    noNaNs(j, "");
    if (!j.contains("relpos") || j["relpos"] != 1) bad("/relpos", "not 1");
    if (!j.contains("name") || !j["name"].is_string()) {
      bad("/name", "missing or not a string");
    } else if (expect_.name_known && isValidUtf8(problem_.name) &&
               j["name"].get<std::string>() != problem_.name) {
      bad("/name", "'" + printable(j["name"].get<std::string>()) + "', the spec's is '" +
                       printable(problem_.name) + "'");
    }
    const std::string status = j.value("status", std::string("(none)"));
    if (status != "solved" && status != "inconsistent" && status != "unhandled")
      bad("/status", "'" + printable(status) + "' is not solved, inconsistent or unhandled");
    // complete (docs/spec.md §2.2): proven that no solution is missing — never for unhandled,
    // always for inconsistent.
    if (!j.contains("complete") || !j["complete"].is_boolean()) {
      bad("/complete", "missing or not a boolean");
    } else if (status == "unhandled" && j["complete"].get<bool>()) {
      bad("/complete", "true for an unhandled result");
    } else if (status == "inconsistent" && !j["complete"].get<bool>()) {
      bad("/complete", "false for an inconsistent result (it is only answered when proven)");
    }
    // isolated_complete (§2.2): implied by complete, never for unhandled.
    if (!j.contains("isolated_complete") || !j["isolated_complete"].is_boolean()) {
      bad("/isolated_complete", "missing or not a boolean");
    } else if (status == "unhandled" && j["isolated_complete"].get<bool>()) {
      bad("/isolated_complete", "true for an unhandled result");
    } else if (j.value("complete", false) && !j["isolated_complete"].get<bool>()) {
      bad("/isolated_complete", "false for a complete result");
    }
    if (!j.contains("message") || !j["message"].is_string()) {
      bad("/message", "missing or not a string");
    } else if (status != "solved" && j["message"].get<std::string>().empty()) {
      bad("/message", "empty for an " + status + " result (SPEC: it says why)");
    }
    if (!j.contains("branches") || !j["branches"].is_array())
      return bad("/branches", "missing or not an array");
    const json& branches = j["branches"];
    if (status == "solved" && branches.empty()) bad("/branches", "none for a solved result");
    if (status != "solved" && !branches.empty())
      bad("/branches", std::to_string(branches.size()) + " for an " + status + " result");
    if (!j.contains("best")) {
      bad("/best", "missing");
    } else if (branches.empty() ? !j["best"].is_null() : !j["best"].is_number_integer()) {
      bad("/best", branches.empty() ? "not null without branches" : "not a branch index");
    } else {
      allowed_nulls_.insert("/best");
    }
    indexList(j, "conflicts");
    indexList(j, "redundant");
    if (status == "inconsistent" && j.contains("conflicts") && j["conflicts"].is_array() &&
        j["conflicts"].empty())
      bad("/conflicts", "empty for an inconsistent result");
    if (!j.contains("rules") || !j["rules"].is_array()) bad("/rules", "missing or not an array");
    const json* stats = j.contains("stats") ? &j["stats"] : nullptr;
    if (!stats || !stats->is_object() || !stats->contains("solve_us") ||
        !(*stats)["solve_us"].is_number() || !((*stats)["solve_us"].get<double>() >= 0))
      bad("/stats/solve_us", "missing or not a non-negative number");
    std::vector<double> distances;
    for (std::size_t b = 0; b < branches.size(); ++b)
      distances.push_back(branch(branches[b], "/branches/" + std::to_string(b)));
    if (!distances.empty() && j["best"].is_number_integer()) {
      const long best = j["best"].get<long>();
      const auto first_min = std::min_element(distances.begin(), distances.end());
      if (best < 0 || best >= static_cast<long>(distances.size()))
        bad("/best", std::to_string(best) + " is not a branch index");
      else if (best != first_min - distances.begin())
        bad("/best", "branch " + std::to_string(best) + " at distance " +
                         fmt(distances[static_cast<std::size_t>(best)]) + ", branch " +
                         std::to_string(first_min - distances.begin()) + " is nearer (" +
                         fmt(*first_min) + ")");
    }
    for (const std::string& at : nulls_)
      if (!allowed_nulls_.count(at))
        bad(at, "null (a NaN or infinity written) where SPEC has a number");
  }

 private:
  void bad(const std::string& at, const std::string& what) {
    out_.push_back({"bad-output", (at.empty() ? "" : at + ": ") + what});
  }

  // Every null's pointer, and every number that is not finite.
  void noNaNs(const json& j, const std::string& at) {
    if (j.is_null()) nulls_.push_back(at);
    if (j.is_number_float() && !std::isfinite(j.get<double>())) bad(at, "not a finite number");
    if (j.is_object())
      for (const auto& [k, v] : j.items()) noNaNs(v, at + "/" + k);
    if (j.is_array())
      for (std::size_t i = 0; i < j.size(); ++i) noNaNs(j[i], at + "/" + std::to_string(i));
  }

  void indexList(const json& j, const char* key) {
    const std::string at = std::string("/") + key;
    if (!j.contains(key) || !j[key].is_array()) return bad(at, "missing or not an array");
    for (const json& i : j[key])
      if (!i.is_number_integer() || i.get<long>() < 0 ||
          i.get<long>() >= static_cast<long>(problem_.constraints.size()))
        bad(at, i.dump() + " is not a constraint index");
  }

  // Checks one branch and returns its nearest pose's distance (infinity when unreadable).
  double branch(const json& b, const std::string& at) {
    const double none = std::numeric_limits<double>::infinity();
    if (!b.is_object()) return bad(at, "not an object"), none;
    if (!b.contains("dof") || !b["dof"].is_number_integer() || b["dof"].get<int>() < 0 ||
        b["dof"].get<int>() > kMaxDof)
      return bad(at + "/dof", "missing or not 0 to 6"), none;
    const int dof = b["dof"].get<int>();
    const json r = b.value("rotational_dof", json()), t = b.value("translational_dof", json());
    if (r.is_null() && t.is_null()) {
      allowed_nulls_.insert(at + "/rotational_dof");
      allowed_nulls_.insert(at + "/translational_dof");
    } else if (!r.is_number_integer() || !t.is_number_integer() ||
               r.get<int>() + t.get<int>() != dof) {
      bad(at, "rotational_dof + translational_dof is not dof");
    }
    if (!b.contains("manifold") || !b["manifold"].is_string()) bad(at + "/manifold", "missing");
    // exact, or certified with a finite, non-negative radius and angle (docs/spec.md §2.4).
    if (!b.contains("exact") || !b["exact"].is_boolean()) {
      bad(at + "/exact", "missing or not a boolean");
    } else if (b["exact"].get<bool>() == b.contains("certified")) {
      bad(at + "/certified", b.contains("certified") ? "present on an exact branch"
                                                     : "missing on a branch that is not exact");
    } else if (b.contains("certified")) {
      const json& c = b["certified"];
      for (const char* k : {"radius", "angle"})
        if (!c.is_object() || !c.contains(k) || !c[k].is_number() || !(c[k].get<double>() >= 0))
          bad(at + "/certified/" + k, "missing or not a non-negative number");
    }
    if (!b.contains("parameters") || !b["parameters"].is_array() ||
        b["parameters"].size() != static_cast<std::size_t>(dof))
      return bad(at + "/parameters", "missing or not dof long"), none;
    std::vector<Bounds> bounds;
    for (int i = 0; i < dof; ++i)
      bounds.push_back(parameter(b["parameters"][i], at + "/parameters/" + std::to_string(i)));
    if (!b.contains("nearest")) return bad(at + "/nearest", "missing"), none;
    const json& n = b["nearest"];
    const auto X = pose(n, at + "/nearest", bounds);
    double d = none;
    if (!n.contains("distance") || !n["distance"].is_number() ||
        !(n["distance"].get<double>() >= 0)) {
      bad(at + "/nearest/distance", "missing or not a non-negative number");
    } else {
      d = n["distance"].get<double>();
      if (X) {
        const double again = poseDistance(problem_.mobile.pose, *X);
        const double slack = kRelativeTolerance * (1 + std::max(size_, X->translation().norm()));
        if (!(std::abs(again - d) <= slack))
          bad(at + "/nearest/distance", fmt(d) + ", the pose is " + fmt(again) + " away");
      }
    }
    const bool has_global = b.contains("nearest_global") && b["nearest_global"].is_boolean();
    if (!has_global) bad(at + "/nearest_global", "missing or not a boolean");
    const bool global = has_global && b["nearest_global"].get<bool>();
    if (expect_.samples > 0) {
      if (!b.contains("samples") || !b["samples"].is_array() ||
          b["samples"].size() != static_cast<std::size_t>(expect_.samples))
        return bad(at + "/samples", "missing or not as many as asked for"), d;
      for (std::size_t k = 0; k < b["samples"].size(); ++k) {
        const auto S = pose(b["samples"][k], at + "/samples/" + std::to_string(k), bounds);
        // A nearest pose said to be global: no pose of the branch is nearer, the samples neither.
        if (!global || !S || d == none) continue;
        const double ds = poseDistance(problem_.mobile.pose, *S);
        const double slack = kRelativeTolerance * (1 + std::max(size_, S->translation().norm()));
        if (ds < d - slack)
          bad(at + "/samples/" + std::to_string(k),
              fmt(ds) + " away, nearer than the global nearest pose's " + fmt(d));
      }
    } else if (b.contains("samples")) {
      bad(at + "/samples", "present though none were asked for");
    }
    return d;
  }

  struct Bounds {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool periodic = false;
  };

  Bounds parameter(const json& p, const std::string& at) {
    Bounds bounds;
    if (!p.is_object() || !p.contains("name") || !p["name"].is_string() || !p.contains("kind") ||
        !p["kind"].is_string())
      return bad(at, "not a parameter {name, kind, min, max, periodic}"), bounds;
    const std::string kind = p["kind"].get<std::string>();
    if (kind != "angle" && kind != "length" && kind != "other") bad(at + "/kind", "'" + kind + "'");
    for (const char* side : {"min", "max"}) {
      const std::string where = at + "/" + side;
      if (!p.contains(side)) {
        bad(where, "missing");
      } else if (p[side].is_null()) {
        if (kind == "length") allowed_nulls_.insert(where);  // unbounded (docs/spec.md §2)
      } else if (!p[side].is_number()) {
        bad(where, "not a number");
      } else {
        (side[1] == 'i' ? bounds.min : bounds.max) = p[side].get<double>();
      }
    }
    if (!(bounds.min <= bounds.max))
      bad(at, "min " + fmt(bounds.min) + " > max " + fmt(bounds.max));
    if (!p.contains("periodic") || !p["periodic"].is_boolean())
      bad(at + "/periodic", "missing or not a boolean");
    else
      bounds.periodic = p["periodic"].get<bool>();
    return bounds;
  }

  // Reads a pose {parameters, position, orientation}, checks its parameters lie within their
  // bounds and that it satisfies every input constraint.
  std::optional<Isometry3d> pose(const json& p, const std::string& at,
                                 const std::vector<Bounds>& bounds) {
    if (!p.is_object()) return bad(at, "not a pose"), std::nullopt;
    auto numbers = [&](const char* key, std::size_t n, double* v) {
      if (!p.contains(key) || !p[key].is_array() || p[key].size() != n)
        return bad(at + "/" + key, "missing or not " + std::to_string(n) + " numbers"), false;
      for (std::size_t i = 0; i < n; ++i) {
        if (!p[key][i].is_number()) return false;  // a null: reported by noNaNs
        v[i] = p[key][i].get<double>();
      }
      return true;
    };
    double theta[kMaxDof], t[3], q[4];
    if (numbers("parameters", bounds.size(), theta))
      for (std::size_t i = 0; i < bounds.size(); ++i) {
        const Bounds& b = bounds[i];
        double magnitude = 1;
        for (double x : {b.min, b.max})
          if (std::isfinite(x)) magnitude = std::max(magnitude, std::abs(x));
        const double slack = 1e-12 * magnitude;
        if (!b.periodic && !(theta[i] >= b.min - slack && theta[i] <= b.max + slack))
          bad(at + "/parameters/" + std::to_string(i),
              fmt(theta[i]) + " outside [" + fmt(b.min) + ", " + fmt(b.max) + "]");
      }
    if (!numbers("position", 3, t) || !numbers("orientation", 4, q)) return std::nullopt;
    const Quaterniond quat(q[3], q[0], q[1], q[2]);
    if (!(std::abs(quat.norm() - 1) <= 1e-9) || !(q[3] >= 0))
      bad(at + "/orientation", "not a unit quaternion with w >= 0");
    Isometry3d X = Isometry3d::Identity();
    X.linear() = quat.normalized().toRotationMatrix();
    X.translation() = Vector3d(t[0], t[1], t[2]);
    if (!X.matrix().allFinite()) return std::nullopt;
    // Lengths in units of the problem's size — or of this pose's distance from the origin when
    // that is larger (samples along an unbounded length reach ± --window): rounding grows with
    // the coordinates a pose is evaluated at.
    const double reach = std::max(1.0, X.translation().norm() / size_);
    Isometry3d Xs = X;
    Xs.translation() /= size_;
    int which = -1;
    const double v = test::worstViolation(scaled_, Xs, &which);
    if (!(v <= kRelativeTolerance * reach)) {
      const InputConstraint& c = problem_.constraints[static_cast<std::size_t>(std::max(which, 0))];
      out_.push_back({"wrong-answer", at + ": violates constraints[" + std::to_string(which) +
                                          "] (" + c.type + " " + printable(c.fixed_name) + " " +
                                          printable(c.mobile_name) + ") by " + fmt(v) +
                                          " (relative to the problem's size " + fmt(size_) + ")"});
    }
    return X;
  }

  const Problem& problem_;
  const ResultExpectation& expect_;
  Findings& out_;
  const double size_;
  const Problem scaled_;
  std::vector<std::string> nulls_;
  std::set<std::string> allowed_nulls_;
};

}  // namespace

double problemSize(const Problem& p) {
  double s = p.lengthScale();
  for (const InputConstraint& c : p.constraints)
    if (lengthValued(c.type))
      for (double b : {c.min, c.max})
        if (std::isfinite(b)) s = std::max(s, std::abs(b));
  // No extent at all (every feature at one point, no length stated): no scale to be relative
  // to. The solver's tolerance is then absolute (Tolerance::forScale floors the scale at 1), and
  // so is the check — relative to 1e-300, a sample 0.3 along a free line overflowed to an
  // infinite violation (regressions/no-extent-free-line.json).
  if (s == 0.0) return 1.0;
  return std::isfinite(s) ? std::max(s, 1e-300) : 1e-300;
}

Problem scaledProblem(const Problem& p, double size) {
  Problem q = p;
  scaleObject(q.fixed, size);
  scaleObject(q.mobile, size);
  for (ObjectSpec& o : q.obstacles) scaleObject(o, size);
  for (InputConstraint& c : q.constraints) {
    scaleFeature(c.fixed, size);
    scaleFeature(c.mobile, size);
    if (!lengthValued(c.type)) continue;
    c.value /= size;
    c.min /= size;
    c.max /= size;
  }
  return q;
}

bool isValidUtf8(std::string_view s) {
  const auto* p = reinterpret_cast<const unsigned char*>(s.data());
  const std::size_t n = s.size();
  for (std::size_t i = 0; i < n;) {
    const unsigned c = p[i];
    if (c < 0x80) {
      ++i;
      continue;
    }
    std::size_t len;
    unsigned lo = 0x80, hi = 0xBF;  // the second byte's range (excludes overlongs, surrogates)
    if (c >= 0xC2 && c <= 0xDF) {
      len = 2;
    } else if (c >= 0xE0 && c <= 0xEF) {
      len = 3;
      if (c == 0xE0) lo = 0xA0;
      if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      len = 4;
      if (c == 0xF0) lo = 0x90;
      if (c == 0xF4) hi = 0x8F;
    } else {
      return false;
    }
    if (i + len > n || p[i + 1] < lo || p[i + 1] > hi) return false;
    for (std::size_t k = 2; k < len; ++k)
      if (p[i + k] < 0x80 || p[i + k] > 0xBF) return false;
    i += len;
  }
  return true;
}

void checkResultText(const std::string& text, const Problem& problem,
                     const ResultExpectation& expect, Findings& out) {
  ResultReader(problem, expect, out).read(text);
}

void checkProblem(const Problem& p, Findings& out) {
  auto bad = [&](const std::string& what) { out.push_back({"bad-problem", what}); };
  auto feature = [&](const Feature& f, const std::string& where) {
    if (!f.point.allFinite() || !std::isfinite(f.radius))
      bad(where + ": a number that is not finite");
    if (f.kind != FeatureKind::kPoint && !(std::abs(f.direction.norm() - 1) <= 1e-9))
      bad(where + ": a direction of length " + fmt(f.direction.norm()) + " (not unit)");
    if (f.kind == FeatureKind::kCylinder && !(f.radius >= 0)) bad(where + ": a negative radius");
  };
  auto pose = [&](const Isometry3d& X, const std::string& where) {
    if (!X.matrix().allFinite()) return bad(where + ": a pose that is not finite");
    const Matrix3d R = X.linear();
    if (!((R.transpose() * R - Matrix3d::Identity()).norm() <= 1e-9) || !(R.determinant() > 0))
      bad(where + ": a pose that is not rigid");
  };
  for (const auto* o : {&p.fixed, &p.mobile}) {
    const std::string side = o == &p.fixed ? "fixed" : "mobile";
    pose(o->pose, side + ".pose");
    for (const NamedFeature& f : o->features)
      feature(f.feature, side + ".features." + printable(f.name));
  }
  for (std::size_t i = 0; i < p.constraints.size(); ++i) {
    const InputConstraint& c = p.constraints[i];
    const std::string at = "constraints[" + std::to_string(i) + "]";
    feature(c.fixed, at + ".fixed");
    feature(c.mobile, at + ".mobile");
    if (c.has_value && !std::isfinite(c.value)) bad(at + ": a value that is not finite");
    if (std::isnan(c.min) || std::isnan(c.max))
      bad(at + ": bounds [" + fmt(c.min) + ", " + fmt(c.max) + "]");
  }
}

namespace {

// Whether m holds "line L, column C" from i on (i is moved past it).
bool lineColumnAt(std::string_view m, std::size_t& i) {
  auto word = [&](std::string_view w) {
    if (m.substr(i, w.size()) != w) return false;
    i += w.size();
    return true;
  };
  auto digits = [&] {
    const std::size_t from = i;
    while (i < m.size() && m[i] >= '0' && m[i] <= '9') ++i;
    return i > from;
  };
  return word("line ") && digits() && word(", column ") && digits();
}

}  // namespace

bool namesTheDocument(std::string_view m) {
  if (m == "the spec must be a JSON object") return true;
  for (std::string_view head : {"malformed JSON at ", "too deeply nested at "}) {
    std::size_t i = head.size();
    if (m.substr(0, i) == head && lineColumnAt(m, i)) return true;
  }
  // "... (line L, column C)" at the end: a value (the root's path is the empty one) in the text.
  const std::size_t open = m.rfind('(');
  if (open == std::string_view::npos || m.back() != ')') return false;
  std::size_t i = open + 1;
  return lineColumnAt(m, i) && i == m.size() - 1;
}

void checkDiagnostics(const ParseResult& r, Findings& out, bool one_line) {
  if (r.problem && !r.errors.empty())
    out.push_back({"bad-output", "a problem was given together with errors"});
  if (!r.problem && r.errors.empty())
    out.push_back({"bad-output", "neither a problem nor an error"});
  for (const auto* list : {&r.errors, &r.warnings})
    for (const Diagnostic& d : *list) {
      const std::string shown = "'" + printable(d.path) + "': '" + printable(d.message) + "'";
      if (one_line &&
          (d.path.find('\n') != std::string::npos || d.message.find('\n') != std::string::npos))
        out.push_back({"split-diagnostic", "a diagnostic holds a newline: " + shown});
      if (d.path.empty() && !namesTheDocument(d.message))
        out.push_back({"pathless-message", "no JSON path: " + shown});
    }
}

void checkAccepted(std::string_view text, const ParseResult& r, Findings& out) {
  if (!r.problem) return;
  checkProblem(*r.problem, out);
  // Up to the first NUL: what a reader that stops there has read (the rest it has not).
  const std::string_view read = text.substr(0, text.find('\0'));
  if (!isValidUtf8(read))
    out.push_back({"accepted-invalid-json", "a spec that is not UTF-8 was read"});
  for (std::size_t i = 0; i < read.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(read[i]);
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r') {
      out.push_back({"accepted-invalid-json", "a spec holding the raw byte " +
                                                  printable(read.substr(i, 1)) + " at offset " +
                                                  std::to_string(i) + " was read"});
      return;
    }
  }
  if (read.size() < text.size())
    out.push_back({"accepted-invalid-json", "a spec holding the raw byte \\x00 at offset " +
                                                std::to_string(read.size()) + " was read"});
}

std::string printable(std::string_view s, std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < s.size() && i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c >= 0x20 && c < 0x7F && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    }
  }
  if (s.size() > n) out += "...(" + std::to_string(s.size()) + " bytes)";
  return out;
}

}  // namespace relpos::fuzz
