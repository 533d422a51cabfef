// Random specs of 2-4 constraints with ranges, built around a known pose (the tests' generator,
// tests/support/random_problems and tests/complete/ranged_problems): every kind of constraint,
// about half of them turned into ranges (two-sided or one-sided), the mobile features fresh or
// shared, generic and axis-aligned geometry alternately, the mobile object starting at a random
// pose. JSONL, one spec per line, from a seed — what issue 16's batch target is measured on:
//   build/bench/relpos_generate_random_specs 10000 1 > random.jsonl
//   build/cli/relpos batch random.jsonl --jobs 2 -o out.jsonl
#include <cstdio>
#include <cstdlib>

#include "ranged_problems.hpp"
#include "spec_writer.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: relpos_generate_random_specs N SEED\n");
    return 2;
  }
  const long count = std::strtol(argv[1], nullptr, 10);
  relpos::test::Rng rng(std::strtoull(argv[2], nullptr, 10));
  for (long i = 0; i < count; ++i) {
    relpos::test::KnownProblem kp = relpos::test::randomRangedProblem(rng, i % 2 == 1);
    kp.problem.name = "random-" + std::to_string(i);
    std::printf("%s\n", relpos::test::specJson(kp.problem).c_str());
  }
  return 0;
}
