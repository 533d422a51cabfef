#pragma once
// The commands relpos knows, and their help: `relpos help [CMD]`, `relpos [CMD] --help`.
#include <ostream>
#include <string>

#include "cli.hpp"

namespace relpos::cli {

struct Option {
  const char* flag;  // with its value, e.g. "--samples N"
  const char* what;
};

struct Command {
  const char* name;
  const char* synopsis;  // the usage line after "relpos "
  const char* what;      // one paragraph
  std::initializer_list<Option> options;
  int (*run)(const Args&, const Registry&);
  bool reads_plugins;  // loads plugins and freezes a registry before it runs
};

// Every command, in the order the usage lists them; nullptr for an unknown name.
const Command* findCommand(const std::string& name);

// The usage of every command (`relpos --help`, and after a usage error).
void printUsage(std::ostream& out);
// One command's help: its synopsis, what it does, each option.
void printHelp(std::ostream& out, const Command& command);
// The same tables as a man page (roff, section 1: `relpos help --man`) and as a bash completion
// script (`relpos help --bash-completion`); the build writes both and installs them.
void printManPage(std::ostream& out, const std::string& version);
void printBashCompletion(std::ostream& out);

}  // namespace relpos::cli
