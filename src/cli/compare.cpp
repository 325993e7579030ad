// ffcompat compare: how far two pictures are apart, with a heat map of where.
#include <cstdio>
#include <memory>

#include "cli/common.h"

namespace ffc::cli {

void add_compare(CLI::App& app) {
  auto* cmd = app.add_subcommand("compare", "Compare two PNGs: max and mean difference, share, PSNR");
  auto a = std::make_shared<std::string>(), b = std::make_shared<std::string>(),
       diff = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("a", *a, "First PNG")->required();
  cmd->add_option("b", *b, "Second PNG")->required();
  cmd->add_option("--diff", *diff, "Write a heat map of the differences here");
  cmd->add_flag("--json", *json, "Print {max_diff, mean_diff, differing_share, rmse, psnr}");
  cmd->callback([=] {
    const image::Image ia = image::read_png(*a), ib = image::read_png(*b);
    const image::Diff d = image::compare(ia, ib);
    if (!diff->empty()) image::write_png(*diff, image::heat_map(ia, ib));
    if (*json) {
      print_json(to_json(d));
      return;
    }
    std::printf("max_diff         %d steps\nmean_diff        %.4f steps\ndiffering_share  %.4f%%\n"
                "psnr             %.2f dB\n",
                d.max_diff, d.mean_diff, 100 * d.differing_share, d.psnr);
  });
}

}  // namespace ffc::cli
