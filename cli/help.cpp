#include "help.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>

namespace relpos::cli {
namespace {

// Options several commands share, spelled once.
constexpr Option kSamples{"--samples N",
                          "also write N poses per branch, drawn uniformly within its parameter "
                          "bounds (\"samples\"; default 0)"};
constexpr Option kWindow{"--window W",
                         "unbounded length parameters are sampled within +-W of the nearest "
                         "pose's (default 1)"};
constexpr Option kSeed{"--seed S", "the seed of the samples' generator (default 0)"};
constexpr Option kAngles{"--angles deg|rad",
                         "write the result's angles (angle parameters, rotation rates) in degrees "
                         "or radians (default rad)"};
constexpr Option kCollision{"--collision",
                            "filter each branch against the meshes (mobile.mesh, fixed.mesh, "
                            "obstacles): adds \"collision\" per branch and "
                            "\"collision_free_branches\""};
constexpr Option kClearance{"--clearance C",
                            "with --collision: closer than C to an object counts as a collision "
                            "(default 0)"};
constexpr Option kCollisionSamples{"--collision-samples N",
                                   "with --collision: poses per branch the filter tests "
                                   "(default 64)"};

int cmdNone(const Args&, const Registry&) { return kExitOk; }

const Command kCommands[] = {
    {"solve",
     "solve SPEC.json [--samples N] [--window W] [--seed S] [--angles deg] [-o OUT.json]\n"
     "               [--collision [--clearance C] [--collision-samples N]]",
     "Solves one spec and prints its result document (docs/spec.md §2), indented.",
     {kSamples,
      kWindow,
      kSeed,
      kAngles,
      {"-o OUT.json", "write the result to OUT.json (replaced whole, only once it is complete)"},
      kCollision,
      kClearance,
      kCollisionSamples},
     cmdSolve,
     true},
    {"rules",
     "rules [--coverage DIR-or-SPEC...]",
     "Lists the registered constraint types, combination rules (with their cases), manifolds and "
     "matchers, built-in and from plugins.",
     {{"--coverage DIR-or-SPEC...",
       "instead, solve the specs (a folder's *.json) and count how often each rule case fired; "
       "lists the cases that never did"}},
     cmdRules,
     true},
    {"table",
     "table DIR-or-SPEC... [--repeat N] [--collision ...]",
     "One row per spec (a folder's *.json in name order): status, branches, their DOF and the "
     "median solve time.",
     {{"--repeat N", "solves per spec for the median time (default 200)"},
      kCollision,
      kClearance,
      kCollisionSamples,
      kWindow,
      kSeed},
     cmdTable,
     true},
    {"batch",
     "batch DIR-or-FILE.jsonl [--jobs N] [-o OUT.jsonl] [solve options]",
     "Solves many specs (a folder's *.json, or one spec per line of a JSONL file) and writes one "
     "result line each, in input order; a summary on stderr.",
     {{"--jobs N", "worker threads (default: one per core)"},
      {"-o OUT.jsonl", "write the lines to OUT.jsonl instead of standard output"},
      kSamples,
      kWindow,
      kSeed,
      kAngles,
      kCollision,
      kClearance,
      kCollisionSamples},
     cmdBatch,
     true},
    {"export",
     "export SPEC.json --format tsr|moveit [--window W] [-o OUT.json]",
     "Writes each branch of a spec's answer as a planner takes it: a Task Space Region chain "
     "(T0_w, Tw_e, Bw per link, as personalrobotics/tsr), or null with the reason; or MoveIt "
     "goal constraints (moveit_msgs/Constraints as JSON), exact or conservative.",
     {{"--format tsr|moveit",
       "tsr: Task Space Region chains; moveit: moveit_msgs/Constraints (JSON, which is YAML)"},
      {"--window W", "unbounded lengths are bounded to +-W about the nearest pose's (default 1)"},
      {"-o OUT.json", "write to OUT.json (replaced whole, only once it is complete)"}},
     cmdExport,
     true},
    {"view",
     "view SPEC.json [-o VIEW.html] [--samples N] [--window W] [--seed S] [--angles deg]\n"
     "               [--collision [--clearance C] [--collision-samples N]]",
     "Writes one self-contained HTML page showing the spec's objects, the mobile object at each "
     "branch's nearest pose, ghosts at samples, and a slider per branch parameter that moves it. "
     "Open it in a browser; it needs no network.",
     {{"-o VIEW.html", "write the page to VIEW.html (default: the spec's file name with .html, "
                       "in the current folder)"},
      {"--samples N", "ghosts per branch, drawn uniformly within its parameter bounds "
                      "(default 12)"},
      {"--window W", "unbounded length parameters slide and are sampled within +-W of the "
                     "nearest pose's (default: the problem's size, its largest coordinate)"},
      kSeed,
      {"--angles deg|rad", "show angles in degrees or radians (default rad)"},
      kCollision,
      kClearance,
      kCollisionSamples},
     cmdView,
     true},
    {"help", "help [COMMAND]", "Prints the usage, or one command's help.", {}, cmdNone, false},
    {"version",
     "--version",
     "Prints relpos's version and its plugin ABI version.",
     {},
     cmdNone,
     false},
};

// What every command accepts.
constexpr Option kCommon[] = {
    {"--plugin LIB.so", "load a plugin first (repeatable; after RELPOS_PLUGIN_PATH)"},
    {"--allow-override", "let a plugin replace a registered name"},
    {"-h, --help", "this help"},
};

// `text` from column `at` on, broken between words before column 100, continued at `indent`.
void wrapped(std::ostream& out, const std::string& text, std::size_t at, std::size_t indent) {
  std::size_t column = at;
  bool line_start = true;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t end = std::min(text.find(' ', i), text.size());
    const std::size_t word = end - i;
    if (!line_start && column + 1 + word > 100) {
      out << "\n" << std::string(indent, ' ');
      column = indent;
      line_start = true;
    }
    if (!line_start) out << ' ', ++column;
    out << text.substr(i, word);
    column += word;
    line_start = false;
    i = end + 1;
  }
  out << "\n";
}

void printOption(std::ostream& out, const Option& o) {
  out << "  " << o.flag;
  const std::size_t width = std::strlen(o.flag);
  if (width < 26)
    out << std::string(26 - width, ' ');
  else
    out << "\n" << std::string(28, ' ');
  wrapped(out, o.what, 28, 28);
}

}  // namespace

const Command* findCommand(const std::string& name) {
  for (const Command& c : kCommands)
    if (name == c.name || (name == "--version" && std::strcmp(c.name, "version") == 0)) return &c;
  return nullptr;
}

void printUsage(std::ostream& out) {
  out << "usage:\n";
  for (const Command& c : kCommands)
    if (std::strcmp(c.name, "help") != 0) out << "  relpos " << c.synopsis << "\n";
  out << "  relpos help COMMAND (or relpos COMMAND --help): each option described\n"
         "every command: [--plugin LIB.so]... [--allow-override] [--help];\n"
         "  RELPOS_PLUGIN_PATH=FILE-or-DIR:...\n";
}

void printHelp(std::ostream& out, const Command& c) {
  out << "usage: relpos " << c.synopsis << "\n\n";
  wrapped(out, c.what, 0, 0);
  if (c.options.size() > 0) {
    out << "\noptions:\n";
    for (const Option& o : c.options) printOption(out, o);
  }
  out << "\nevery command:\n";
  for (const Option& o : kCommon) printOption(out, o);
  out << "  RELPOS_PLUGIN_PATH=FILE-or-DIR:...\n"
      << std::string(28, ' ') << "plugins to load first (a folder: its *.so)\n";
}

namespace {

// Text for roff: a backslash escaped, a leading dot or quote escaped, every hyphen of an option
// (a word that starts with one) a minus sign, so that options can be searched and copied.
std::string roff(const std::string& text) {
  std::string out;
  bool option = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const bool word_start = i == 0 || text[i - 1] == ' ' || text[i - 1] == '[';
    if (word_start) option = c == '-';
    if (c == '\\')
      out += "\\e";
    else if (c == '-' && option)
      out += "\\-";
    else
      out += c;
  }
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out = "\\&" + out;
  return out;
}

// The first word of an option's flag ("--samples N" -> "--samples"; "-h, --help" -> "-h").
std::string flagWord(const Option& o) {
  const std::string f = o.flag;
  return f.substr(0, f.find_first_of(" ,"));
}

}  // namespace

void printManPage(std::ostream& out, const std::string& version) {
  out << ".\\\" -*- coding: utf-8 -*-\n"
      << ".TH RELPOS 1 \"\" \"relpos " << version << "\" \"User Commands\"\n"
      << ".SH NAME\nrelpos \\- every pose of an object that satisfies geometric relations\n"
      << ".SH SYNOPSIS\n";
  for (const Command& c : kCommands) {
    std::string synopsis;  // on one line: the help's continuation indent is for a terminal
    for (const char* p = c.synopsis; *p; ++p)
      if (!(std::isspace(static_cast<unsigned char>(*p)) && !synopsis.empty() &&
            synopsis.back() == ' '))
        synopsis += std::isspace(static_cast<unsigned char>(*p)) ? ' ' : *p;
    out << ".B relpos\n" << roff(synopsis) << "\n.br\n";
  }
  out << ".SH DESCRIPTION\n"
      << "relpos solves relational positioning problems exactly: given a fixed object, a mobile "
         "object and geometric constraints between their features, it returns every pose of the "
         "mobile object that satisfies them, as solution branches. The file formats and results "
         "are specified in docs/spec.md.\n"
      << ".SH COMMANDS\n";
  for (const Command& c : kCommands) {
    out << ".SS " << c.name << "\n" << roff(c.what) << "\n";
    for (const Option& o : c.options)
      out << ".TP\n.B " << roff(o.flag) << "\n" << roff(o.what) << "\n";
  }
  out << ".SH OPTIONS OF EVERY COMMAND\n";
  for (const Option& o : kCommon) out << ".TP\n.B " << roff(o.flag) << "\n" << roff(o.what) << "\n";
  out << ".SH ENVIRONMENT\n.TP\n.B RELPOS_PLUGIN_PATH\n"
      << "Colon-separated plugin files or folders (a folder: its *.so) to load first.\n"
      << ".SH EXIT STATUS\n0 when a result was written (whatever its status), 2 for invalid "
         "input or usage, 1 for an internal failure.\n"
      << ".SH SEE ALSO\ndocs/spec.md, README.md\n";
}

void printBashCompletion(std::ostream& out) {
  out << "# bash completion for relpos (generated by `relpos help --bash-completion`)\n"
      << "_relpos() {\n"
      << "  local cur=\"${COMP_WORDS[COMP_CWORD]}\" cmd=\"${COMP_WORDS[1]}\"\n"
      << "  local prev=\"${COMP_WORDS[COMP_CWORD-1]}\"\n"
      << "  if [ \"$COMP_CWORD\" -eq 1 ]; then\n"
      << "    COMPREPLY=($(compgen -W \"";
  for (const Command& c : kCommands) out << (c.name[0] == 'v' ? "--" : "") << c.name << " ";
  out << "--help\" -- \"$cur\"))\n    return\n  fi\n"
      << "  case \"$prev\" in\n"
      << "    --angles) COMPREPLY=($(compgen -W \"deg rad\" -- \"$cur\")); return ;;\n"
      << "    --format) COMPREPLY=($(compgen -W \"tsr moveit\" -- \"$cur\")); return ;;\n"
      << "    --plugin|-o) mapfile -t COMPREPLY < <(compgen -f -- \"$cur\"); return ;;\n"
      << "  esac\n"
      << "  if [ \"$cmd\" = help ] && [ \"$COMP_CWORD\" -eq 2 ]; then\n"
      << "    COMPREPLY=($(compgen -W \"";
  for (const Command& c : kCommands)
    if (c.name[0] != 'v' && std::strcmp(c.name, "help") != 0) out << c.name << " ";
  out << "\" -- \"$cur\"))\n    return\n  fi\n"
      << "  local opts\n  case \"$cmd\" in\n";
  for (const Command& c : kCommands) {
    out << "    " << c.name << ") opts=\"";
    for (const Option& o : c.options) out << flagWord(o) << " ";
    out << "\" ;;\n";
  }
  out << "  esac\n  opts+=\"";
  for (const Option& o : kCommon) out << flagWord(o) << " ";
  out << "--help\"\n"
      << "  if [[ \"$cur\" == -* ]]; then\n"
      << "    COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\"))\n"
      << "  else\n"
      << "    mapfile -t COMPREPLY < <(compgen -f -- \"$cur\")  # names with spaces whole\n"
      << "  fi\n"
      << "}\n"
      << "complete -o filenames -F _relpos relpos\n";
}

}  // namespace relpos::cli
