#include "benchmark_problems.hpp"

#include <map>
#include <stdexcept>

#include "relpos/builtins/builtins.hpp"
#include "relpos/io/spec_reader.hpp"
#include "test_config.hpp"

namespace relpos::test {

const std::vector<BenchmarkProblem>& benchmarkProblems() {
  static const std::vector<BenchmarkProblem> b = {
      {"stewart-gough-dietmaier-40.json", false, 40,
       "Dietmaier 1998: a general 6-6 platform with 40 real poses"},
      {"octahedral-a.json", false, -1, "paper 001 §V-A, configuration a"},
      {"octahedral-b.json", false, -1, "paper 001 §V-A, configuration b"},
      {"four-spheres-12-lines.json", true, 12,
       "paper 001 §V-B after Macdonald et al.: 12 real tangent lines"},
  };
  return b;
}

const BenchmarkProblem& problemNamed(const std::string& file) {
  for (const BenchmarkProblem& b : benchmarkProblems())
    if (file == b.file) return b;
  throw std::runtime_error(file);
}

Problem loadComplete(const std::string& file) {
  ParseResult r = parseSpecFile(RELPOS_DATA_DIR "/complete/" + file, relpos::builtinRegistry());
  if (!r.problem) throw std::runtime_error("cannot read data/complete/" + file);
  return *r.problem;
}

const ReferenceRoots& benchmarkReference(const BenchmarkProblem& b) {
  static std::map<std::string, ReferenceRoots> cache;
  auto it = cache.find(b.file);
  if (it != cache.end()) return it->second;
  ReferenceOptions o;
  o.starts = 6000;
  o.seed = 20261202;
  o.line_quotient = b.line_quotient;
  return cache.emplace(b.file, referenceRoots(loadComplete(b.file), o)).first->second;
}

}  // namespace relpos::test
