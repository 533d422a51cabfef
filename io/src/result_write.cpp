// The result document (docs/spec.md §2), written straight to text from a Report: a batch writes one
// per spec, and building a JSON tree only to print it cost more than solving and parsing
// together. Strings are escaped as JSON needs and always valid UTF-8 (result_write_test checks the
// document and that every number reads back).
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <nlohmann/json.hpp>

#include "relpos/io/result_writer.hpp"
#include "shortest_double.hpp"
#include "utf8.hpp"

namespace relpos {

const char* toString(ParameterMotion::Type t) {
  switch (t) {
    case ParameterMotion::Type::kRotation:
      return "rotation";
    case ParameterMotion::Type::kTranslation:
      return "translation";
    case ParameterMotion::Type::kScrew:
      return "screw";
    case ParameterMotion::Type::kUnknown:
      return "unknown";
    case ParameterMotion::Type::kNone:
      break;
  }
  return "none";
}

namespace {

// Appends into a string used as a raw buffer (sized ahead, trimmed at the end): a line is a few
// hundred short pieces, and std::string's append is an out-of-line call each. The text is final
// when the Writer goes out of scope. Commas, and in the indented layout the line breaks, come
// from the nesting the Writer tracks: callers only open, name and close.
class Writer {
 public:
  Writer(std::string& out, ResultFormat format) : out_(out), format_(format) {
    out_.resize(std::max<std::size_t>(out_.capacity(), 512));
  }
  ~Writer() { out_.resize(n_); }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  void beginObject() { open('{'); }
  void endObject() { close('}'); }
  void beginArray() { open('['); }
  void endArray() { close(']'); }

  // A member's key; its value follows.
  template <std::size_t N>
  void key(const char (&k)[N]) {
    element();
    room(N + 4);
    out_[n_++] = '"';
    put(k, N - 1);
    format_.indented ? put("\": ", 3) : put("\":", 2);
    after_key_ = true;
  }

  void null() { value("null", 4); }
  void boolean(bool v) { v ? value("true", 4) : value("false", 5); }
  void integer(long v) {
    element();
    room(24);
    char* first = &out_[n_];
    n_ += static_cast<std::size_t>(std::to_chars(first, first + 24, v).ptr - first);
  }
  // -1 (a mixed manifold's split of its DOF): null.
  void integerOrNull(int v) { v >= 0 ? integer(v) : null(); }
  // The shortest text that reads back as exactly v (std::to_chars's, shortest_double.hpp), with
  // ".0" when it would look like an integer: every reader then takes it as a double (simdjson
  // does not refuse 21 digits as too wide an integer, -0.0 keeps its sign). Or nlohmann's spelling
  // (ResultFormat). Non-finite: null.
  void number(double v) {
    if (!std::isfinite(v)) return null();
    element();
    // At most 24 characters ("-2.2250738585072014e-308") and ".0"; writeShortestDouble's copies
    // may reach 40 bytes.
    room(40);
    char* const first = &out_[n_];
    char* last;
    if (format_.library_numbers) {
      last = nlohmann::detail::to_chars(first, first + 32, v);  // appends ".0" itself
    } else {
      last = detail::writeShortestDouble(first, v);
      if (std::find_if(first, last, [](char c) { return c == '.' || c == 'e'; }) == last) {
        *last++ = '.';
        *last++ = '0';
      }
    }
    n_ += static_cast<std::size_t>(last - first);
  }
  void string(const std::string& s) { string(s.data(), s.size()); }
  void string(const char* s) { string(s, std::char_traits<char>::length(s)); }
  void string(const char* s, std::size_t n) {
    element();
    put('"');
    for (std::size_t i = 0; i < n; ++i) {
      // A run of characters that stand for themselves (a name, a kind, a manifold's name: most
      // strings whole) is copied at once.
      std::size_t run = i;
      while (run < n && standsForItself(s[run])) ++run;
      if (run > i) {
        put(s + i, run - i);
        i = run - 1;
        continue;
      }
      const unsigned char c = static_cast<unsigned char>(s[i]);
      switch (c) {
        case '"':
          put("\\\"", 2);
          break;
        case '\\':
          put("\\\\", 2);
          break;
        case '\b':
          put("\\b", 2);
          break;
        case '\f':
          put("\\f", 2);
          break;
        case '\n':
          put("\\n", 2);
          break;
        case '\r':
          put("\\r", 2);
          break;
        case '\t':
          put("\\t", 2);
          break;
        default:
          if (c < 0x20) {
            char esc[8];
            std::snprintf(esc, sizeof esc, "\\u%04x", c);
            put(esc, 6);
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
  void list(std::size_t n, F&& each) {
    beginArray();
    for (std::size_t i = 0; i < n; ++i) each(i);
    endArray();
  }

 private:
  // Printable ASCII other than the quote and the backslash: written as it is in a JSON string.
  static bool standsForItself(char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return c >= 0x20 && c < 0x80 && c != '"' && c != '\\';
  }
  // Before a value or a key: the comma after the previous element, and in the indented layout
  // the line break and indentation (nlohmann's dump(2) layout).
  void element() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (depth_ == 0) return;
    if (!empty_[depth_]) put(',');
    empty_[depth_] = false;
    if (format_.indented) newline(depth_);
  }
  void value(const char* s, std::size_t k) {
    element();
    put(s, k);
  }
  void open(char c) {
    element();
    put(c);
    ++depth_;
    empty_[depth_] = true;
  }
  void close(char c) {
    if (format_.indented && !empty_[depth_]) newline(depth_ - 1);
    --depth_;
    put(c);
  }
  void newline(int depth) {
    const std::size_t k = 1 + 2 * static_cast<std::size_t>(depth);
    room(k);
    out_[n_] = '\n';
    std::memset(&out_[n_ + 1], ' ', k - 1);
    n_ += k;
  }
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
  ResultFormat format_;
  std::size_t n_ = 0;
  int depth_ = 0;
  bool after_key_ = false;
  bool empty_[16] = {};  // per open container: nothing in it yet (the result nests 6 deep)
};

// The orientation as docs/spec.md writes it: unit quaternion coefficients (x, y, z, w), w ≥ 0 (one
// of the two equal quaternions, deterministically).
Eigen::Vector4d orientationOf(const Isometry3d& X) {
  Quaterniond q(X.linear());
  q.normalize();
  return q.w() < 0 ? Eigen::Vector4d(-q.coeffs()) : Eigen::Vector4d(q.coeffs());
}

// The one pose writer: parameters, position, orientation — inside an object the caller opened
// (and closes, after any fields of its own such as "distance").
// Each parameter's unit factor: 180/π for an angle parameter written in degrees, else 1.
using Units = std::array<double, kMaxDof>;

void writePose(Writer& w, const Isometry3d& X, const Params& theta, int dof, const Units& u) {
  w.key("parameters");
  w.list(static_cast<std::size_t>(dof), [&](std::size_t i) { w.number(theta[i] * u[i]); });
  const Vector3d t = X.translation();
  w.key("position");
  w.list(3, [&](std::size_t i) { w.number(t[static_cast<Eigen::Index>(i)]); });
  const Eigen::Vector4d q = orientationOf(X);
  w.key("orientation");
  w.list(4, [&](std::size_t i) { w.number(q[static_cast<Eigen::Index>(i)]); });
}

void writeNearest(Writer& w, const NearestPose& n, int dof, const Units& u) {
  w.beginObject();
  writePose(w, n.pose, n.parameters, dof, u);
  w.key("distance");
  w.number(n.distance);
  w.endObject();
}

void writeCollision(Writer& w, const Report& r, const CollisionReport& c, int dof, const Units& u) {
  w.beginObject();
  w.key("checked_against");
  w.list(r.checked_against.size(), [&](std::size_t i) { w.string(r.checked_against[i]); });
  w.key("clearance");
  w.number(r.clearance);
  w.key("nearest_collides");
  w.boolean(c.nearest_collides);
  w.key("nearest_contacts");
  w.list(c.nearest_contacts.size(), [&](std::size_t i) {
    w.beginObject();
    w.key("object");
    w.string(c.nearest_contacts[i].object);
    w.key("depth");
    w.number(c.nearest_contacts[i].depth);
    w.endObject();
  });
  w.key("nearest_free");
  if (c.has_nearest_free) {
    writeNearest(w, c.nearest_free, dof, u);
  } else {
    w.null();
    w.key("nearest_free_reason");
    w.string(c.nearest_free_reason);
  }
  w.key("free_samples");
  w.list(c.free_samples.size(), [&](std::size_t i) {
    w.beginObject();
    writePose(w, c.free_samples[i].pose, c.free_samples[i].parameters, dof, u);
    w.endObject();
  });
  w.key("blocked_samples");
  w.integer(c.blocked_samples);
  w.endObject();
}

// A parameter's motion (docs/spec.md §2.5): its type alone when it moves nothing or is unknown.
// `deg`: 180/π when angles are written in degrees (1 otherwise), `unit` the parameter's own
// factor.
void writeMotion(Writer& w, const ParameterMotion& m, double deg, double unit) {
  if (m.type == ParameterMotion::Type::kNone || m.type == ParameterMotion::Type::kUnknown) {
    w.beginObject();
    w.key("type");
    w.string(toString(m.type));
    return w.endObject();
  }
  auto vec = [&](const Vector3d& v) {
    w.list(3, [&](std::size_t i) { w.number(v[static_cast<Eigen::Index>(i)]); });
  };
  w.beginObject();
  w.key("type");
  w.string(toString(m.type));
  if (m.type == ParameterMotion::Type::kTranslation) {
    w.key("direction");
    vec(m.axis);
  } else {
    w.key("axis");
    vec(m.axis);
    w.key("point");
    vec(m.point);
  }
  const bool turns = m.type != ParameterMotion::Type::kTranslation;
  if (m.type == ParameterMotion::Type::kScrew) {
    w.key("pitch");
    w.number(m.pitch / deg);  // length per radian, or per degree
  }
  w.key("rate");
  w.number(m.rate * (turns ? deg : 1.0) / unit);
  w.endObject();
}

void writeBranch(Writer& w, const Report& r, std::size_t b, bool degrees) {
  const BranchReport& br = r.branches[b];
  const double deg = degrees ? 180.0 / kPi : 1.0;
  Units u;
  for (std::size_t i = 0; i < u.size(); ++i)
    u[i] = static_cast<int>(i) < br.dof && br.parameters[i].kind == ParamKind::kAngle ? deg : 1.0;
  w.beginObject();
  w.key("dof");
  w.integer(br.dof);
  w.key("rotational_dof");
  w.integerOrNull(br.rotational_dof);
  w.key("translational_dof");
  w.integerOrNull(br.rotational_dof >= 0 ? br.translational_dof : -1);
  w.key("manifold");
  w.string(br.manifold);
  w.key("exact");
  w.boolean(br.exact);
  if (!br.exact) {  // found numerically: its proof (docs/spec.md §2.4, §8)
    w.key("certified");
    w.beginObject();
    w.key("radius");
    w.number(br.certified.radius);
    w.key("angle");
    w.number(br.certified.angle * deg);
    w.endObject();
  }
  w.key("parameters");
  w.list(static_cast<std::size_t>(br.dof), [&](std::size_t i) {
    const Parameter& p = br.parameters[i];
    w.beginObject();
    w.key("name");
    w.string(p.name);
    w.key("kind");
    w.string(toString(p.kind));
    w.key("min");
    w.number(p.min * u[i]);
    w.key("max");
    w.number(p.max * u[i]);
    w.key("periodic");
    w.boolean(p.periodic);
    w.key("motion");
    writeMotion(w, br.motions[i], deg, u[i]);
    const ParameterMotion& mo = br.motions[i];
    if (mo.constraint >= 0) {
      w.key("constraint");
      w.integer(mo.constraint);
      if (!mo.constraint_id.empty()) {
        w.key("constraint_id");
        w.string(mo.constraint_id);
      }
    }
    w.endObject();
  });
  w.key("nearest");
  writeNearest(w, br.nearest, br.dof, u);
  w.key("nearest_global");
  w.boolean(br.nearest.global);
  if (br.sample_count > 0) {
    w.key("samples");
    const SamplePose* samples = r.samplesOf(b);
    w.list(br.sample_count, [&](std::size_t i) {
      w.beginObject();
      writePose(w, samples[i].pose, samples[i].parameters, br.dof, u);
      w.endObject();
    });
  }
  if (r.collision_checked && b < r.collision.size()) {
    w.key("collision");
    writeCollision(w, r, r.collision[b], br.dof, u);
  }
  w.endObject();
}

}  // namespace

void writeReport(const Report& r, ResultFormat format, std::string& out) {
  Writer w(out,
           format);  // overwrites `out` from its start (keeping its size saves zero-filling it)
  w.beginObject();
  w.key("relpos");
  w.integer(1);
  w.key("name");
  w.string(r.name);
  if (format.degrees) {
    w.key("units");
    w.beginObject();
    w.key("angle");
    w.string("deg");
    w.endObject();
  }
  w.key("status");
  w.string(toString(r.status));
  w.key("complete");
  w.boolean(r.complete);
  w.key("isolated_complete");
  w.boolean(r.isolated_complete);
  w.key("message");
  w.string(r.message);
  w.key("branches");
  w.list(r.branches.size(), [&](std::size_t b) { writeBranch(w, r, b, format.degrees); });
  w.key("best");
  r.best >= 0 ? w.integer(r.best) : w.null();
  w.key("conflicts");
  w.list(r.conflicts.size(), [&](std::size_t i) { w.integer(r.conflicts[i]); });
  w.key("redundant");
  w.list(r.redundant.size(), [&](std::size_t i) { w.integer(r.redundant[i]); });
  w.key("rules");
  w.list(r.rules.size(), [&](std::size_t i) { w.string(r.ruleName(i)); });
  w.key("stats");
  w.beginObject();
  w.key("solve_us");
  w.number(r.solve_us);
  w.endObject();
  if (r.collision_checked) {
    w.key("collision_free_branches");
    w.integer(r.collision_free_branches);
  }
  w.endObject();
}

void writeStatusLine(const std::string& name, const char* status, const std::string& message,
                     std::string& out) {
  Writer w(out, kResultLine);
  w.beginObject();
  w.key("relpos");
  w.integer(1);
  w.key("name");
  w.string(name);
  w.key("status");
  w.string(status);
  w.key("message");
  w.string(message);
  w.endObject();
}

}  // namespace relpos
