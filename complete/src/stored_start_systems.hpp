#pragma once
// Start systems stored in the repository (data/start_systems/*.txt, issue 15): computed offline
// by complete/tools/make_start_systems.cpp and compiled into the library (the build turns the
// files into a table, cmake/embed_start_systems.cmake), so that a one-shot solve does not run
// monodromy. The signature is stored spelled out and compared whole: a file written for another
// signature format is never used for a family it does not name.
//
// Format (text, one item a line; numbers in C99 hex-float, exact):
//   relpos-start-system 1
//   signature <Family::signature()>
//   source <spec file the generator encoded, relative to the repository> <alternative>
//   check <StartSystem::check>
//   counts <monodromy_loops> <total_degree_paths> <total_degree_added>
//          <second_monodromy_roots> <second_monodromy_added> <trace_witness_points>
//   params <P>            then P lines "re im"
//   roots <N> <n>         then N lines of n "re im" pairs
#include <memory>
#include <string>
#include <vector>

#include "relpos/complete/fiber.hpp"

namespace relpos::complete::detail {

struct StoredStartSystem {
  std::string signature;
  std::string source;  // "path alternative" (what the test re-encodes to check the signature)
  StartSystem system;
};

std::string formatStoredStartSystem(const StoredStartSystem& s);
// False (the reason in *why) on any deviation from the format.
bool parseStoredStartSystem(const std::string& text, StoredStartSystem* out, std::string* why);

// The file name of a signature's start system: 16 hex digits of its stable hash, ".txt".
std::string storedFileName(const std::string& signature);

// The texts compiled into the library (name, contents), in file-name order.
struct EmbeddedText {
  const char* name;
  const char* text;
};
const std::vector<EmbeddedText>& embeddedStartSystems();

// The stored start system of f's signature, checked against f: the parameter and variable
// counts match, and every root passes Krawczyk's test on the member's coefficients with boxes
// pairwise disjoint (a stored file that no longer fits its family is not used). nullptr when
// there is none or it fails (*why says which, if not null).
std::unique_ptr<StartSystem> loadStoredStartSystem(const Family& f, std::string* why = nullptr);
// The same from another table (tests).
std::unique_ptr<StartSystem> loadStoredStartSystem(const Family& f,
                                                   const std::vector<EmbeddedText>& table,
                                                   std::string* why);

// Whether the roots of s are distinct certified roots of f's member at s.params (the check above).
bool certifyStartSystem(const Family& f, const StartSystem& s, std::string* why);

}  // namespace relpos::complete::detail
