// ffcompat: the legacy fixed-function lighting pipeline, rendered and compared.
#include <iostream>

#include "cli/common.h"

namespace ffc::cli {
void add_check(CLI::App& app);  // check.cpp
void add_bench(CLI::App& app);  // bench.cpp
void add_report(CLI::App& app);  // report.cpp
void add_stress(CLI::App& app);  // stress.cpp
void add_fuzz(CLI::App& app);    // fuzz.cpp
}

int main(int argc, char** argv) {
  CLI::App app{"ffcompat: legacy OpenGL fixed-function lighting, rendered and checked against Mesa"};
  app.require_subcommand(1);
  ffc::cli::add_render(app);
  ffc::cli::add_normals(app);
  ffc::cli::add_compare(app);
  ffc::cli::add_shading(app);
  ffc::cli::add_check(app);
  ffc::cli::add_bench(app);
  ffc::cli::add_report(app);
  ffc::cli::add_stress(app);
  ffc::cli::add_fuzz(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "ffcompat: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
