// make_start_systems ROOT OUT_DIR LIST: writes data/start_systems (stored_start_systems.hpp).
// LIST names spec files (one a line, relative to ROOT; '#' starts a comment); each is encoded
// as the numeric stage encodes it (a line family when the mobile features lie on one line, else
// a pose family per "either" alternative) and the start system of every new signature computed
// by monodromy with the total-degree or second-monodromy cross-check (start_system.hpp), checked
// by the trace test where it applies (trace_test.hpp), certified and written to OUT_DIR/<hash>.txt.
// Deterministic (seeded by the signature): running it again rewrites the same files. Exit status 1
// if a spec cannot be read or encoded or a start system fails its certification.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "random.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/complete/encoding.hpp"
#include "relpos/complete/problem_encoding.hpp"
#include "relpos/io/spec_reader.hpp"
#include "start_system.hpp"
#include "stored_start_systems.hpp"
#include "trace_test.hpp"

namespace {

using namespace relpos;
using namespace relpos::complete;

struct Encoded {
  std::unique_ptr<Family> family;
  unsigned alternative = 0;
};

// The families the numeric stage solves the problem with (stage.cpp: solveLine, solvePose).
bool familiesOf(const Problem& p, std::vector<Encoded>* out, std::string* why) {
  const Tolerance tol = Tolerance::forScale(2.0 * p.lengthScale());
  if (mobileFeaturesOnOneLine(p, tol)) {
    LineEncoding e;
    if (!encodeLine(p, tol, &e, why)) return false;
    out->push_back({std::make_unique<LineFamily>(e.equations, static_cast<int>(e.target.size()))});
    return true;
  }
  PoseEncoding first;
  if (!encodePose(p, 0, &first, why)) return false;
  for (unsigned a = 0; a < (1u << first.alternatives); ++a) {
    PoseEncoding e;
    if (!encodePose(p, 0, &e, why, a)) return false;
    out->push_back(
        {std::make_unique<PoseFamily>(e.equations, static_cast<int>(e.target.size())), a});
  }
  return true;
}

std::vector<std::string> readList(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file);
  std::vector<std::string> out;
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string w;
    if (words >> w) out.push_back(w);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: make_start_systems ROOT OUT_DIR LIST\n";
    return 2;
  }
  const std::string root = argv[1], dir = argv[2];
  int status = 0;
  std::set<std::string> done;
  for (const std::string& spec : readList(argv[3])) {
    ParseResult r = parseSpecFile(root + "/" + spec, builtinRegistry());
    std::vector<Encoded> families;
    std::string why;
    if (!r.problem || !familiesOf(*r.problem, &families, &why)) {
      std::cerr << spec << ": " << (r.problem ? why : "not a valid spec") << "\n";
      status = 1;
      continue;
    }
    for (const Encoded& e : families) {
      const Family& f = *e.family;
      if (!done.insert(f.signature()).second) continue;
      const auto t0 = std::chrono::steady_clock::now();
      const std::unique_ptr<StartSystem> s =
          detail::computeStartSystem(f, detail::kDefaultMaxBezout);
      // The trace test (trace_test.hpp) where it applies: "+trace" in the check when it passed.
      const detail::TraceOutcome trace =
          detail::traceTest(f, *s, detail::mixSeed(detail::stableHash(f.signature()), 5));
      if (trace.passed) {
        s->check += "+trace";
        s->trace_witness_points = trace.witness_points;
      } else {
        std::cerr << spec << ": trace test not passed: " << trace.why << "\n";
        // More fibre points than the start system holds: the start system is incomplete.
        if (trace.fibre_roots > static_cast<int>(s->roots.size())) status = 1;
      }
      const double sec =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::string fail;
      if (!detail::certifyStartSystem(f, *s, &fail)) {
        std::cerr << spec << ": " << f.signature() << ": " << fail << "\n";
        status = 1;
        continue;
      }
      detail::StoredStartSystem stored;
      stored.signature = f.signature();
      stored.source = spec + " " + std::to_string(e.alternative);
      stored.system = *s;
      const std::string name = detail::storedFileName(f.signature());
      std::ofstream out(dir + "/" + name);
      out << detail::formatStoredStartSystem(stored);
      if (!out) {
        std::cerr << dir << "/" << name << ": cannot write\n";
        status = 1;
        continue;
      }
      std::printf("%s  %zu roots  %s  %.2f s  %s\n", name.c_str(), s->roots.size(),
                  s->check.c_str(), sec, spec.c_str());
    }
  }
  return status;
}
