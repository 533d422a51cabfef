// The start systems stored in data/start_systems and compiled into relpos_complete: each names
// the family its source spec encodes to (a stale signature is caught here), its roots are
// distinct certified roots of its member, an independent recomputation finds as many, and the
// trace test passes again where the generator's passed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "krawczyk.hpp"
#include "polynomial_eval.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/complete/encoding.hpp"
#include "relpos/complete/problem_encoding.hpp"
#include "relpos/io/spec_reader.hpp"
#include "start_system.hpp"
#include "stored_start_systems.hpp"
#include "test_config.hpp"
#include "total_degree.hpp"
#include "trace_test.hpp"

namespace relpos::complete {
namespace {

const std::string kRoot = RELPOS_DATA_DIR "/..";

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The family of a stored file's source ("spec alternative"), encoded as the stage does.
std::unique_ptr<Family> familyOfSource(const std::string& source) {
  std::istringstream words(source);
  std::string spec;
  unsigned alternative = 0;
  if (!(words >> spec >> alternative)) return nullptr;
  ParseResult r = parseSpecFile(kRoot + "/" + spec, builtinRegistry());
  if (!r.problem) return nullptr;
  const Problem& p = *r.problem;
  const Tolerance tol = Tolerance::forScale(2.0 * p.lengthScale());
  std::string why;
  if (mobileFeaturesOnOneLine(p, tol)) {
    LineEncoding e;
    if (alternative != 0 || !encodeLine(p, tol, &e, &why)) return nullptr;
    return std::make_unique<LineFamily>(e.equations, static_cast<int>(e.target.size()));
  }
  PoseEncoding e;
  if (!encodePose(p, 0, &e, &why, alternative)) return nullptr;
  return std::make_unique<PoseFamily>(e.equations, static_cast<int>(e.target.size()));
}

detail::StoredStartSystem parsed(const detail::EmbeddedText& e) {
  detail::StoredStartSystem s;
  std::string why;
  EXPECT_TRUE(detail::parseStoredStartSystem(e.text, &s, &why)) << e.name << ": " << why;
  return s;
}

TEST(StoredStartSystems, TheLibraryEmbedsExactlyTheFilesOfTheRepository) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(kRoot + "/data/start_systems"))
    if (entry.path().extension() == ".txt")
      files[entry.path().filename().string()] = readFile(entry.path().string());
  ASSERT_GE(files.size(), 3u);  // the benchmark families at least
  const auto& table = detail::embeddedStartSystems();
  ASSERT_EQ(table.size(), files.size());
  for (const auto& e : table) {
    ASSERT_TRUE(files.count(e.name)) << e.name;
    EXPECT_EQ(files[e.name], e.text) << e.name << " changed since the build";
  }
}

TEST(StoredStartSystems, EveryBenchmarkFamilyHasOne) {
  std::map<std::string, int> stored;
  for (const auto& e : detail::embeddedStartSystems()) ++stored[parsed(e).signature];
  for (const char* spec : {"stewart-gough-dietmaier-40.json", "octahedral-a.json",
                           "octahedral-b.json", "four-spheres-12-lines.json"}) {
    const auto f = familyOfSource(std::string("data/complete/") + spec + " 0");
    ASSERT_TRUE(f) << spec;
    EXPECT_EQ(stored[f->signature()], 1) << spec << ": " << f->signature();
    EXPECT_TRUE(startSystem(*f).stored) << spec;
  }
}

// A stored signature spells out its family: familyOfSignature rebuilds the family the source
// spec encodes to (same signature, same shape), and refuses texts that are not signatures.
TEST(StoredStartSystems, EverySignatureRebuildsItsFamily) {
  for (const auto& e : detail::embeddedStartSystems()) {
    const detail::StoredStartSystem s = parsed(e);
    const auto rebuilt = familyOfSignature(s.signature);
    const auto encoded = familyOfSource(s.source);
    ASSERT_TRUE(rebuilt) << e.name;
    ASSERT_TRUE(encoded) << e.name;
    EXPECT_EQ(rebuilt->signature(), s.signature);
    EXPECT_EQ(rebuilt->parameterCount(), encoded->parameterCount());
    EXPECT_EQ(rebuilt->shape().terms.size(), encoded->shape().terms.size());
    // Cut short, with a kind renamed, a count changed or a field added: not a signature.
    EXPECT_FALSE(familyOfSignature(s.signature.substr(0, s.signature.size() - 1))) << e.name;
    std::string renamed = s.signature;
    renamed.replace(renamed.find(';') + 1, 1, "X");
    EXPECT_FALSE(familyOfSignature(renamed)) << e.name;
    EXPECT_FALSE(familyOfSignature(s.signature + ";study(-1,-1,-1,-1)")) << e.name;
  }
  for (const char* text : {"", "pose", "pose/", "pose/x", "line/3;unit(-1,-1)", "plane/4;x(1)",
                           "pose/4;chart(-1,-1,-1,0)"})
    EXPECT_FALSE(familyOfSignature(text)) << text;
}

// preloadStoredStartSystems loads each stored file (every one fits its family).
TEST(StoredStartSystems, PreloadLoadsEveryFile) {
  EXPECT_EQ(preloadStoredStartSystems(),
            static_cast<int>(detail::embeddedStartSystems().size()));
}

class EachStored : public ::testing::TestWithParam<int> {};

// The file names its family (the source spec re-encoded today gives the stored signature), its
// roots are distinct certified roots of its member, startSystem uses it, and a computation from
// another generic member (monodromy with the total-degree cross-check) finds as many roots.
TEST_P(EachStored, IsTheCertifiedStartSystemOfItsFamily) {
  const auto& table = detail::embeddedStartSystems();
  ASSERT_LT(GetParam(), static_cast<int>(table.size()));
  const detail::EmbeddedText& e = table[GetParam()];
  const detail::StoredStartSystem s = parsed(e);
  EXPECT_EQ(detail::formatStoredStartSystem(s), e.text);  // exact round trip
  EXPECT_EQ(detail::storedFileName(s.signature), e.name);
  const auto f = familyOfSource(s.source);
  ASSERT_TRUE(f) << e.name << ": source " << s.source;
  ASSERT_EQ(f->signature(), s.signature) << e.name << " is stale: regenerate data/start_systems";

  std::string why;
  EXPECT_TRUE(detail::certifyStartSystem(*f, s.system, &why)) << why;
  const detail::CompiledShape shape(f->shape());
  std::vector<Complex> c(shape.terms());
  f->coefficients(s.system.params.data(), c.data());
  detail::EvalScratch scratch(shape);
  for (const Eigen::VectorXcd& r : s.system.roots) {
    detail::CVec fx(shape.variables());
    detail::evaluate(shape, c.data(), nullptr, detail::CVec(r), scratch, &fx, nullptr, nullptr);
    EXPECT_LT(fx.lpNorm<Eigen::Infinity>(), 1e-10 * (1.0 + r.squaredNorm()));
  }

  const StartSystem& used = startSystem(*f);
  EXPECT_TRUE(used.stored);
  ASSERT_EQ(used.roots.size(), s.system.roots.size());
  for (std::size_t i = 0; i < used.roots.size(); ++i) EXPECT_EQ(used.roots[i], s.system.roots[i]);

  // Independent: another generic member and other loops.
  const auto again = detail::computeStartSystem(*f, detail::kDefaultMaxBezout, 0x5eed2026);
  EXPECT_EQ(again->roots.size(), s.system.roots.size());
  // The stored check is the computation's, with "+trace" when the generator's trace test passed.
  const std::string claimed = s.system.check;
  const bool traced = claimed.size() > 6 && claimed.compare(claimed.size() - 6, 6, "+trace") == 0;
  EXPECT_EQ(again->check, traced ? claimed.substr(0, claimed.size() - 6) : claimed);
  if (traced) {
    // The trace test again, on another line and other slices.
    const detail::TraceOutcome t = detail::traceTest(*f, s.system, 0x7ace2026);
    EXPECT_TRUE(t.passed) << e.name << ": " << t.why;
    EXPECT_EQ(t.fibre_roots, static_cast<int>(s.system.roots.size()));
    EXPECT_GT(s.system.trace_witness_points, 0);
  } else {
    EXPECT_EQ(s.system.trace_witness_points, 0);
  }

  // The total-degree homotopy at the stored member itself: every root it certifies is a stored
  // one, and it certifies every stored one.
  const std::uint64_t bezout = detail::bezoutNumber(shape);
  if (bezout <= detail::kDefaultMaxBezout) {
    detail::Certifier cert(shape, c.data());
    std::vector<bool> hit(s.system.roots.size(), false);
    for (const detail::CVec& x : detail::totalDegreeEndpoints(f->shape(), c.data(), 77)) {
      const detail::BoxCertificate b = cert.certify(x);
      if (!b.ok) continue;
      bool stored = false;
      for (std::size_t i = 0; i < s.system.roots.size(); ++i) {
        const detail::BoxCertificate si = cert.certify(detail::CVec(s.system.roots[i]));
        if (si.ok && detail::boxesOverlap(si.x, si.radius, b.x, b.radius)) hit[i] = stored = true;
      }
      EXPECT_TRUE(stored) << "a root of the member missing from " << e.name;
    }
    for (std::size_t i = 0; i < hit.size(); ++i) EXPECT_TRUE(hit[i]) << e.name << " root " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Files, EachStored,
                         ::testing::Range(0,
                                          static_cast<int>(detail::embeddedStartSystems().size())));

// A stored text whose signature differs from the family's (a changed signature format), whose
// roots are not roots, or whose counts do not fit, is not used.
TEST(StoredStartSystems, AFileThatDoesNotFitItsFamilyIsNotUsed) {
  const auto& table = detail::embeddedStartSystems();
  ASSERT_FALSE(table.empty());
  const detail::StoredStartSystem s = parsed(table[0]);
  const auto f = familyOfSource(s.source);
  ASSERT_TRUE(f);
  auto load = [&](const detail::StoredStartSystem& t) {
    const std::string text = detail::formatStoredStartSystem(t);
    const std::vector<detail::EmbeddedText> one = {{table[0].name, text.c_str()}};
    std::string why;
    return detail::loadStoredStartSystem(*f, one, &why) != nullptr;
  };
  EXPECT_TRUE(load(s));

  detail::StoredStartSystem other = s;
  other.signature += " ";  // same file name, another signature
  EXPECT_FALSE(load(other));

  detail::StoredStartSystem moved = s;
  moved.system.roots[0][0] += 1e-3;
  EXPECT_FALSE(load(moved));

  detail::StoredStartSystem twice = s;
  twice.system.roots.push_back(twice.system.roots[0]);
  EXPECT_FALSE(load(twice));

  detail::StoredStartSystem fewer = s;
  fewer.system.params.pop_back();
  EXPECT_FALSE(load(fewer));

  // The text itself: truncated or with a changed format line, not parsed.
  std::string why;
  detail::StoredStartSystem out;
  const std::string text = table[0].text;
  EXPECT_FALSE(detail::parseStoredStartSystem(text.substr(0, text.size() / 2), &out, &why));
  EXPECT_FALSE(detail::parseStoredStartSystem(
      "relpos-start-system 2" + text.substr(text.find('\n')), &out, &why));
}

}  // namespace
}  // namespace relpos::complete
