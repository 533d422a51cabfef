// The relpos command and the API example, run as a user runs them.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_run.hpp"
#include "test_config.hpp"

namespace {

using namespace relpos::test;

TEST(Cli, SolveWorkedExample) {
  CmdResult r = run("solve " + kExample + " --samples 3 --seed 5");
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "solved");
  EXPECT_EQ(j["name"], "pmf-simple-example");
  ASSERT_EQ(j["branches"].size(), 1u);
  const auto& b = j["branches"][0];
  EXPECT_EQ(b["dof"], 1);
  EXPECT_EQ(b["rotational_dof"], 1);
  EXPECT_EQ(b["translational_dof"], 0);
  EXPECT_EQ(b["samples"].size(), 3u);
  // Nearest to the identity: φ = 0, |T| = 5 and a quarter turn (derived by hand: along the
  // branch |T|² = 25 + 18(1 − cos φ) and the rotation angle is acos((cos φ − 1)/2)).
  EXPECT_NEAR(b["nearest"]["distance"].get<double>(), 5 + M_PI / 2, 1e-9);
  EXPECT_EQ(j["best"], 0);
  EXPECT_TRUE(j["stats"]["solve_us"].is_number());
}

TEST(Cli, InconsistentNamesConstraintsAndTheirIds) {
  CmdResult r = run("solve " RELPOS_DATA_DIR "/examples/inconsistent-two-points.json");
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "inconsistent");
  EXPECT_EQ(j["conflicts"], nlohmann::json({0, 1}));
  EXPECT_EQ(j["branches"].size(), 0u);
  const std::string msg = j["message"];
  EXPECT_NE(msg.find("(constraints 0 = 'P on A', 1 = 'Q on B')"), std::string::npos) << msg;
}

// Issue 17: --angles deg writes every angle in degrees and nothing else differently.
TEST(Cli, AnglesInDegrees) {
  const std::string spec = RELPOS_DATA_DIR "/scenarios/scenario-b-seam-welding.json";
  CmdResult rad = run("solve " + spec + " --samples 2"), deg = run("solve " + spec +
                                                                    " --samples 2 --angles deg");
  ASSERT_EQ(rad.code, 0) << rad.err;
  ASSERT_EQ(deg.code, 0) << deg.err;
  const nlohmann::json a = nlohmann::json::parse(rad.out), b = nlohmann::json::parse(deg.out);
  EXPECT_FALSE(a.contains("units"));
  EXPECT_EQ(b["units"]["angle"], "deg");
  const double k = 180.0 / M_PI;
  ASSERT_EQ(a["branches"].size(), b["branches"].size());
  for (std::size_t i = 0; i < a["branches"].size(); ++i) {
    const nlohmann::json &x = a["branches"][i], &y = b["branches"][i];
    for (std::size_t j = 0; j < x["parameters"].size(); ++j) {
      const bool angle = x["parameters"][j]["kind"] == "angle";
      const double f = angle ? k : 1.0;
      for (const char* bound : {"min", "max"})
        EXPECT_NEAR(y["parameters"][j][bound].get<double>(),
                    x["parameters"][j][bound].get<double>() * f, 1e-9);
      EXPECT_NEAR(y["nearest"]["parameters"][j].get<double>(),
                  x["nearest"]["parameters"][j].get<double>() * f, 1e-9);
      for (std::size_t s = 0; s < 2; ++s)
        EXPECT_NEAR(y["samples"][s]["parameters"][j].get<double>(),
                    x["samples"][s]["parameters"][j].get<double>() * f, 1e-9);
      // a turn's rate: per degree of an angle parameter as per radian (1), per length unit in
      // degrees
      const nlohmann::json &mx = x["parameters"][j]["motion"], &my = y["parameters"][j]["motion"];
      const double rate_f = (mx["type"] == "rotation" ? k : 1.0) / f;
      EXPECT_NEAR(my["rate"].get<double>(), mx["rate"].get<double>() * rate_f, 1e-9);
    }
    EXPECT_EQ(x["nearest"]["position"], y["nearest"]["position"]);
    EXPECT_EQ(x["nearest"]["orientation"], y["nearest"]["orientation"]);
    EXPECT_EQ(x["nearest"]["distance"], y["nearest"]["distance"]);
  }
  CmdResult bad = run("solve " + spec + " --angles grad");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--angles: expected deg or rad, got 'grad'"), std::string::npos) << bad.err;
  // the batch's lines too
  CmdResult lines = run("batch " RELPOS_DATA_DIR "/scenarios --angles deg --jobs 1");
  ASSERT_EQ(lines.code, 0) << lines.err;
  EXPECT_EQ(nlohmann::json::parse(lines.out.substr(0, lines.out.find('\n')))["units"]["angle"],
            "deg");
}

// Issue 17: relpos export --format tsr writes a chain per branch (checked pose by pose in
// tests/report/tsr_test.cpp), or null with the reason.
TEST(Cli, ExportWritesTsrChains) {
  fs::path d = scratchDir();
  const std::string out = (d / "tsr.json").string();
  CmdResult r = run("export " RELPOS_DATA_DIR "/scenarios/scenario-d-soda-can-grasp.json "
                    "--format tsr -o " + out);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json doc = nlohmann::json::parse(slurp(out));
  EXPECT_EQ(doc["format"], "tsr");
  EXPECT_EQ(doc["status"], "solved");
  ASSERT_EQ(doc["branches"].size(), 2u);
  for (const auto& b : doc["branches"]) {
    ASSERT_TRUE(b["exact"].get<bool>()) << b.dump();
    for (const auto& link : b["tsr_chain"]) {
      EXPECT_EQ(link["T0_w"].size(), 4u);
      EXPECT_EQ(link["Tw_e"][3], nlohmann::json({0.0, 0.0, 0.0, 1.0}));
      ASSERT_EQ(link["Bw"].size(), 6u);
      for (const auto& row : link["Bw"]) EXPECT_LE(row[0].get<double>(), row[1].get<double>());
    }
  }
  // A branch without a chain (a second angle that follows the first nonlinearly) says why.
  CmdResult c = run("export " RELPOS_DATA_DIR "/examples/two-angles.json --format tsr");
  ASSERT_EQ(c.code, 0) << c.err;
  const nlohmann::json cdoc = nlohmann::json::parse(c.out);
  EXPECT_TRUE(cdoc["branches"][0]["tsr_chain"].is_null());
  EXPECT_FALSE(cdoc["branches"][0]["why"].get<std::string>().empty());
  CmdResult bad = run("export " RELPOS_DATA_DIR "/scenarios/scenario-c-cylinder-grasp.json --format urdf");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--format: expected tsr or moveit, got 'urdf'"), std::string::npos)
      << bad.err;
  // MoveIt goal constraints (checked pose by pose in tests/report/moveit_test.cpp): a part at a
  // distance from a plane turns freely about the plane's normal.
  CmdResult m = run("export " RELPOS_DATA_DIR "/scenarios/scenario-a-plane-distance.json "
                    "--format moveit");
  ASSERT_EQ(m.code, 0) << m.err;
  const nlohmann::json goal = nlohmann::json::parse(m.out)["branches"][0];
  EXPECT_TRUE(goal["exact"].get<bool>());
  const nlohmann::json& pc = goal["constraints"]["position_constraints"][0];
  EXPECT_EQ(pc["constraint_region"]["primitives"][0]["type"], 1);
  EXPECT_EQ(pc["header"]["frame_id"], "world");
  const nlohmann::json& oc = goal["constraints"]["orientation_constraints"][0];
  double widest = 0;
  for (const char* axis : {"x", "y", "z"})
    widest = std::max(widest, oc[std::string("absolute_") + axis + "_axis_tolerance"].get<double>());
  EXPECT_NEAR(widest, M_PI, 1e-9);
}

// Issue 17: the man page and the bash completion come from the help's own tables.
TEST(Cli, ManPageAndBashCompletionFollowTheHelp) {
  CmdResult man = run("help --man");
  ASSERT_EQ(man.code, 0) << man.err;
  EXPECT_EQ(man.out.rfind(".\\\" -*- coding: utf-8 -*-\n.TH RELPOS 1 ", 0), 0u)
      << man.out.substr(0, 80);
  for (const char* command : {"solve", "batch", "table", "rules", "export"}) {
    EXPECT_NE(man.out.find(std::string(".SS ") + command + "\n"), std::string::npos) << command;
    // every option of the command's help is in the page, its hyphens as roff's minus signs
    CmdResult help = run(std::string("help ") + command);
    std::istringstream lines(help.out);
    for (std::string line; std::getline(lines, line);) {
      if (line.rfind("  --", 0) != 0) continue;
      std::string flag = line.substr(2, line.find(' ', 2) - 2), escaped;
      for (char c : flag) escaped += c == '-' ? std::string("\\-") : std::string(1, c);
      EXPECT_NE(man.out.find(".B " + escaped), std::string::npos) << command << " " << flag;
    }
  }
  CmdResult script = run("help --bash-completion");
  ASSERT_EQ(script.code, 0) << script.err;
  fs::path d = scratchDir();
  std::ofstream(d / "relpos.bash") << script.out;
  // What bash offers: commands after "relpos so", solve's options after "--an", the units after
  // "--angles".
  const std::string complete =
      "bash -c 'source " + (d / "relpos.bash").string() +
      "; COMP_WORDS=(relpos so); COMP_CWORD=1; _relpos; echo \"${COMPREPLY[*]}\";"
      " COMP_WORDS=(relpos solve x.json --an); COMP_CWORD=3; _relpos; echo \"${COMPREPLY[*]}\";"
      " COMP_WORDS=(relpos solve x.json --angles \"\"); COMP_CWORD=4; _relpos;"
      " echo \"${COMPREPLY[*]}\"; COMP_WORDS=(relpos help ex); COMP_CWORD=2; _relpos;"
      " echo \"${COMPREPLY[*]}\"'";
  CmdResult offered = runShell(complete);
  ASSERT_EQ(offered.code, 0) << offered.err;
  EXPECT_EQ(offered.out, "solve\n--angles\ndeg rad\nexport\n");
}

TEST(Cli, SameSeedSameSamples) {
  CmdResult a = run("solve " + kExample + " --samples 4 --seed 9");
  CmdResult b = run("solve " + kExample + " --samples 4 --seed 9");
  auto strip = [](std::string s) {
    nlohmann::json j = nlohmann::json::parse(s);
    j.erase("stats");
    return j.dump();
  };
  EXPECT_EQ(strip(a.out), strip(b.out));
}

TEST(Cli, OutputFileAndNoPartialFileOnBadInput) {
  fs::path out = scratchDir() / "result.json";
  fs::remove(out);
  CmdResult ok = run("solve " + kExample + " -o " + out.string());
  ASSERT_EQ(ok.code, 0) << ok.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(out))["status"], "solved");
  fs::remove(out);
  fs::path bad = writeSpec("bad.json", R"({"relpos": 1, "fixed": {"features": {}},
      "mobile": {"name": "gripper", "features": {"tcp": {"point": [0, 0, 0]}}},
      "constraints": [{"type": "coincident", "fixed": "tcp", "mobile": "tcp2"}]})");
  CmdResult r = run("solve " + bad.string() + " -o " + out.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_NE(r.err.find(bad.string() + ": constraints[0].mobile: no feature 'tcp2' on mobile "
                                      "object 'gripper' (it has: tcp)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("constraints[0].fixed: no feature 'tcp' on fixed object"), std::string::npos)
      << r.err;
}

TEST(Cli, MalformedJsonAndMissingFile) {
  fs::path bad = writeSpec("broken.json", "{\n \"relpos\": 1,\n \"fixed\": [}\n");
  CmdResult r = run("solve " + bad.string());
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("broken.json: malformed JSON at line 3"), std::string::npos) << r.err;
  CmdResult m = run("solve /nonexistent/spec.json");
  EXPECT_EQ(m.code, 2);
  EXPECT_NE(m.err.find("/nonexistent/spec.json: cannot read the file"), std::string::npos) << m.err;
}

TEST(Cli, UsageErrors) {
  EXPECT_EQ(run("").code, 2);
  EXPECT_EQ(run("frobnicate").code, 2);
  EXPECT_EQ(run("solve " + kExample + " --samples -3").code, 2);
  EXPECT_EQ(run("solve " + kExample + " --bogus").code, 2);
  EXPECT_EQ(run("solve").code, 2);
}

// Help from any command, and the version, are answers (exit 0 on stdout), not usage errors.
TEST(Cli, HelpAndVersion) {
  for (const char* args : {"--help", "-h", "help"}) {
    const CmdResult r = run(args);
    EXPECT_EQ(r.code, 0) << args << ": " << r.err;
    EXPECT_NE(r.out.find("relpos solve SPEC.json"), std::string::npos) << args;
    EXPECT_NE(r.out.find("relpos help COMMAND"), std::string::npos) << args;
    EXPECT_EQ(r.err, "") << args;
  }
  const CmdResult unknown = run("help frobnicate");
  EXPECT_EQ(unknown.code, 2);
  EXPECT_NE(unknown.err.find("usage:"), std::string::npos) << unknown.err;
  const CmdResult v = run("--version");
  EXPECT_EQ(v.code, 0) << v.err;
  // "relpos MAJOR.MINOR.PATCH (plugin ABI N)"
  EXPECT_EQ(v.out.rfind("relpos ", 0), 0u) << v.out;
  EXPECT_NE(v.out.find("(plugin ABI "), std::string::npos) << v.out;
  EXPECT_EQ(std::count(v.out.begin(), v.out.end(), '\n'), 1) << v.out;
  EXPECT_GE(std::count(v.out.begin(), v.out.end(), '.'), 2) << v.out;
}

// `relpos help CMD` and `relpos CMD --help` are the same answer: that command's synopsis and a
// line for each of its options (and the common ones), exit 0, nothing on stderr.
TEST(Cli, EachCommandDescribesEachOfItsOptions) {
  const std::pair<const char*, std::vector<const char*>> commands[] = {
      {"solve",
       {"--samples N", "--window W", "--seed S", "-o OUT.json", "--collision", "--clearance C",
        "--collision-samples N"}},
      {"batch", {"--jobs N", "-o OUT.jsonl", "--samples N", "--collision"}},
      {"table", {"--repeat N", "--collision"}},
      {"rules", {"--coverage"}},
  };
  for (const auto& [name, options] : commands) {
    const std::string cmd = name;
    const CmdResult help = run("help " + cmd);
    const CmdResult flag = run(cmd + " --help");
    EXPECT_EQ(help.code, 0) << cmd << ": " << help.err;
    EXPECT_EQ(flag.code, 0) << cmd << ": " << flag.err;
    EXPECT_EQ(help.out, flag.out) << cmd;
    EXPECT_EQ(help.err, "") << cmd;
    EXPECT_EQ(help.out.rfind("usage: relpos " + cmd, 0), 0u) << help.out;
    for (const std::string option : options) {
      // The option starts a line of the options list, followed by its description.
      const std::size_t at = help.out.find("\n  " + option + " ");
      ASSERT_NE(at, std::string::npos) << cmd << " lacks " << option << ":\n" << help.out;
      const std::size_t end = help.out.find('\n', at + 1);
      EXPECT_GT(end - at, option.size() + 12) << cmd << " " << option << ": no description";
    }
    for (const char* common : {"--plugin LIB.so", "--allow-override"})
      EXPECT_NE(help.out.find(common), std::string::npos) << cmd;
    for (std::size_t at = 0, end; at < help.out.size(); at = end + 1) {
      end = std::min(help.out.find('\n', at), help.out.size());
      EXPECT_LE(end - at, 100u) << cmd << ": a line longer than 100 columns";
    }
  }
}

TEST(Cli, RulesListsTypesRulesAndManifolds) {
  CmdResult r = run("rules");
  ASSERT_EQ(r.code, 0);
  for (const char* s : {"distance", "tangent", "pp+pp/circle", "PMF App. IV Table VII",
                        "rotation/TwoAngle", "translation/Ellipse", "built-in"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s;
}

TEST(Cli, TableOfExamples) {
  CmdResult r = run("table " RELPOS_DATA_DIR "/examples --repeat 3");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("pmf-simple-example"), std::string::npos);
  EXPECT_NE(r.out.find(" 0 invalid"), std::string::npos);
}

TEST(Cli, ApiExampleRuns) {
  fs::path d = scratchDir();
  int status = std::system((std::string(RELPOS_API_EXAMPLE) + " >" + (d / "out").string()).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  std::string out = slurp(d / "out");
  EXPECT_NE(out.find("rotation OneParallel, translation Point, 1 DOF"), std::string::npos) << out;
  EXPECT_NE(out.find("pose(phi=0): translation [5, "), std::string::npos) << out;
}

}  // namespace

namespace {

// README code snippets are copies of compiled examples (STYLE.md §14): the README's C++ block is
// exactly examples/api_example.cpp.
TEST(Readme, ApiSnippetIsTheCompiledExample) {
  const std::string readme = slurp(RELPOS_DATA_DIR "/../README.md");
  const std::string code = slurp(RELPOS_DATA_DIR "/../examples/api_example.cpp");
  ASSERT_FALSE(code.empty());
  EXPECT_NE(readme.find("```cpp\n" + code + "```"), std::string::npos);
}

TEST(Readme, StartsWithTheTwoCommands) {
  const std::string readme = slurp(RELPOS_DATA_DIR "/../README.md");
  const auto block = readme.find("```sh\n");
  ASSERT_NE(block, std::string::npos);
  const auto end = readme.find("```", block + 6);
  const std::string cmds = readme.substr(block + 6, end - block - 6);
  EXPECT_EQ(cmds.find("./scripts/run_examples.sh"), 0u) << cmds;
  EXPECT_NE(cmds.find("\n./scripts/run_tests.sh"), std::string::npos) << cmds;
  EXPECT_EQ(std::count(cmds.begin(), cmds.end(), '\n'), 2) << cmds;
}

}  // namespace

namespace {

TEST(Cli, RuleCoverageOverTheBundledProblems) {
  CmdResult r = run("rules --coverage " RELPOS_DATA_DIR "/rules " RELPOS_DATA_DIR "/examples");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("0 rule cases never fired"), std::string::npos) << r.out;
  CmdResult some = run("rules --coverage " RELPOS_DATA_DIR "/examples/pmf-simple-example.json");
  ASSERT_EQ(some.code, 0);
  EXPECT_NE(some.out.find("1 specs solved"), std::string::npos) << some.out;
  EXPECT_NE(some.out.find("never fired: "), std::string::npos);
}

}  // namespace

namespace {

const std::string kPluginDir = RELPOS_PLUGIN_DIR;

TEST(CliPlugins, ASpecNeedingAPluginFailsWithoutIt) {
  CmdResult r = run("solve " RELPOS_DATA_DIR "/plugins/symmetric-centred-grasp.json");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("symmetric-centred-grasp.json: constraints[0].type: unknown constraint "
                       "type 'symmetric' (load the plugin that provides it)"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST(CliPlugins, PluginFlagLoadsItAndRulesShowItsOrigin) {
  CmdResult r = run("solve " RELPOS_DATA_DIR "/plugins/symmetric-centred-grasp.json --plugin " +
                    kPluginDir + "/relpos-symmetric.so");
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "solved");
  EXPECT_EQ(j["rules"], nlohmann::json({"shell-cut:pp+pplane/annulus"}));
  CmdResult rules = run("rules --plugin " + kPluginDir + "/relpos-helical.so");
  ASSERT_EQ(rules.code, 0) << rules.err;
  const std::string origin = "[" + fs::canonical(kPluginDir + "/relpos-helical.so").string() + "]";
  for (const char* item : {"  thread  ", "  Helical  ", "  helical  "})
    EXPECT_NE(rules.out.find(item + origin), std::string::npos) << item << "\n" << rules.out;
  EXPECT_NE(rules.out.find("  distance  [built-in]"), std::string::npos);
}

// Issue 17: a plugin named without its path is the one beside relpos (here the build tree's).
TEST(CliPlugins, APluginIsFoundByItsName) {
  const std::string origin = "[" + fs::canonical(kPluginDir + "/relpos-helical.so").string() + "]";
  for (const char* name : {"helical", "relpos-helical", "relpos-helical.so"}) {
    CmdResult rules = run(std::string("rules --plugin ") + name);
    ASSERT_EQ(rules.code, 0) << name << ": " << rules.err;
    EXPECT_NE(rules.out.find("  thread  " + origin), std::string::npos) << name;
  }
  // A spec's list by name too (not a file beside the spec).
  fs::path d = scratchDir();
  std::string spec = slurp(RELPOS_DATA_DIR "/plugins/symmetric-centred-grasp.json");
  spec.insert(spec.find('{') + 1, R"("plugins": ["symmetric"], )");
  std::ofstream(d / "named.json") << spec;
  CmdResult r = run("solve " + (d / "named.json").string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["status"], "solved");
  // A path with a folder names that file only: a stale one does not load the build's plugin.
  CmdResult stale = run("rules --plugin /nonexistent/relpos-helical.so");
  EXPECT_EQ(stale.code, 2);
  EXPECT_NE(stale.err.find("/nonexistent/relpos-helical.so: no such plugin file"), std::string::npos)
      << stale.err;
  EXPECT_EQ(stale.err.find("nor is"), std::string::npos) << stale.err;
  // Neither a file nor a name: where it was looked for.
  CmdResult none = run("rules --plugin nonesuch");
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("relpos: nonesuch: no such plugin file (nor is nonesuch, nonesuch.so or "
                          "relpos-nonesuch.so in " +
                          fs::canonical(kPluginDir).string() + ")"),
            std::string::npos)
      << none.err;
}

// Issue 17: a plugin's parameter says what it moves too — the thread's turn is a screw about
// the hole's axis advancing the spec's pitch per turn.
TEST(CliPlugins, APluginsParameterIsAScrewAlongItsAxis) {
  CmdResult r = run("solve " RELPOS_DATA_DIR "/plugins/helical-screw-insertion.json --plugin helical");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json motion = nlohmann::json::parse(r.out)["branches"][0]["parameters"][0]["motion"];
  EXPECT_EQ(motion["type"], "screw");
  EXPECT_NEAR(std::abs(motion["axis"][2].get<double>()), 1.0, 1e-9);
  EXPECT_NEAR(motion["point"][0].get<double>(), 0.2, 1e-9);  // the hole's axis, x = 0.2, y = 0.1
  EXPECT_NEAR(motion["point"][1].get<double>(), 0.1, 1e-9);
  // 1.25 mm per turn, and the screw advances into the hole (direction 0 0 -1) as it turns
  EXPECT_NEAR(std::abs(motion["pitch"].get<double>()), 0.00125 / (2 * M_PI), 1e-12);
}

TEST(CliPlugins, EnvironmentPathLoadsAFolder) {
  fs::path d = scratchDir();
  std::string cmd = "RELPOS_PLUGIN_PATH=/nonexistent-dir-is-skipped-not:" + kPluginDir + " " +
                    RELPOS_EXE + " table " RELPOS_DATA_DIR "/plugins >" + (d / "out").string() +
                    " 2>" + (d / "err").string();
  int status = std::system(cmd.c_str());
  // The missing entry is reported as a missing plugin file: exit 2, one line.
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_NE(slurp(d / "err").find("RELPOS_PLUGIN_PATH: /nonexistent-dir-is-skipped-not: no such "
                                  "plugin file"),
            std::string::npos)
      << slurp(d / "err");
  cmd = "RELPOS_PLUGIN_PATH=" + kPluginDir + " " + RELPOS_EXE +
        " table " RELPOS_DATA_DIR "/plugins >" + (d / "out").string() + " 2>" +
        (d / "err").string();
  status = std::system(cmd.c_str());
  ASSERT_EQ(WEXITSTATUS(status), 0) << slurp(d / "err");
  EXPECT_NE(slurp(d / "out").find("2 specs, 0 invalid"), std::string::npos) << slurp(d / "out");
}

TEST(CliPlugins, SpecPluginListIsRelativeToTheSpec) {
  fs::path d = scratchDir();
  fs::copy_file(kPluginDir + "/relpos-helical.so", d / "relpos-helical.so",
                fs::copy_options::overwrite_existing);
  std::string spec = slurp(RELPOS_DATA_DIR "/plugins/helical-screw-insertion.json");
  spec.insert(spec.find("\"fixed\""), "\"plugins\": [\"relpos-helical.so\"],\n  ");
  fs::path file = writeSpec("with-plugin.json", spec);
  CmdResult r = run("solve " + file.string());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["branches"][0]["dof"], 1);
}

TEST(CliPlugins, EveryBadPluginIsOneLineAndExitTwo) {
  const fs::path text = writeSpec("not-a-library.so", "plain text\n");
  for (const std::string& bad :
       {text.string(), std::string(RELPOS_BAD_PLUGIN_DIR "/bad-no-entry.so"),
        std::string(RELPOS_BAD_PLUGIN_DIR "/bad-wrong-abi.so"),
        std::string(RELPOS_BAD_PLUGIN_DIR "/bad-throws.so"),
        std::string(RELPOS_BAD_PLUGIN_DIR "/bad-duplicate.so")}) {
    for (const std::string& cmd :
         {std::string("rules"), "solve " + kExample, "table " + kExample}) {
      CmdResult r = run(cmd + " --plugin " + bad);
      EXPECT_EQ(r.code, 2) << cmd << " " << bad;
      EXPECT_EQ(r.err.rfind("relpos: " + bad + ": ", 0), 0u) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_TRUE(r.out.empty()) << r.out;
    }
  }
  CmdResult ok = run("rules --allow-override --plugin " RELPOS_BAD_PLUGIN_DIR "/bad-duplicate.so");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_NE(ok.out.find("distance  [" +
                        fs::canonical(RELPOS_BAD_PLUGIN_DIR "/bad-duplicate.so").string() +
                        "]  a plugin's replacement"),
            std::string::npos)
      << ok.out;
}

}  // namespace

namespace {

const std::string kPartOnTable = RELPOS_DATA_DIR "/collision/part-on-table-beside-wall.json";

TEST(CliCollision, SolveWritesTheCollisionFields) {
  CmdResult r = run("solve " + kPartOnTable + " --collision --collision-samples 10 --seed 4");
  ASSERT_EQ(r.code, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["collision_free_branches"], 1);
  const auto& c = j["branches"][0]["collision"];
  EXPECT_EQ(c["checked_against"], nlohmann::json({"table", "wall"}));
  EXPECT_EQ(c["clearance"], 0.0);
  EXPECT_EQ(c["nearest_collides"], true);
  ASSERT_EQ(c["nearest_contacts"].size(), 1u);
  EXPECT_EQ(c["nearest_contacts"][0]["object"], "wall");
  EXPECT_GT(c["nearest_contacts"][0]["depth"].get<double>(), 0.0);
  EXPECT_NEAR(c["nearest_free"]["position"][0].get<double>(), 0.38, 1e-6);
  EXPECT_EQ(c["free_samples"].size() + c["blocked_samples"].get<std::size_t>(), 10u);
  // Without --collision: none of these fields.
  CmdResult plain = run("solve " + kPartOnTable);
  nlohmann::json p = nlohmann::json::parse(plain.out);
  EXPECT_FALSE(p.contains("collision_free_branches"));
  EXPECT_FALSE(p["branches"][0].contains("collision"));
}

TEST(CliCollision, ClearanceWithoutCollisionIsAUsageError) {
  // Every command that filters collisions: table accepted and ignored them (docs/spec.md §3).
  for (const std::string cmd : {"solve ", "table ", "batch "}) {
    for (const std::string option : {" --clearance 0.01", " --collision-samples 3"}) {
      SCOPED_TRACE(cmd + option);
      CmdResult r = run(cmd + kPartOnTable + option);
      EXPECT_EQ(r.code, 2);
      EXPECT_NE(r.err.find("--clearance and --collision-samples need --collision"),
                std::string::npos);
    }
  }
}

TEST(CliCollision, BadMeshesAreExitTwoWithTheirJsonPath) {
  fs::path d = scratchDir();
  std::ofstream(d / "garbage.off") << "not a mesh\n";
  std::ofstream(d / "empty.off") << "OFF\n0 0 0\n";
  std::ofstream(d / "quads.off") << "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  const std::string spec = slurp(kPartOnTable);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"missing.off", "mesh file not found"},
      {"garbage.off", "unreadable mesh"},
      {"empty.off", "empty mesh"},
      {"quads.off", "not a triangle mesh"}};
  for (const auto& [mesh, reason] : cases) {
    std::string s = spec;
    s.replace(s.find("meshes/part.off"), std::string("meshes/part.off").size(), mesh);
    const fs::path file = d / ("bad-" + mesh + ".json");
    std::ofstream(file) << s;
    CmdResult r = run("solve " + file.string() + " --collision");
    EXPECT_EQ(r.code, 2) << mesh;
    EXPECT_NE(r.err.find(file.string() + ": mobile.mesh: " + reason), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty());
  }
  // No mesh on the mobile object at all.
  std::string s = spec;
  s.replace(s.find("\"mesh\": \"meshes/part.off\","),
            std::string("\"mesh\": \"meshes/part.off\",").size(), "");
  const fs::path file = d / "no-mobile-mesh.json";
  std::ofstream(file) << s;
  CmdResult r = run("solve " + file.string() + " --collision");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("mobile.mesh: collision filtering needs a mesh for the mobile object"),
            std::string::npos)
      << r.err;
}

}  // namespace

namespace {

// Result lines without their timings (the only field that may differ between runs).
std::vector<nlohmann::json> resultLines(const std::string& text) {
  std::vector<nlohmann::json> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    nlohmann::json j = nlohmann::json::parse(line);
    j.erase("stats");
    lines.push_back(j);
  }
  return lines;
}

TEST(CliBatch, OrderAndResultsDoNotDependOnTheThreadCount) {
  for (const std::string& input : {std::string(RELPOS_DATA_DIR "/examples"), kBatchSample}) {
    CmdResult one = run("batch " + input + " --jobs 1");
    CmdResult four = run("batch " + input + " --jobs 4");
    ASSERT_EQ(one.code, 0) << one.err;
    ASSERT_EQ(four.code, 0) << four.err;
    const auto a = resultLines(one.out), b = resultLines(four.out);
    ASSERT_GT(a.size(), 60u);
    EXPECT_EQ(a, b) << input;
    EXPECT_NE(one.err.find("batch: " + std::to_string(a.size()) + " specs"), std::string::npos)
        << one.err;
  }
  // Folder order is name order; JSONL order is line order.
  const auto lines = resultLines(run("batch " + kBatchSample + " --jobs 3").out);
  ASSERT_EQ(lines.size(), 100u);
  std::istringstream in(slurp(kBatchSample));
  std::string spec;
  for (std::size_t i = 0; std::getline(in, spec); ++i)
    EXPECT_EQ(lines[i]["name"], nlohmann::json::parse(spec)["name"]) << i;
}

TEST(CliBatch, EachLineIsWhatSolveWrites) {
  fs::path d = scratchDir();
  const auto lines =
      resultLines(run("batch " RELPOS_DATA_DIR "/examples --samples 2 --seed 9").out);
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(RELPOS_DATA_DIR "/examples"))
    files.push_back(e.path());
  std::sort(files.begin(), files.end());
  ASSERT_EQ(files.size(), lines.size());
  for (std::size_t i = 0; i < files.size(); i += 7) {
    CmdResult s = run("solve " + files[i] + " --samples 2 --seed 9");
    nlohmann::json j = nlohmann::json::parse(s.out);
    j.erase("stats");
    EXPECT_EQ(j, lines[i]) << files[i];
  }
}

TEST(CliBatch, InvalidSpecsBecomeLinesAndTheBatchGoesOn) {
  const std::string good = slurp(RELPOS_DATA_DIR "/examples/pmf-simple-example.json");
  std::string compact = nlohmann::json::parse(good).dump();
  std::string unknown = compact;
  unknown.replace(unknown.find("\"coincident\""), 12, "\"welded\"");
  const fs::path file =
      writeSpec("mixed.jsonl", compact + "\n{not json\n\n" + unknown + "\n" + compact + "\n");
  CmdResult r = run("batch " + file.string() + " --jobs 2");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = resultLines(r.out);
  ASSERT_EQ(lines.size(), 4u);  // the blank line is no spec
  EXPECT_EQ(lines[0]["status"], "solved");
  EXPECT_EQ(lines[1]["status"], "invalid");
  EXPECT_EQ(lines[1]["name"], "mixed:2");
  EXPECT_NE(lines[1]["message"].get<std::string>().find(file.string() + ":2: malformed JSON"),
            std::string::npos)
      << lines[1];
  EXPECT_EQ(lines[2]["status"], "invalid");
  EXPECT_EQ(lines[2]["name"], "pmf-simple-example");
  EXPECT_NE(lines[2]["message"].get<std::string>().find(
                file.string() + ":4: constraints[0].type: unknown constraint type 'welded'"),
            std::string::npos)
      << lines[2];
  EXPECT_EQ(lines[3]["status"], "solved");
  EXPECT_NE(r.err.find("invalid 2"), std::string::npos) << r.err;
}

TEST(CliBatch, EmptyInputAndNonSpecFiles) {
  CmdResult empty = run("batch " + writeSpec("empty.jsonl", "").string());
  EXPECT_EQ(empty.code, 0) << empty.err;
  EXPECT_TRUE(empty.out.empty());
  EXPECT_NE(empty.err.find("batch: 0 specs"), std::string::npos) << empty.err;
  fs::path d = scratchDir() / "folder";
  fs::create_directories(d);
  fs::copy_file(RELPOS_DATA_DIR "/examples/pmf-simple-example.json", d / "a.json",
                fs::copy_options::overwrite_existing);
  std::ofstream(d / "notes.txt") << "not a spec";
  std::ofstream(d / "b.json") << "{\"relpos\": 1}";
  CmdResult r = run("batch " + d.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = resultLines(r.out);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0]["status"], "solved");
  EXPECT_EQ(lines[1]["status"], "invalid");
  EXPECT_EQ(lines[1]["name"], "b");
}

TEST(CliBatch, InterruptLeavesCompleteLinesInOrder) {
  fs::path d = scratchDir();
  const std::string input = (d / "many.jsonl").string(), out = (d / "out.jsonl").string();
  std::string many;
  const std::string sample = slurp(kBatchSample);
  for (int k = 0; k < 300; ++k) many += sample;  // 30,000 specs
  std::ofstream(input) << many;
  // Ctrl-C as soon as the first results are on disk (a fixed delay would race a fast batch).
  const std::string cmd = std::string(RELPOS_EXE) + " batch " + input + " --jobs 2 -o " + out +
                          " 2>" + (d / "err").string() + " & pid=$!; while [ ! -s " + out +
                          " ]; do sleep 0.001; done; kill -INT $pid; wait $pid";
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(WEXITSTATUS(status), 130) << slurp(d / "err");
  const std::string text = slurp(out);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const auto lines = resultLines(text);
  EXPECT_LT(lines.size(), 30000u);
  std::istringstream in(many);
  std::string spec;
  for (std::size_t i = 0; i < lines.size() && std::getline(in, spec); ++i)
    ASSERT_EQ(lines[i]["name"], nlohmann::json::parse(spec)["name"]) << i;
  EXPECT_NE(slurp(d / "err").find("before the interruption"), std::string::npos);
}

}  // namespace

namespace {

TEST(CliBatch, CollisionOptionsApplyToEveryLine) {
  CmdResult r =
      run("batch " RELPOS_DATA_DIR "/collision --collision --collision-samples 8 --jobs 2");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = resultLines(r.out);
  ASSERT_EQ(lines.size(), 3u);
  for (const auto& j : lines) {
    ASSERT_TRUE(j.contains("collision_free_branches")) << j["name"];
    for (const auto& b : j["branches"]) {
      ASSERT_TRUE(b.contains("collision"));
      const std::size_t n = b["collision"]["free_samples"].size() +
                            b["collision"]["blocked_samples"].get<std::size_t>();
      EXPECT_EQ(n, b["dof"] == 0 ? 1u : 8u) << j["name"];
    }
  }
  // The same as solving each alone.
  CmdResult one =
      run("solve " RELPOS_DATA_DIR
          "/collision/part-on-table-beside-wall.json --collision --collision-samples 8");
  nlohmann::json j = nlohmann::json::parse(one.out);
  j.erase("stats");
  EXPECT_EQ(j, lines[1]);
}

}  // namespace

namespace {

TEST(CliPlugins, BatchLinesLoadTheirPluginLists) {
  fs::path d = scratchDir();
  fs::copy_file(std::string(RELPOS_PLUGIN_DIR) + "/relpos-helical.so", d / "relpos-helical.so",
                fs::copy_options::overwrite_existing);
  nlohmann::json spec =
      nlohmann::json::parse(slurp(RELPOS_DATA_DIR "/plugins/helical-screw-insertion.json"));
  spec["plugins"] = {"relpos-helical.so"};
  const fs::path file = writeSpec("with-plugins.jsonl", spec.dump() + "\n" + spec.dump() + "\n");
  CmdResult r = run("batch " + file.string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto lines = resultLines(r.out);
  ASSERT_EQ(lines.size(), 2u);
  for (const auto& j : lines) EXPECT_EQ(j["status"], "solved") << j;
}

}  // namespace

namespace {

TEST(CliCollision, TableCountsCollisionFreeBranches) {
  CmdResult r = run("table " RELPOS_DATA_DIR "/collision --collision --repeat 3");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("free branches"), std::string::npos) << r.out;
  // The arm's second solution runs into the block: 1 of its 2 branches is free.
  std::istringstream in(r.out);
  std::string line;
  std::map<std::string, std::string> last_column;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::vector<std::string> w{std::istream_iterator<std::string>(words), {}};
    if (w.size() == 6) last_column[w[0]] = w[5];
  }
  EXPECT_EQ(last_column["arm-either-side"], "1");
  EXPECT_EQ(last_column["part-on-table-beside-wall"], "1");
  EXPECT_EQ(last_column["soda-can-grasp-collision"], "2");
}

}  // namespace
