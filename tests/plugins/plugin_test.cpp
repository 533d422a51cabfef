// Plugins through the loader, as a user loads them: the example plugins solve their bundled specs
// and random known-pose problems, pass the same conformance kits as the built-ins, outlive their
// registry inside solutions; bad plugins are refused with one clear line and the registry left
// untouched.
#include <elf.h>
#include <gtest/gtest.h>
#include <link.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>

#include "evaluator.hpp"
#include "expected_results.hpp"
#include "pin_manifold.hpp"
#include "random_problems.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/plugin_api.hpp"
#include "relpos/io/spec_reader.hpp"
#include "relpos/plugins/conformance.hpp"
#include "relpos/plugins/loader.hpp"
#include "solve_helpers.hpp"
#include "test_config.hpp"

namespace relpos::test {
namespace {
namespace fs = std::filesystem;

const std::string kSymmetric = RELPOS_PLUGIN_DIR "/relpos-symmetric.so";
const std::string kHelical = RELPOS_PLUGIN_DIR "/relpos-helical.so";

// Built-ins plus the given plugins; fails the test on a load error.
Registry withPlugins(std::initializer_list<std::string> paths, bool freeze = true) {
  Registry r;
  registerBuiltins(r);
  for (const auto& p : paths) {
    std::string error;
    EXPECT_TRUE(plugins::loadPlugin(p, r, &error)) << error;
  }
  if (freeze) r.freeze();
  return r;
}

const Registry& exampleRegistry() {
  static const Registry r = withPlugins({kSymmetric, kHelical});
  return r;
}

TEST(Plugins, ExamplePluginsSolveTheirBundledSpecs) {
  EXPECT_EQ(checkFolderAgainstExpectations("plugins", "plugins.json", exampleRegistry()), 2);
}

TEST(Plugins, ItemsCarryThePluginPathAsOrigin) {
  const Registry& r = exampleRegistry();
  ASSERT_NE(r.constraintType("symmetric"), nullptr);
  EXPECT_EQ(r.constraintType("symmetric")->origin, fs::canonical(kSymmetric).string());
  EXPECT_EQ(r.constraintType("distance")->origin, "built-in");
  ASSERT_NE(r.customKind("helical"), nullptr);
  EXPECT_EQ(r.customKind("helical")->origin, fs::canonical(kHelical).string());
  EXPECT_EQ(r.pluginPaths().size(), 2u);
}

TEST(Plugins, LoadingTheSamePathTwiceIsOneLoad) {
  Registry r = withPlugins({kSymmetric}, false);
  std::string error;
  EXPECT_TRUE(plugins::loadPlugin(RELPOS_PLUGIN_DIR "/../plugins/relpos-symmetric.so", r, &error))
      << error;
  EXPECT_EQ(r.pluginPaths().size(), 1u);
}

double noResidual(const Fundamental&, const Isometry3d&, const void*) { return 0.0; }

// The helical plugin keeps its kind's index in its callbacks' context, not in a global: two
// registries in which the kind has different indices both solve a thread, and its branch names
// the library it comes from (MatcherInfo::library, resolved at registration).
TEST(Plugins, EachRegistryKeepsItsOwnPluginState) {
  Registry first;
  registerBuiltins(first);
  first.addCustomKind({"taken-first", "moves helical to index 1", &noResidual});
  std::string error;
  ASSERT_TRUE(plugins::loadPlugin(kHelical, first, &error)) << error;
  first.freeze();
  const Registry second = withPlugins({kHelical});
  ASSERT_NE(first.customKind("helical") - first.customKinds().data(),
            second.customKind("helical") - second.customKinds().data());
  for (const Registry* r : {static_cast<const Registry*>(&first), &second}) {
    ParseResult pr = parseSpecFile(RELPOS_DATA_DIR "/plugins/helical-screw-insertion.json", *r);
    ASSERT_TRUE(pr.problem);
    const Solution s = solve(*pr.problem, *r);
    ASSERT_EQ(s.status, Status::kSolved) << s.message;
    ASSERT_NE(s.branches[0].origin, nullptr);
    EXPECT_EQ(s.branches[0].origin, fs::canonical(kHelical).string());
  }
}

// A thread around a known pose: random axis, pitch and turn; the known pose lies on the helix.
TEST(Plugins, RandomThreadsContainTheKnownPose) {
  Rng rng(77);
  for (int k = 0; k < 100; ++k) {
    Problem p;
    const Vector3d a = rng.point(), d = rng.unit(), u_m = rng.unit(), p_m = rng.point(0.5);
    const double pitch = rng.uniform(-0.01, 0.01) + (k % 2 ? 0.002 : -0.002);
    const double theta = rng.uniform(-40, 40);
    Isometry3d X = Isometry3d::Identity();
    X.linear() = axisAngle(d, theta) * Quaterniond::FromTwoVectors(u_m, d).toRotationMatrix();
    X.translation() = a + pitch * theta / (2 * kPi) * d - X.linear() * p_m;
    p.addFixedFeature("hole", Feature::makeCylinder(a, d, 0.004))
        .addMobileFeature("shank", Feature::makeLine(p_m, u_m));
    p.addConstraint("thread", "hole", "shank", pitch);
    p.constraints[0].has_value = true;
    p.mobile.pose = rng.pose();
    SCOPED_TRACE("thread #" + std::to_string(k));
    ASSERT_LT(worstViolation(p, X), 1e-9);
    Solution s = solve(p, exampleRegistry());
    ASSERT_EQ(s.status, Status::kSolved) << s.message;
    ASSERT_EQ(s.branches.size(), 1u);
    EXPECT_EQ(s.branches[0].manifold->dof(), 1);
    EXPECT_TRUE(someBranchContains(s, X)) << poseText(X);
    std::string where;
    EXPECT_LT(worstSampledViolation(p, s, 20, 500 + k, &where), 1e-8) << where;
    plugins::Report report;
    plugins::checkManifold(*s.branches[0].manifold, 900 + k, report);
    EXPECT_TRUE(report.ok()) << report.text();
  }
}

// A fingertip centre mirrored about a random mid-plane and kept within a distance range of a
// random point: the plugin's rule turns the shell and the plane into an annulus or a disc.
TEST(Plugins, RandomCentredGraspsContainTheKnownPose) {
  Rng rng(78);
  int annulus = 0, disc = 0;
  for (int k = 0; k < 100; ++k) {
    const Isometry3d X = rng.pose();
    const Vector3d c_m = rng.point(0.5), u_m = rng.unit();
    const Vector3d c_W = X * c_m, n_W = X.linear() * u_m;
    Problem p;
    p.addFixedFeature("mid", Feature::makePlane(c_W + rng.perpendicular(n_W), n_W));
    // The handle: off the plane by h, at distance r from the centre.
    const double h = rng.uniform(-0.3, 0.3);
    const Vector3d handle = c_W + h * n_W + rng.uniform(0.0, 0.4) * rng.perpendicular(n_W);
    const double r = (handle - c_W).norm();
    p.addFixedFeature("handle", Feature::makePoint(handle));
    p.addMobileFeature("fingers", Feature::makeLine(c_m, u_m))
        .addMobileFeature("centre", Feature::makePoint(c_m));
    p.addConstraint("symmetric", "mid", "fingers");
    p.addConstraint("distance", "handle", "centre");
    p.constraints[1].has_value = false;
    p.constraints[1].min = std::max(0.0, r - rng.uniform(0.01, 0.3));
    p.constraints[1].max = r + rng.uniform(0.01, 0.3);
    p.mobile.pose = rng.pose();
    SCOPED_TRACE("grasp #" + std::to_string(k));
    ASSERT_LT(worstViolation(p, X), 1e-9);
    Solution s = solve(p, exampleRegistry());
    ASSERT_EQ(s.status, Status::kSolved) << s.message;
    for (const char* rule : s.ruleNames()) {
      annulus += std::string(rule) == "shell-cut:pp+pplane/annulus";
      disc += std::string(rule) == "shell-cut:pp+pplane/disc";
    }
    EXPECT_TRUE(someBranchContains(s, X)) << describeBranches(s) << poseText(X);
    std::string where;
    EXPECT_LT(worstSampledViolation(p, s, 20, 700 + k, &where), 1e-8) << where;
    EXPECT_EQ(dofOfBranchesContaining(s, X), 3) << describeBranches(s);
  }
  EXPECT_GT(annulus, 10);
  EXPECT_GT(disc, 10);
}

// The installed rule kit on the plugin's rule: random shell/plane pairs around a known pose.
TEST(Plugins, PluginRulePassesTheRuleConformanceKit) {
  const Registry& reg = exampleRegistry();
  const RuleInfo* rule = nullptr;
  for (const auto& r : reg.rules())
    if (r.name == "shell-cut:pp+pplane") rule = &r;
  ASSERT_NE(rule, nullptr);
  Rng rng(79);
  std::mt19937_64 sampler(80);
  plugins::Report report;
  for (int k = 0; k < 200; ++k) {
    const Isometry3d X = rng.pose();
    const Vector3d p_m = rng.point(0.5), p_W = X * p_m, n = rng.unit();
    const Vector3d centre = rng.point();
    const double dist = (p_W - centre).norm();
    Fundamental shell = Fundamental::pointPoint(p_m, centre, 0.0, 1);
    shell.lo = std::max(0.0, dist - rng.uniform(0.01, 0.5));
    shell.hi = dist + rng.uniform(0.01, 0.5);
    const Fundamental plane = Fundamental::pointPlane(Side::kMobile, p_m, p_W, n, 0.0, 2);
    const Tolerance tol = Tolerance::forScale(3.0);
    plugins::checkRule(reg, *rule, shell, plane, tol, sampler, report, &X);
  }
  EXPECT_TRUE(report.ok()) << report.text();
  EXPECT_GT(report.checked, 150);
}

TEST(Plugins, SolutionsKeepThePluginLoadedAfterTheRegistryIsGone) {
  // A copy of its own: no other registry of this process holds that file, so without the
  // solution's reference the library would really be unloaded here.
  const std::string own_copy = ::testing::TempDir() + "keep-alive-helical.so";
  fs::copy_file(kHelical, own_copy, fs::copy_options::overwrite_existing);
  Solution s;
  Isometry3d X_expected;
  {
    const Registry r = withPlugins({own_copy});
    ParseResult pr = parseSpecFile(RELPOS_DATA_DIR "/plugins/helical-screw-insertion.json", r);
    ASSERT_TRUE(pr.problem);
    s = solve(*pr.problem, r);
    ASSERT_EQ(s.status, Status::kSolved);
    Params t{};
    t[0] = 2 * kPi;
    X_expected = s.branches[0].manifold->pose(t);
  }
  // The registry (and its reference to the library) is gone; the branch's code is still there.
  Params t{};
  t[0] = 2 * kPi;
  EXPECT_LT(poseDistance(s.branches[0].manifold->pose(t), X_expected), 1e-15);
  Solution copy = s;
  s = Solution();
  EXPECT_EQ(copy.branches[0].manifold->describe(), "mixed Helical (pitch 0.001250 per turn)");
}

// --- bad plugins ------------------------------------------------------------------------------

struct Counts {
  std::size_t types, rules, manifolds, matchers, kinds, plugins;
  bool operator==(const Counts& o) const {
    return types == o.types && rules == o.rules && manifolds == o.manifolds &&
           matchers == o.matchers && kinds == o.kinds && plugins == o.plugins;
  }
};
Counts counts(const Registry& r) {
  return {r.constraintTypes().size(), r.rules().size(),       r.manifolds().size(),
          r.matchers().size(),        r.customKinds().size(), r.pluginPaths().size()};
}

// Loading fails with `expected` in its message and leaves the registry as it was.
void expectRefused(const std::string& path, const std::string& expected) {
  Registry r;
  registerBuiltins(r);
  const Counts before = counts(r);
  std::string error;
  EXPECT_FALSE(plugins::loadPlugin(path, r, &error));
  EXPECT_NE(error.find(expected), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
  EXPECT_EQ(error.rfind(path, 0), 0u) << "names the plugin: " << error;
  EXPECT_TRUE(counts(r) == before);
  EXPECT_EQ(r.constraintType("half-registered"), nullptr);
  EXPECT_EQ(r.constraintType("distance")->origin, "built-in");
}

TEST(BadPlugins, AFileThatIsNotALibrary) {
  const std::string path = ::testing::TempDir() + "not-a-library.so";
  std::ofstream(path) << "this is text, not ELF\n";
  expectRefused(path, "not a loadable plugin (not an ELF file");
}

TEST(BadPlugins, AMissingFile) {
  expectRefused(::testing::TempDir() + "no-such-plugin.so", "no such plugin file");
}

TEST(BadPlugins, AnEmptyFile) {
  const std::string path = ::testing::TempDir() + "empty-plugin.so";
  std::ofstream{path};
  expectRefused(path, "not a loadable plugin (an empty file)");
}

TEST(BadPlugins, ADirectory) {
  const std::string path = ::testing::TempDir() + "a-directory.so";
  fs::create_directories(path);
  expectRefused(path, "a directory, not a plugin file");
}

// A copy of a real plugin with `edit` applied to its bytes, in the test's temp dir.
std::string editedPlugin(const std::string& name, const std::function<void(std::string&)>& edit) {
  std::ifstream in(kHelical, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  edit(bytes);
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  return path;
}

ElfW(Ehdr) & header(std::string& bytes) { return *reinterpret_cast<ElfW(Ehdr)*>(&bytes[0]); }

// dlopen maps the segments the headers name: a file cut short would be a SIGBUS inside dlopen
// (this whole test binary dying) when the check did not come first.
TEST(BadPlugins, ATruncatedLibraryIsRefusedBeforeDlopen) {
  const std::string cut = editedPlugin("truncated-2000.so", [](std::string& b) { b.resize(2000); });
  expectRefused(cut, "not a loadable plugin (truncated: segment ");
  Registry r;
  std::string error;
  EXPECT_FALSE(plugins::loadPlugin(cut, r, &error));
  EXPECT_NE(error.find(" of a 2000-byte file)"), std::string::npos) << error;

  // Every cut: inside the ELF header, the program headers, the segments, the section headers.
  const auto full = static_cast<std::size_t>(fs::file_size(kHelical));
  for (std::size_t size : {std::size_t{3}, std::size_t{40}, std::size_t{63}, std::size_t{100},
                           std::size_t{300}, full / 4, full / 2, full - 100, full - 1}) {
    SCOPED_TRACE("cut to " + std::to_string(size) + " of " + std::to_string(full) + " bytes");
    const std::string path = editedPlugin("truncated.so", [&](std::string& b) { b.resize(size); });
    expectRefused(path, size < 4 ? "not an ELF file" : "truncated: ");
  }
}

TEST(BadPlugins, AnElfFileThisHostCannotRun) {
  const struct {
    const char* name;
    std::function<void(std::string&)> edit;
    const char* expected;
  } cases[] = {
      {"elf32.so", [](std::string& b) { header(b).e_ident[EI_CLASS] = ELFCLASS32; },
       "a 32-bit ELF file; this relpos is 64-bit"},
      {"big-endian.so",
       [](std::string& b) {
         header(b).e_ident[EI_DATA] =
             header(b).e_ident[EI_DATA] == ELFDATA2LSB ? ELFDATA2MSB : ELFDATA2LSB;
       },
       __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
           ? "a big-endian ELF file; this host is little-endian"
           : "a little-endian ELF file; this host is big-endian"},
      {"other-machine.so",
       [](std::string& b) {
         header(b).e_machine = header(b).e_machine == EM_AARCH64 ? EM_X86_64 : EM_AARCH64;
       },
       "built for another machine ("},
      {"executable.so", [](std::string& b) { header(b).e_type = ET_EXEC; },
       "an executable, not a shared library"},
      {"object.so", [](std::string& b) { header(b).e_type = ET_REL; },
       "an object file (.o), not a shared library"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    expectRefused(editedPlugin(c.name, c.edit),
                  std::string("not a loadable plugin (") + c.expected);
  }
}

// Headers that point outside the file, whatever their size (no overflow in the check).
TEST(BadPlugins, HeadersPointingPastTheEndOfTheFile) {
  auto firstLoad = [](std::string& b) -> ElfW(Phdr) & {
    auto* ph = reinterpret_cast<ElfW(Phdr)*>(&b[header(b).e_phoff]);
    for (int i = 0; i < header(b).e_phnum; ++i)
      if (ph[i].p_type == PT_LOAD) return ph[i];
    throw std::runtime_error("no PT_LOAD");
  };
  expectRefused(
      editedPlugin("far-segment.so", [&](std::string& b) { firstLoad(b).p_offset = ~0ull - 8; }),
      "ends at byte 18446744073709551615 of a ");
  expectRefused(
      editedPlugin("long-segment.so", [&](std::string& b) { firstLoad(b).p_filesz = ~0ull; }),
      "truncated: segment ");
  expectRefused(editedPlugin("far-program-headers.so",
                             [](std::string& b) { header(b).e_phoff = 1ull << 40; }),
                "truncated: the program header table ends at byte ");
  expectRefused(
      editedPlugin("far-section-headers.so", [](std::string& b) { header(b).e_shoff = b.size(); }),
      "truncated: the section header table ends at byte ");
}

// Bound lazily, the missing function would only be looked up at its first call, inside
// registration, and the dynamic loader would end the process (exit 127).
TEST(BadPlugins, AnUnresolvedSymbolIsRefusedAtLoad) {
  expectRefused(RELPOS_BAD_PLUGIN_DIR "/bad-unresolved-symbol.so",
                "not a loadable plugin (undefined symbol: relpos_test_function_nothing_defines");
}

TEST(BadPlugins, ALibraryWithoutTheEntryPoint) {
  expectRefused(RELPOS_BAD_PLUGIN_DIR "/bad-no-entry.so", "not a relpos plugin");
}

TEST(BadPlugins, AWrongAbiVersion) {
  expectRefused(
      RELPOS_BAD_PLUGIN_DIR "/bad-wrong-abi.so",
      "built for relpos plugin ABI " + std::to_string(kPluginAbiVersion + 1) + " (layout 0x");
}

// The same version, other layouts: refused with the version and both fingerprints named.
TEST(BadPlugins, AWrongLayoutFingerprint) {
  char mine[32], theirs[32];
  std::snprintf(mine, sizeof mine, "%#lx", pluginAbiFingerprintOf(pluginAbi()));
  std::snprintf(theirs, sizeof theirs, "%#lx", pluginAbiFingerprintOf(pluginAbi() ^ 1L));
  const std::string v = std::to_string(kPluginAbiVersion);
  expectRefused(RELPOS_BAD_PLUGIN_DIR "/bad-wrong-layout.so",
                "built for relpos plugin ABI " + v + " (layout " + theirs + "), this relpos has " +
                    v + " (layout " + mine +
                    "): the same version built from headers with other shared layouts");
}

// A slide along x over [-1, 1]: what the broken manifolds below get wrong is their own.
template <typename Derived>
class SlideAlongX : public MixedManifoldBase<Derived> {
 public:
  int dof() const override { return 1; }
  Parameter parameter(int) const override { return {"x", ParamKind::kLength, -1.0, 1.0, false}; }
  Isometry3d pose(const Params& t) const override {
    Isometry3d X = Isometry3d::Identity();
    X.translation().x() = t[0];
    return X;
  }
};

// A slide whose project() forgets where it was (always 0): the kit names the invariant.
class ForgetfulSlide final : public SlideAlongX<ForgetfulSlide> {
 public:
  const char* typeName() const override { return "ForgetfulSlide"; }
  Params project(const Isometry3d&) const override { return Params{}; }
  std::string describe() const override { return "forgetful slide"; }
};

TEST(Conformance, AFailureIsNamedByTheInvariantThatBroke) {
  plugins::Report report;
  plugins::checkManifold(ForgetfulSlide(), 3, report, 5);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.failures[0].rfind("[params-round-trip] forgetful slide: ", 0), 0u)
      << report.text();
}

// A slide that weighs every pose for the search as half its distance: a shortcut
// (Manifold::searchDistance) that is not the pose's distance.
class HalfWeighedSlide final : public SlideAlongX<HalfWeighedSlide> {
 public:
  const char* typeName() const override { return "HalfWeighedSlide"; }
  Params project(const Isometry3d& X) const override {
    return Params{std::min(1.0, std::max(-1.0, X.translation().x()))};
  }
  double searchDistance(const Isometry3d& X, Params* t) const override {
    return 0.5 * poseDistance(pose(*t), X);
  }
  std::string describe() const override { return "half-weighed slide"; }
};

TEST(Conformance, ASearchDistanceThatIsNotThePosesIsNamed) {
  plugins::Report report;
  plugins::checkManifold(HalfWeighedSlide(), 3, report, 5);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.failures[0].rfind("[search-distance] half-weighed slide: ", 0), 0u)
      << report.text();
}

// A pin that claims a coupling of 1 where its positions move 5 a radian (pin_manifold.hpp): a
// turn away from X's rotation is nearer than keeping it, and the kit names the claim.
TEST(Conformance, ACouplingThatATurnBeatsIsNamed) {
  plugins::Report report;
  plugins::checkManifold(test::PinManifold(1.0), 3, report, 5);
  ASSERT_FALSE(report.ok());
  EXPECT_EQ(report.failures[0].rfind("[rotation-coupling] pin: ", 0), 0u) << report.text();
  // Its honest coupling, 5, claims nothing: the search finds the turn, and the kit is content.
  plugins::Report honest;
  plugins::checkManifold(test::PinManifold(5.0), 3, honest, 5);
  EXPECT_TRUE(honest.ok()) << honest.text();
}

// The fingerprint reads layouts and signatures: a callback with one more parameter, or a struct
// with one more member, is another fingerprint.
TEST(PluginAbi, TheFingerprintSeesSignaturesAndLayouts) {
  using Two = void (*)(const Fundamental&, const void*);
  using Three = void (*)(const Fundamental&, const void*, int);
  EXPECT_NE(abi::Signature<Two>::value, abi::Signature<Three>::value);
  using ByValue = void (*)(Fundamental, const void*);
  EXPECT_NE(abi::Signature<Two>::value, abi::Signature<ByValue>::value);
  struct A {
    double x;
    int y;
  };
  struct B {
    int y;
    double x;
  };
  EXPECT_NE(abi::hash(RELPOS_ABI_MEMBER(A, x), RELPOS_ABI_MEMBER(A, y)),
            abi::hash(RELPOS_ABI_MEMBER(B, x), RELPOS_ABI_MEMBER(B, y)));
  EXPECT_EQ(pluginAbiVersionOf(pluginAbi()), kPluginAbiVersion);
  EXPECT_EQ(pluginAbiVersionOf(5 * 1000000L + 4242), 5);  // an answer of version 5's form
}

TEST(BadPlugins, APluginThatThrowsWhileRegistering) {
  expectRefused(RELPOS_BAD_PLUGIN_DIR "/bad-throws.so",
                "registration failed: the plugin's own set-up failed");
}

TEST(BadPlugins, ADuplicateNameUnlessOverrideIsAskedFor) {
  expectRefused(RELPOS_BAD_PLUGIN_DIR "/bad-duplicate.so",
                "constraint type 'distance' is already registered (by built-in)");
  Registry r;
  registerBuiltins(r);
  std::string error;
  plugins::LoadOptions override;
  override.allow_override = true;
  ASSERT_TRUE(plugins::loadPlugin(RELPOS_BAD_PLUGIN_DIR "/bad-duplicate.so", r, &error, override))
      << error;
  EXPECT_EQ(r.constraintType("distance")->description, "a plugin's replacement");
  EXPECT_NE(r.constraintType("distance")->origin, "built-in");
}

TEST(BadPlugins, AFrozenRegistryTakesNoPlugin) {
  Registry r;
  registerBuiltins(r);
  r.freeze();
  std::string error;
  EXPECT_FALSE(plugins::loadPlugin(kSymmetric, r, &error));
  EXPECT_NE(error.find("frozen"), std::string::npos) << error;
}

TEST(PluginPath, FoldersExpandToTheirLibrariesInNameOrder) {
  const auto files = plugins::expandPluginPath(std::string(RELPOS_PLUGIN_DIR) + "::/nowhere.so");
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(fs::path(files[0]).filename(), "relpos-helical.so");
  EXPECT_EQ(fs::path(files[1]).filename(), "relpos-symmetric.so");
  EXPECT_EQ(files[2], "/nowhere.so");
}

}  // namespace
}  // namespace relpos::test
