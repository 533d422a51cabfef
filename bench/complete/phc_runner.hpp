#pragma once
// PHCpack (`phc`, Debian package phcpack) run as a subprocess on generated input files: the
// blackbox solver `phc -b` and the one-parameter homotopy `phc -p` from a cached start system.
#include <string>
#include <vector>

#include "phc_systems.hpp"

namespace relpos::bench {

// `phc` on PATH (its full path), or empty.
std::string findPhc();

struct PhcRun {
  bool ran = false;
  double seconds = 0.0;                         // wall clock of the subprocess
  std::vector<std::vector<double>> real_roots;  // solutions with every imaginary part ≈ 0
  int solutions = 0;                            // every solution PHC listed
  std::string error;
};

// `phc -b IN OUT` in dir (PHC appends the solutions to IN).
PhcRun phcBlackbox(const std::string& phc, const std::string& dir, const std::string& name,
                   const PolySystem& target);

// The start system of `phc -p` for a family: a generic complex member solved once by `phc -b`,
// its solutions' t set to 0 (phc -p starts each path at its solution's t). Cached in cache_dir
// across runs; *roots is the start's root count, *seconds the time to make it (0 when cached).
std::string startSystem(const std::string& phc, const std::string& cache_dir, Family family,
                        int* roots, double* seconds, std::string* error);

// `phc -p`: H = a(1−t)^k Q + t^k P from the start system Q (with its roots) to the target P,
// PHC's default settings, answered through its prompts on standard input.
PhcRun phcParameter(const std::string& phc, const std::string& dir, const std::string& name,
                    const PolySystem& target, const std::string& start_file);

}  // namespace relpos::bench
