// ffcompat: the legacy fixed-function lighting pipeline, rendered and compared.
#include <iostream>
#include <string>

#include "cli/common.h"
#include "ffcompat/ffcompat.h"

namespace ffc::cli {
void add_check(CLI::App& app);  // check.cpp
void add_bench(CLI::App& app);  // bench.cpp
void add_report(CLI::App& app);  // report.cpp
void add_stress(CLI::App& app);  // stress.cpp
void add_fuzz(CLI::App& app);    // fuzz.cpp
void add_run(CLI::App& app);     // run.cpp
void add_calls(CLI::App& app);   // calls.cpp
void add_glsl(CLI::App& app);    // glsl.cpp
void add_seeds(CLI::App& app);   // seeds.cpp
}

// Exit codes, the same for every command (README, "The command line"):
//   0  done (a check passed)
//   1  usage or input error: an unknown command or option, a bad value, an option the command does
//      not take, a missing, unreadable or invalid file; the message says which and what applies
//   2  a check ran and failed (check, stress; the examples' --check)
// CLI11's own codes for parse errors (105-109 and others) are folded into 1: a script needs to
// know "you called me wrong", not which of CLI11's error classes it was.
int main(int argc, char** argv) {
  CLI::App app{"ffcompat: legacy OpenGL fixed-function lighting, rendered and checked against Mesa"};
  app.require_subcommand(1);
  std::string backends;
  for (const std::string& name : ffcompat::backends()) backends += (backends.empty() ? "" : ", ") + name;
  app.set_version_flag("--version", std::string("ffcompat ") + ffcompat::version() + " (backends: " + backends + ")",
                       "Print the version and the backends of this build (with --json: as JSON) and exit");
  if (argc == 3 && std::string(argv[1]) == "--version" && std::string(argv[2]) == "--json") {
    std::string list;
    for (const std::string& name : ffcompat::backends()) list += (list.empty() ? "\"" : ", \"") + name + "\"";
    std::cout << "{\"name\": \"ffcompat\", \"version\": \"" << ffcompat::version() << "\", \"backends\": [" << list
              << "]}\n";
    return 0;
  }
  ffc::cli::add_render(app);
  ffc::cli::add_normals(app);
  ffc::cli::add_compare(app);
  ffc::cli::add_shading(app);
  ffc::cli::add_check(app);
  ffc::cli::add_bench(app);
  ffc::cli::add_report(app);
  ffc::cli::add_stress(app);
  ffc::cli::add_fuzz(app);
  ffc::cli::add_run(app);
  ffc::cli::add_calls(app);
  ffc::cli::add_glsl(app);
  ffc::cli::add_seeds(app);
  ffc::cli::add_platform_options(app);  // after the commands: it adds --platform to those that draw on Mesa
  // A missing or mistyped command: CLI11 says only "A subcommand is required"; name the real ones.
  std::string commands;
  bool known = false;
  for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    commands += (commands.empty() ? "" : ", ") + sub->get_name();
    known |= argc >= 2 && sub->get_name() == argv[1];
  }
  if (argc < 2 || (argv[1][0] != '-' && !known)) {
    if (argc < 2)
      std::cerr << "ffcompat: a command is required: " << commands << " (ffcompat --help)\n";
    else
      std::cerr << "ffcompat: unknown command '" << argv[1] << "'; the commands are " << commands << " (ffcompat --help)\n";
    return 1;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {  // thrown by a command with its exit code (2: check failed)
    return e.get_exit_code();
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints the message (or the help, for --help: code 0)
    return code == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "ffcompat: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
