// The stored start systems' text format and their loader (stored_start_systems.hpp). Numbers
// are written in hex-float (%a), which strtod reads back exactly: a stored root is bit for bit
// the root the generator certified.
#include "stored_start_systems.hpp"

#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "krawczyk.hpp"
#include "polynomial_eval.hpp"
#include "random.hpp"

// The generated table (build/…/stored_start_systems_data.cpp): entries up to a null name.
extern const relpos::complete::detail::EmbeddedText kRelposEmbeddedStartSystems[];

namespace relpos::complete::detail {
namespace {

constexpr const char* kMagic = "relpos-start-system 1";

std::string hex(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%a", v);
  return buf;
}

void writeComplex(std::ostringstream& o, Complex z) { o << hex(z.real()) << ' ' << hex(z.imag()); }

// Reads the rest of a line after `key `; false if the line does not start so.
bool keyed(std::istringstream& in, const std::string& key, std::string* rest) {
  std::string line;
  if (!std::getline(in, line)) return false;
  if (line.compare(0, key.size() + 1, key + " ") != 0) return false;
  *rest = line.substr(key.size() + 1);
  return true;
}

// Reads `count` complex numbers ("re im" pairs) from one line; only finite values.
bool readComplexLine(std::istringstream& in, int count, Complex* out) {
  std::string line;
  if (!std::getline(in, line)) return false;
  const char* p = line.c_str();
  for (int i = 0; i < 2 * count; ++i) {
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p || !std::isfinite(v)) return false;
    p = end;
    if (i % 2 == 0)
      out[i / 2].real(v);
    else
      out[i / 2].imag(v);
  }
  while (*p == ' ') ++p;
  return *p == '\0';
}

}  // namespace

std::string formatStoredStartSystem(const StoredStartSystem& s) {
  std::ostringstream o;
  const StartSystem& t = s.system;
  o << kMagic << '\n';
  o << "signature " << s.signature << '\n';
  o << "source " << s.source << '\n';
  o << "check " << t.check << '\n';
  o << "counts " << t.monodromy_loops << ' ' << t.total_degree_paths << ' ' << t.total_degree_added
    << ' ' << t.second_monodromy_roots << ' ' << t.second_monodromy_added << ' '
    << t.trace_witness_points << '\n';
  o << "params " << t.params.size() << '\n';
  for (const Complex& p : t.params) {
    writeComplex(o, p);
    o << '\n';
  }
  const Eigen::Index n = t.roots.empty() ? 0 : t.roots[0].size();
  o << "roots " << t.roots.size() << ' ' << n << '\n';
  for (const Eigen::VectorXcd& r : t.roots) {
    for (Eigen::Index i = 0; i < r.size(); ++i) {
      if (i) o << ' ';
      writeComplex(o, r[i]);
    }
    o << '\n';
  }
  return o.str();
}

bool parseStoredStartSystem(const std::string& text, StoredStartSystem* out, std::string* why) {
  auto fail = [&](const char* what) {
    *why = what;
    return false;
  };
  std::istringstream in(text);
  std::string line, rest;
  if (!std::getline(in, line) || line != kMagic) return fail("not a start system (format 1)");
  StoredStartSystem s;
  if (!keyed(in, "signature", &s.signature)) return fail("no signature line");
  if (!keyed(in, "source", &s.source)) return fail("no source line");
  if (!keyed(in, "check", &s.system.check)) return fail("no check line");
  if (!keyed(in, "counts", &rest)) return fail("no counts line");
  {
    std::istringstream c(rest);
    StartSystem& t = s.system;
    if (!(c >> t.monodromy_loops >> t.total_degree_paths >> t.total_degree_added >>
          t.second_monodromy_roots >> t.second_monodromy_added >> t.trace_witness_points))
      return fail("bad counts line");
  }
  int np = -1, nr = -1, nv = -1;
  if (!keyed(in, "params", &rest) || std::sscanf(rest.c_str(), "%d", &np) != 1 || np < 0 ||
      np > 100000)
    return fail("bad params line");
  s.system.params.resize(np);
  for (int i = 0; i < np; ++i)
    if (!readComplexLine(in, 1, &s.system.params[i])) return fail("bad parameter");
  if (!keyed(in, "roots", &rest) || std::sscanf(rest.c_str(), "%d %d", &nr, &nv) != 2 || nr < 0 ||
      nv < 0 || nv > kMaxVariables || nr > 1000000)
    return fail("bad roots line");
  for (int i = 0; i < nr; ++i) {
    Eigen::VectorXcd r(nv);
    if (!readComplexLine(in, nv, r.data())) return fail("bad root");
    s.system.roots.push_back(std::move(r));
  }
  if (std::getline(in, line) && !line.empty()) return fail("text after the roots");
  *out = std::move(s);
  return true;
}

std::string storedFileName(const std::string& signature) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%016" PRIx64 ".txt", stableHash(signature));
  return buf;
}

const std::vector<EmbeddedText>& embeddedStartSystems() {
  static const std::vector<EmbeddedText> all = [] {
    std::vector<EmbeddedText> v;
    for (const EmbeddedText* e = kRelposEmbeddedStartSystems; e->name; ++e) v.push_back(*e);
    return v;
  }();
  return all;
}

bool certifyStartSystem(const Family& f, const StartSystem& s, std::string* why) {
  auto fail = [&](std::string what) {
    if (why) *why = std::move(what);
    return false;
  };
  const CompiledShape shape(f.shape());
  if (static_cast<int>(s.params.size()) != f.parameterCount())
    return fail("parameter count differs from the family's");
  if (s.roots.empty()) return fail("no roots");
  std::vector<Complex> c(shape.terms());
  f.coefficients(s.params.data(), c.data());
  Certifier certifier(shape, c.data());
  std::vector<BoxCertificate> boxes;
  for (std::size_t i = 0; i < s.roots.size(); ++i) {
    if (s.roots[i].size() != shape.variables()) return fail("root size differs from the family's");
    BoxCertificate b = certifier.certify(CVec(s.roots[i]));
    if (!b.ok) return fail("root " + std::to_string(i) + " not certified");
    // The box must be around the stored point, not around another root Newton reached.
    if (normInf(b.x - CVec(s.roots[i])) > b.radius)
      return fail("root " + std::to_string(i) + " is not in its box");
    for (std::size_t j = 0; j < boxes.size(); ++j)
      if (boxesOverlap(boxes[j].x, boxes[j].radius, b.x, b.radius))
        return fail("roots " + std::to_string(j) + " and " + std::to_string(i) + " overlap");
    boxes.push_back(std::move(b));
  }
  return true;
}

std::unique_ptr<StartSystem> loadStoredStartSystem(const Family& f, std::string* why) {
  return loadStoredStartSystem(f, embeddedStartSystems(), why);
}

std::unique_ptr<StartSystem> loadStoredStartSystem(const Family& f,
                                                   const std::vector<EmbeddedText>& table,
                                                   std::string* why) {
  const std::string name = storedFileName(f.signature());
  for (const EmbeddedText& e : table) {
    if (name != e.name) continue;
    StoredStartSystem s;
    std::string reason;
    if (!parseStoredStartSystem(e.text, &s, &reason)) {
      if (why) *why = name + ": " + reason;
      return nullptr;
    }
    // The hash names the file; the signature spelled inside decides.
    if (s.signature != f.signature()) continue;
    if (!certifyStartSystem(f, s.system, &reason)) {
      if (why) *why = name + ": " + reason;
      return nullptr;
    }
    auto out = std::make_unique<StartSystem>(std::move(s.system));
    out->stored = true;
    return out;
  }
  if (why) *why = "no stored start system for the signature";
  return nullptr;
}

}  // namespace relpos::complete::detail
