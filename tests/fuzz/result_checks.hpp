#pragma once
// The invariants of issue 13 that hold on ANY input, checked on what relpos gives back: a parse
// either gives a problem or one-line diagnostics that name a JSON path (or where the JSON is
// malformed); a result is one valid UTF-8 JSON document of docs/spec.md §2 whose numbers are all
// finite (only the nulls SPEC allows), and every pose it reports — each branch's nearest pose
// and samples, as read back from the text — satisfies every input constraint by the tests'
// evaluator (tests/support/evaluator.hpp, written from SPEC alone). Shared by the libFuzzer
// target, the mutation test and the mutation campaign.
#include <string>
#include <string_view>
#include <vector>

#include "relpos/core/problem.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/report/evaluate.hpp"

namespace relpos::fuzz {

// One broken invariant. Kinds: "wrong-answer" (a reported pose violates a constraint),
// "bad-output" (not UTF-8 or JSON, a NaN/null where SPEC has a number, a field of the wrong
// shape), "split-diagnostic" (a Diagnostic holding a newline), "pathless-message"; the CLI
// checks add "split-message" (a stderr line that does not name the file), "crash", "hang",
// "exit-1", "exit-code", "lost-line" and "slow"; checkAccepted "accepted-invalid-json",
// checkProblem "bad-problem".
struct Finding {
  std::string kind;
  std::string detail;
};
using Findings = std::vector<Finding>;

// A pose counts as satisfying the constraints when every violation, with lengths measured in
// units of the problem's size, is at most this: a thousand times the solver's own tolerance
// (SolverOptions: 1e-9 relative lengths, 1e-9 rad), a tenth of the violation at which the solver
// itself calls a branch a numerical breakdown (10⁴ tolerances), and ten orders of magnitude above
// the rounding of evaluating a pose (1e-16 relative). Anything above it is a wrong answer, not
// rounding.
inline constexpr double kRelativeTolerance = 1e-6;

// The problem's length scale: its largest coordinate, radius or length value (Problem::
// lengthScale) or finite distance bound, at least 1e-300 (so that a problem of zeros divides).
double problemSize(const Problem& p);

// The problem with every length divided by `size` (points, positions, radii, distance values
// and bounds); directions and angles unchanged. Its violations are relative lengths and radians,
// one scale for both.
Problem scaledProblem(const Problem& p, double size);

bool isValidUtf8(std::string_view s);

struct ResultExpectation {
  int samples = 0;         // poses per branch asked for
  bool one_line = true;    // a result line (batch, writeResultLine); false: `solve`'s document
  bool name_known = true;  // the result's "name" must be the problem's name
};

// Reads the result document `text` back and checks it against the problem it answers.
void checkResultText(const std::string& text, const Problem& problem,
                     const ResultExpectation& expect, Findings& out);

// Every diagnostic names a path, or says "malformed JSON at line L, column C"; a problem comes
// with no errors, no problem with at least one. With `one_line`, no diagnostic holds a newline
// (the library's promise; the CLI also escapes what it prints, which its own checks see).
void checkDiagnostics(const ParseResult& r, Findings& out, bool one_line = true);

// A reader that gives a problem has read one JSON document (RFC 8259): the text is valid UTF-8
// and holds no control character but tab, newline and carriage return (JSON allows them nowhere
// else, raw) — in particular no NUL, after which a C-string reader would stop reading — and the
// problem it gives keeps checkProblem's promises.
void checkAccepted(std::string_view text, const ParseResult& r, Findings& out);

// What parsing promises of a Problem (feature.hpp, problem.hpp): every number finite, every
// direction and normal of unit length, every pose rigid. A spec that breaks it should have been
// refused: the solver and the checks above would otherwise reason about another problem (a
// direction that overflowed to zero satisfies every constraint on it).
void checkProblem(const Problem& p, Findings& out);

// Whether a message (after "FILE: ") with the empty JSON path is about the document as a whole
// (whose path the empty one is) and says where: a place in its text ("malformed JSON at line L,
// column C: …", "too deeply nested at line L, column C: …", "… '1e400' (line L, column C)" of a
// root that is a number) or its root not being an object (docs/spec.md §1.11).
bool namesTheDocument(std::string_view message);

// The first `n` characters of `s` with bytes outside printable ASCII as \xHH: quotable in a
// report whatever the input held.
std::string printable(std::string_view s, std::size_t n = 300);

}  // namespace relpos::fuzz
