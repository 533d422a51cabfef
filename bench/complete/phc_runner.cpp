#include "phc_runner.hpp"

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace relpos::bench {
namespace fs = std::filesystem;
namespace {

std::string readFile(const std::string& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeFile(const std::string& f, const std::string& text) { std::ofstream(f) << text; }

// Quotes a path for the shell.
std::string q(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

double timedShell(const std::string& command, int* status) {
  const auto t0 = std::chrono::steady_clock::now();
  *status = std::system(command.c_str());
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// " NAME :  RE  IM" exactly (a word, a colon, two numbers): the value of one unknown. Plain
// stream parsing, not <regex>, whose GCC 12 headers warn (maybe-uninitialized) under -Werror.
bool valueLine(const std::string& line, std::string* name, std::string* re, std::string* im) {
  std::istringstream words(line);
  std::string colon, rest;
  if (!(words >> *name >> colon >> *re >> *im) || colon != ":" || (words >> rest)) return false;
  for (char c : *name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

// "t :  RE  IM" lines set to 0: phc -p starts every path at its solution's t.
std::string resetT(const std::string& text) {
  std::istringstream in(text);
  std::string line, out;
  while (std::getline(in, line)) {
    std::string name, re, im;
    if (valueLine(line, &name, &re, &im) && name == "t")
      line = "t :  0.00000000000000E+00   0.00000000000000E+00";
    out += line + "\n";
  }
  return out;
}

// The last solution list of a PHC file: "THE SOLUTIONS :", "N DIM", then per solution the lines
// " NAME :  RE  IM" for each unknown, in the order of `variables` whatever order PHC prints.
void parseSolutions(const std::string& text, const std::vector<std::string>& variables,
                    PhcRun* run) {
  const std::size_t at = text.rfind("THE SOLUTIONS");
  if (at == std::string::npos) {
    run->error = "no solution list in PHC's output";
    return;
  }
  std::istringstream in(text.substr(at));
  std::string line;
  std::vector<double> re(variables.size()), im(variables.size());
  std::vector<bool> seen(variables.size(), false);
  bool failed = false;  // the block's path failed or diverged ("failure", "no solution")
  auto flush = [&] {
    bool all = !failed, real = true;
    for (std::size_t i = 0; i < variables.size(); ++i) {
      all = all && seen[i];
      real =
          real && std::isfinite(re[i]) && std::abs(im[i]) <= 1e-8 * std::max(1.0, std::abs(re[i]));
    }
    if (all) {
      ++run->solutions;
      if (real) run->real_roots.push_back(re);
    }
    seen.assign(variables.size(), false);
    failed = false;
  };
  while (std::getline(in, line)) {
    if (line.rfind("solution ", 0) == 0) flush();
    // A path's verdict is on its "solution N :" line and its "== err ... ==" line (the summary
    // after the list counts "failures" too, of no solution in particular).
    const bool verdict = line.rfind("solution ", 0) == 0 || line.rfind("==", 0) == 0;
    if (verdict && (line.find("failure") != std::string::npos ||
                    line.find("no solution") != std::string::npos))
      failed = true;
    std::string name, real, imag;
    if (!valueLine(line, &name, &real, &imag)) continue;
    for (std::size_t i = 0; i < variables.size(); ++i)
      if (name == variables[i]) {
        re[i] = std::strtod(real.c_str(), nullptr);
        im[i] = std::strtod(imag.c_str(), nullptr);
        seen[i] = true;
      }
  }
  flush();
}

}  // namespace

std::string findPhc() {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  std::string d;
  while (std::getline(dirs, d, ':')) {
    const fs::path f = fs::path(d) / "phc";
    std::error_code ec;
    if (!d.empty() && fs::is_regular_file(f, ec)) return f.string();
  }
  return "";
}

PhcRun phcBlackbox(const std::string& phc, const std::string& dir, const std::string& name,
                   const PolySystem& target) {
  PhcRun run;
  const std::string in = dir + "/" + name + ".b.phc", out = dir + "/" + name + ".b.out";
  writeFile(in, phcText(target));
  fs::remove(out);
  int status = 0;
  run.seconds = timedShell("cd " + q(dir) + " && " + q(phc) + " -b " + q(in) + " " + q(out) +
                               " > /dev/null 2>&1 < /dev/null",
                           &status);
  run.ran = status == 0;
  if (!run.ran) run.error = "phc -b exited with status " + std::to_string(status);
  parseSolutions(readFile(in), target.variables, &run);
  return run;
}

std::string startSystem(const std::string& phc, const std::string& cache, Family family, int* roots,
                        double* seconds, std::string* error) {
  const std::string cache_dir = fs::absolute(cache).string();  // phc runs in another folder
  const std::string name =
      family == Family::kPointDistances ? "start-point-distances" : "start-line-distances";
  const std::string file = cache_dir + "/" + name + ".phc";
  const PolySystem generic = genericMember(family, 20261202u);
  *seconds = 0.0;
  if (!fs::exists(file)) {
    fs::create_directories(cache_dir);
    const PhcRun run = phcBlackbox(phc, cache_dir, name, generic);
    *seconds = run.seconds;
    if (!run.ran || run.solutions == 0) {
      *error = run.ran ? "phc -b found no root of the generic start system" : run.error;
      return "";
    }
    // phc -p starts every path at its solution's t: the solved start's t = 1 becomes 0.
    writeFile(file, resetT(readFile(cache_dir + "/" + name + ".b.phc")));
  }
  PhcRun listed;
  parseSolutions(readFile(file), generic.variables, &listed);
  *roots = listed.solutions;
  return file;
}

PhcRun phcParameter(const std::string& phc, const std::string& dir, const std::string& name,
                    const PolySystem& target, const std::string& start_file) {
  PhcRun run;
  const std::string in = dir + "/" + name + ".p.phc", out = dir + "/" + name + ".p.out",
                    answers = dir + "/" + name + ".p.answers";
  writeFile(in, phcText(target));
  fs::remove(out);
  // Target file, output file, no separate solution file, start file (system and solutions),
  // then 0 to keep the homotopy settings, 0 the continuation parameters, 0 no intermediate output.
  writeFile(answers, in + "\n" + out + "\nn\n" + start_file + "\n0\n0\n0\n");
  int status = 0;
  run.seconds = timedShell(
      "cd " + q(dir) + " && " + q(phc) + " -p < " + q(answers) + " > /dev/null 2>&1", &status);
  run.ran = status == 0;
  if (!run.ran) run.error = "phc -p exited with status " + std::to_string(status);
  parseSolutions(readFile(out), target.variables, &run);
  return run;
}

}  // namespace relpos::bench
