// The result document (SPEC.md §2), written straight to text: a batch writes one per spec, and
// building a JSON tree only to print it cost more than solving and parsing together. Numbers are
// the shortest text that reads back as the same double (std::to_chars); strings are escaped as
// JSON needs and always valid UTF-8. resultToJson is simply the parse of this text
// (result_line_test checks both: every number read back, and the document).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>

#include "relpos/core/solver.hpp"
#include "relpos/io/result_writer.hpp"
#include "utf8.hpp"

namespace relpos {
namespace {

// ordered_json: fields come out in the order of SPEC.md §2.
using json = nlohmann::ordered_json;

json num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

// Appends into a string used as a raw buffer (sized ahead, trimmed at the end): a line is a few
// hundred short pieces, and std::string's append is an out-of-line call each. The text is final
// when the Writer goes out of scope.
class Writer {
 public:
  explicit Writer(std::string& out) : out_(out) {
    out_.resize(std::max<std::size_t>(out_.capacity(), 512));
  }
  ~Writer() { out_.resize(n_); }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  template <std::size_t N>
  void raw(const char (&s)[N]) {
    put(s, N - 1);
  }
  // A member's key, after a comma unless it opens its object.
  template <std::size_t N>
  void key(const char (&k)[N]) {
    room(N + 3);
    if (out_[n_ - 1] != '{') out_[n_++] = ',';
    out_[n_++] = '"';
    put(k, N - 1);
    put("\":", 2);
  }
  // The shortest text that reads back as exactly v (std::to_chars), with ".0" when it would look
  // like an integer: every reader then takes it as a double (nlohmann keeps it a float, simdjson
  // does not refuse 21 digits as too wide an integer, -0.0 keeps its sign). Non-finite: null.
  void number(double v) {
    if (!std::isfinite(v)) return raw("null");
    room(32);  // at most 24 characters ("-2.2250738585072014e-308"), and ".0"
    char* const first = &out_[n_];
    char* last = std::to_chars(first, first + 30, v).ptr;
    if (std::find_if(first, last, [](char c) { return c == '.' || c == 'e'; }) == last) {
      *last++ = '.';
      *last++ = '0';
    }
    n_ += static_cast<std::size_t>(last - first);
  }
  void integer(long v) {
    room(24);
    char* first = &out_[n_];
    n_ += static_cast<std::size_t>(std::to_chars(first, first + 24, v).ptr - first);
  }
  void boolean(bool v) { v ? raw("true") : raw("false"); }
  void string(const std::string& s) { string(s.data(), s.size()); }
  void string(const char* s) { string(s, std::char_traits<char>::length(s)); }
  void string(const char* s, std::size_t n) {
    put('"');
    for (std::size_t i = 0; i < n; ++i) {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      switch (c) {
        case '"':
          raw("\\\"");
          break;
        case '\\':
          raw("\\\\");
          break;
        case '\b':
          raw("\\b");
          break;
        case '\f':
          raw("\\f");
          break;
        case '\n':
          raw("\\n");
          break;
        case '\r':
          raw("\\r");
          break;
        case '\t':
          raw("\\t");
          break;
        default:
          if (c < 0x20) {
            char esc[8];
            std::snprintf(esc, sizeof esc, "\\u%04x", c);
            put(esc, 6);
          } else if (c < 0x80) {
            put(static_cast<char>(c));
          } else {
            // A name may come from a file name that is not UTF-8: each ill-formed part becomes
            // U+FFFD, so the line stays valid JSON text.
            const detail::Utf8Step step = detail::utf8Step(std::string_view(s + i, n - i));
            if (step.valid)
              put(s + i, step.length);
            else
              put("\xEF\xBF\xBD", 3);
            i += step.length - 1;
          }
      }
    }
    put('"');
  }
  template <typename F>
  void list(int n, F&& each) {
    put('[');
    for (int i = 0; i < n; ++i) {
      if (i) put(',');
      each(i);
    }
    put(']');
  }

 private:
  void room(std::size_t k) {
    if (n_ + k > out_.size()) out_.resize(2 * (n_ + k));
  }
  void put(char c) {
    room(1);
    out_[n_++] = c;
  }
  void put(const char* s, std::size_t k) {
    room(k);
    std::memcpy(&out_[n_], s, k);
    n_ += k;
  }

  std::string& out_;
  std::size_t n_ = 0;
};

// The orientation as SPEC.md writes it: unit quaternion coefficients (x, y, z, w), w ≥ 0 (one of
// the two equal quaternions, deterministically).
Eigen::Vector4d orientationOf(const Isometry3d& X) {
  Quaterniond q(X.linear());
  q.normalize();
  return q.w() < 0 ? Eigen::Vector4d(-q.coeffs()) : Eigen::Vector4d(q.coeffs());
}

// parameters, position, orientation, without the closing brace.
void writePose(Writer& w, const Isometry3d& X, const Params& theta, int dof) {
  w.raw("{");
  w.key("parameters");
  w.list(dof, [&](int i) { w.number(theta[i]); });
  const Vector3d t = X.translation();
  w.key("position");
  w.list(3, [&](int i) { w.number(t[i]); });
  const Eigen::Vector4d q = orientationOf(X);
  w.key("orientation");
  w.list(4, [&](int i) { w.number(q[i]); });
}

// The message, with the user's constraint ids next to the indices (SPEC: ids are echoed).
std::string resultMessage(const Problem& problem, const Solution& solution) {
  std::string message = solution.message;
  std::string ids;
  for (int k : solution.conflicts) {
    const std::string& id = problem.constraints[static_cast<std::size_t>(k)].id;
    if (!id.empty()) ids += (ids.empty() ? "" : ", ") + std::to_string(k) + " = '" + id + "'";
  }
  if (!ids.empty()) message += " (constraints " + ids + ")";
  return message;
}

}  // namespace

json poseToJson(const Isometry3d& X, const Params& theta, int dof) {
  json j;
  json ps = json::array();
  for (int i = 0; i < dof; ++i) ps.push_back(num(theta[i]));
  j["parameters"] = ps;
  const Vector3d t = X.translation();
  j["position"] = {t.x(), t.y(), t.z()};
  const Eigen::Vector4d q = orientationOf(X);
  j["orientation"] = {q[0], q[1], q[2], q[3]};
  return j;
}

namespace {

void writeLine(const Problem& problem, const Solution& solution, const ResultOptions& opt,
               std::string& out) {
  Writer w(out);  // overwrites `out` from its start (keeping its size saves zero-filling it)
  w.raw("{");
  w.key("relpos");
  w.raw("1");
  w.key("name");
  w.string(problem.name);
  w.key("status");
  w.string(toString(solution.status));
  w.key("message");
  w.string(resultMessage(problem, solution));
  w.key("branches");
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  // Seeding the generator costs more than writing a branch: only when samples are asked for.
  std::optional<std::mt19937_64> rng;
  if (opt.samples > 0) rng.emplace(opt.seed);
  w.list(static_cast<int>(solution.branches.size()), [&](int b) {
    const Manifold& m = *solution.branches[static_cast<std::size_t>(b)].manifold;
    const int dof = m.dof();
    w.raw("{");
    w.key("dof");
    w.integer(dof);
    w.key("rotational_dof");
    m.rotationalDof() >= 0 ? w.integer(m.rotationalDof()) : w.raw("null");
    w.key("translational_dof");
    m.rotationalDof() >= 0 ? w.integer(m.translationalDof()) : w.raw("null");
    w.key("manifold");
    w.string(m.describe());
    w.key("parameters");
    w.list(dof, [&](int i) {
      const Parameter p = m.parameter(i);
      w.raw("{");
      w.key("name");
      w.string(p.name);
      w.key("kind");
      w.string(toString(p.kind));
      w.key("min");
      w.number(p.min);
      w.key("max");
      w.number(p.max);
      w.key("periodic");
      w.boolean(p.periodic);
      w.raw("}");
    });
    const NearestPose n =
        nearestOnBranch(solution.branches[static_cast<std::size_t>(b)], problem.mobile.pose);
    w.key("nearest");
    writePose(w, n.pose, n.parameters, dof);
    w.key("distance");
    w.number(n.distance);
    w.raw("}");
    if (n.distance < best_d) best_d = n.distance, best = b;
    if (opt.samples > 0) {
      w.key("samples");
      w.list(opt.samples, [&](int) {
        const Params t = sampleParameters(m, n.parameters, opt.window, *rng);
        writePose(w, m.pose(t), t, dof);
        w.raw("}");
      });
    }
    w.raw("}");
  });
  w.key("best");
  best >= 0 ? w.integer(best) : w.raw("null");
  w.key("conflicts");
  w.list(static_cast<int>(solution.conflicts.size()),
         [&](int i) { w.integer(solution.conflicts[i]); });
  w.key("redundant");
  w.list(static_cast<int>(solution.redundant.size()),
         [&](int i) { w.integer(solution.redundant[i]); });
  w.key("rules");
  w.list(static_cast<int>(solution.rules.size()), [&](int i) { w.string(solution.ruleName(i)); });
  w.key("stats");
  w.raw("{");
  w.key("solve_us");
  w.number(solution.solve_us);
  w.raw("}}");
}

}  // namespace

// Writing runs the branches' code (describe, the nearest-pose search, samples): a plugin's
// manifold that throws there makes the line an `unhandled` one naming the plugin, not a lost line.
void writeResultLine(const Problem& problem, const Solution& solution, const ResultOptions& opt,
                     std::string& out) {
  std::string what;
  try {
    writeLine(problem, solution, opt, out);
    return;
  } catch (const std::exception& e) {
    what = e.what();
  } catch (...) {
    what = "an exception that is not a std::exception";
  }
  writeLine(problem, unhandledAfterThrow(solution, "writing the result", what), opt, out);
}

json resultToJson(const Problem& problem, const Solution& solution, const ResultOptions& opt) {
  std::string text;
  writeResultLine(problem, solution, opt, text);
  return json::parse(text);
}

}  // namespace relpos
