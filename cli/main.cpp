// The relpos command (docs/spec.md §3): finds the command, loads the plugins, runs it. The commands
// live in commands/, their help in help.cpp.
#include <csignal>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

#include "cli.hpp"
#include "help.hpp"
#include "relpos/builtins/builtins.hpp"
#include "relpos/core/plugin_api.hpp"
#include "relpos/core/registry.hpp"
#include "relpos/io/text.hpp"

using namespace relpos::cli;
using relpos::oneLine;

namespace {

int run(int argc, char** argv) {
  if (argc < 2) throw UsageError("missing command");
  const std::string name = argv[1];
  const Command* command = findCommand(name);
  // Help and version before anything is parsed or loaded: `relpos solve --help` is help, not a
  // usage error about the missing spec.
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "-h") == 0 || std::strcmp(argv[i], "--help") == 0) {
      command && command->reads_plugins ? printHelp(std::cout, *command) : printUsage(std::cout);
      return kExitOk;
    }
  if (name == "help") {
    if (argc == 2) {
      printUsage(std::cout);
      return kExitOk;
    }
    if (argc == 3 && std::strcmp(argv[2], "--man") == 0) {
      printManPage(std::cout, RELPOS_VERSION);
      return kExitOk;
    }
    if (argc == 3 && std::strcmp(argv[2], "--bash-completion") == 0) {
      printBashCompletion(std::cout);
      return kExitOk;
    }
    const Command* about = argc == 3 ? findCommand(argv[2]) : nullptr;
    if (!about) throw UsageError("help: expected one command, e.g. 'relpos help solve'");
    printHelp(std::cout, *about);
    return kExitOk;
  }
  if (name == "--version" || name == "version") {
    std::cout << "relpos " << RELPOS_VERSION << " (plugin ABI " << relpos::kPluginAbiVersion
              << ")\n";
    return kExitOk;
  }
  Args a = parseArgs(argc, argv, 2);
  if (a.out_given && a.out.empty()) throw InvalidInput("-o: an empty path");
  if (a.out_given && name != "solve" && name != "batch" && name != "export" &&
      name != "view")
    throw InvalidInput("-o: '" + name + "' writes to standard output only");
  relpos::Registry reg;
  relpos::registerBuiltins(reg);
  if (!loadPlugins(name, a, reg)) return kExitInvalid;
  reg.freeze();
  if (!command) throw UsageError("unknown command '" + name + "'");
  return command->run(a, reg);
}

}  // namespace

int main(int argc, char** argv) {
  // Past a file size limit (ulimit -f) a write fails with EFBIG and is reported like a full disk,
  // instead of the signal killing the process half-way through a line.
  std::signal(SIGXFSZ, SIG_IGN);
  try {
    return run(argc, argv);
  } catch (const UsageError& e) {
    std::cerr << "relpos: " << oneLine(e.what()) << "\n";
    printUsage(std::cerr);
    return kExitInvalid;
  } catch (const InvalidInput& e) {
    std::cerr << "relpos: " << oneLine(e.what()) << "\n";
    return kExitInvalid;
  } catch (const WriteFailed& e) {
    std::cerr << "relpos: " << oneLine(e.what()) << "\n";
    return kExitInternal;
  } catch (const std::exception& e) {
    std::cerr << "relpos: internal error: " << oneLine(e.what()) << "\n";
    return kExitInternal;
  }
}
