#pragma once
// Structured mutations of relpos specs (issue 13): the edits a careless or hostile user, a broken
// exporter or a cut download make to a spec — members and elements deleted, duplicated, swapped;
// types changed; numbers huge, tiny, negative, NaN-spelled or beyond double range; zero and huge
// directions; deep nesting; non-ASCII, invalid UTF-8 and control characters in names and keys;
// truncation; unknown types and features; duplicated features; other orientations; fixed and
// mobile swapped — and also the edits that keep a spec valid but make it another problem
// (another feature, value, orientation or constraint), so that the solver, not only the reader,
// is exercised. Deterministic for a given seed.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "json_tree.hpp"

namespace relpos::fuzz {

struct Seed {
  std::string origin;  // "data/examples/x.json" or "data/batch/y.jsonl:17"
  JsonNode tree;
};

// Every spec of data/ (every *.json outside data/expected, every line of every *.jsonl), in name
// order. A spec's "plugins" list is dropped: a batch loads every line's plugins before it starts,
// and a path that does not resolve would stop the whole batch.
std::vector<Seed> loadSeeds(const std::string& data_dir);

struct MutationOptions {
  bool one_line = false;      // a JSONL line: never a raw newline, never blank
  int max_depth = 10000;      // deepest nesting a mutation may write (up to 300000)
  double deep_share = 0.002;  // of mutations that nest, the share that nest 10⁵ or 3×10⁵ deep
};

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed, MutationOptions options = {});

  // A mutated copy of `seed` as text; `what` (optional) receives the mutations applied, for a
  // report. `name`, when not empty, is set as the spec's "name" before mutating (a mutation may
  // still change it), so that results can be told apart.
  std::string mutate(const JsonNode& seed, const std::string& name, std::string* what = nullptr);

 private:
  struct Slot;
  std::vector<Slot> slots(JsonNode& root);
  bool mutateTree(JsonNode& root, std::string& what);
  void mutateText(std::string& text, std::string& what);

  std::size_t below(std::size_t n);  // uniform in [0, n)
  bool chance(double p);
  std::string pick(const std::vector<std::string>& options);
  JsonNode randomScalar();
  JsonNode randomFeature();
  std::string weirdNumber();
  std::string weirdBytes();
  std::string deepText();

  std::mt19937_64 rng_;
  MutationOptions options_;
};

}  // namespace relpos::fuzz
