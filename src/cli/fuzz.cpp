// ffcompat fuzz: the differential tester (src/difftest). Random GL call streams run on Mesa and
// on soft in forked children; mismatches that no known deviation explains are shrunk and printed
// as C snippets. Exit code 2 when one is found, or a side crashed or hung.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "cli/common.h"
#include "difftest/fuzz.h"
#include "difftest/known.h"

namespace ffc::cli {

namespace {

std::string slug(const std::string& key) {
  std::string s;
  for (char c : key) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return s.substr(0, 80);
}

nlohmann::json to_json(const difftest::Summary& s, const difftest::FuzzOptions& o) {
  nlohmann::json findings = nlohmann::json::array();
  for (const auto& f : s.findings)
    findings.push_back({{"kind", f.mismatch.kind},
                        {"key", f.mismatch.key},
                        {"detail", f.mismatch.detail},
                        {"stream_seed", f.seed},
                        {"streams", f.streams},
                        {"calls", f.stream.size()},
                        {"c", difftest::to_c(f.stream)},
                        {"repro", difftest::to_text(f.stream)}});
  nlohmann::json cats = nlohmann::json::array();
  for (const auto& c : difftest::categories())
    if (o.gen.has(c.name)) cats.push_back(c.name);
  return {{"seed", o.seed},
          {"streams", s.streams},
          {"calls", s.calls},
          {"unexplained_streams", s.unexplained_streams},
          {"seconds", s.seconds},
          {"streams_per_minute", s.seconds > 0 ? s.streams * 60.0 / s.seconds : 0.0},
          {"categories", cats},
          {"mismatches_by_kind", s.mismatches_by_kind},
          {"known_deviations", s.known_by_name},
          {"crashes", s.crashes},
          {"hangs", s.hangs},
          {"findings", findings},
          {"failed", s.failed()}};
}

// One stream call by call: what each side's glGetError said after it and what it returned, so a
// shrunk repro can be read against Mesa without writing a program.
void print_trace(const difftest::Stream& st, const difftest::Checked& c, bool json) {
  auto at = [](const auto& v, size_t i, auto none) { return i < v.size() ? v[i] : none; };
  auto status = [](const difftest::SideResult& r) {
    return r.status == difftest::SideResult::Status::Ok ? std::string("ok")
           : r.status == difftest::SideResult::Status::Hung ? "hung at call " + std::to_string(r.call)
                                                              : "crashed at call " + std::to_string(r.call) + ": " + r.what;
  };
  nlohmann::json calls = nlohmann::json::array();
  for (size_t i = 0; i < st.size(); ++i) {
    const GLenum me = at(c.mesa.errors, i, GLenum(0)), se = at(c.soft.errors, i, GLenum(0));
    const double mr = at(c.mesa.returns, i, std::nan("")), sr = at(c.soft.returns, i, std::nan(""));
    const std::string line = difftest::to_text({st[i]}).substr(difftest::to_text({}).size());
    if (json) {
      calls.push_back({{"call", i}, {"text", line}, {"mesa_error", difftest::error_name(me)},
                       {"soft_error", difftest::error_name(se)}, {"mesa_return", std::isnan(mr) ? nlohmann::json() : nlohmann::json(mr)},
                       {"soft_return", std::isnan(sr) ? nlohmann::json() : nlohmann::json(sr)}});
      continue;
    }
    std::string text = line.substr(0, line.find('\n')).substr(0, 70);
    std::printf("%3zu %s %-70s mesa %s soft %s", i, me != se ? "*" : " ", text.c_str(), difftest::error_name(me).c_str(),
                difftest::error_name(se).c_str());
    if (!std::isnan(mr) || !std::isnan(sr)) std::printf("  returned mesa %g soft %g", mr, sr);
    std::printf("\n");
  }
  std::vector<std::string> unexplained;
  for (const auto& m : c.unexplained) unexplained.push_back(m.key + " (" + m.detail + ")");
  if (json) {
    print_json({{"calls", calls}, {"mesa", status(c.mesa)}, {"soft", status(c.soft)}, {"unexplained", unexplained}});
    return;
  }
  for (const auto* side : {&c.mesa, &c.soft})
    for (const auto& o : side->outputs) {
      std::printf("%s output of call %d:", side == &c.mesa ? "mesa" : "soft", o.call);
      for (size_t k = 0; k < o.values.size() && k < 24; ++k) std::printf(" %g", o.values[k]);
      std::printf(o.values.size() > 24 ? " ...\n" : "\n");
    }
  std::printf("mesa %s, soft %s\n", status(c.mesa).c_str(), status(c.soft).c_str());
  for (const auto& u : unexplained) std::printf("unexplained: %s\n", u.c_str());
}

}  // namespace

void add_fuzz(CLI::App& app) {
  auto* cmd = app.add_subcommand("fuzz", "Differential tester: random GL call streams on Mesa and soft, mismatches shrunk to C snippets");
  auto o = std::make_shared<difftest::FuzzOptions>();
  auto only = std::make_shared<std::vector<std::string>>();
  auto exclude = std::make_shared<std::vector<std::string>>();
  auto json = std::make_shared<bool>(false);
  auto list = std::make_shared<bool>(false);
  auto no_shrink = std::make_shared<bool>(false);
  auto out = std::make_shared<std::string>();
  auto replay = std::make_shared<std::string>();
  auto one_seed = std::make_shared<uint64_t>(0);
  auto trace = std::make_shared<bool>(false);
  cmd->add_option("--seed", o->seed, "Seed of the run: stream i is generated from (seed, i)")->capture_default_str();
  cmd->add_option("--streams", o->streams, "Streams to run at most")->capture_default_str();
  cmd->add_option("--minutes", o->minutes, "Stop after this long (0: when --streams are done)")->capture_default_str();
  cmd->add_option("--calls", o->gen.calls, "Calls a stream makes, checkpoints not counted")->capture_default_str();
  cmd->add_option("--only", *only, "Only these generator categories (comma-separated or repeated; --list-categories)")->delimiter(',');
  cmd->add_option("--exclude", *exclude, "Leave these categories out")->delimiter(',');
  cmd->add_option("--timeout", o->run.timeout, "Seconds a side may run a stream before it counts as hung")->capture_default_str();
  cmd->add_option("--shrink-budget", o->shrink_budget, "Runs of a stream the shrinker may make per finding")->capture_default_str();
  cmd->add_flag("--no-shrink", *no_shrink, "Report findings as generated");
  cmd->add_flag("--list-categories", *list, "List the generator's categories and run nothing");
  cmd->add_option("--out", *out, "Write each finding as DIR/<n>-<key>.txt (replayable) and .c");
  cmd->add_option("--replay", *replay, "Run one stream from a file written by --out instead of generating");
  cmd->add_option("--stream-seed", *one_seed,
                  "Run the one stream generated from this stream seed (as `fuzz: unexplained: ... seed S` logs it) "
                  "and shrink what it shows; with --no-shrink --out DIR, write it whole");
  cmd->add_flag("--trace", *trace,
                 "With --replay or --stream-seed: print each call with the error and value it left on Mesa and on soft "
                 "(the mismatches are not shrunk)");
  cmd->add_flag("--json", *json, "Print {streams, mismatches_by_kind, known_deviations, crashes, hangs, findings: [{kind, key, c, repro}], ...}");
  cmd->callback([=] {
    if (*list) {
      if (*json) {
        nlohmann::json j = nlohmann::json::array();
        for (const auto& c : difftest::categories()) j.push_back({{"name", c.name}, {"what", c.what}});
        nlohmann::json k = nlohmann::json::array();
        for (const auto& d : difftest::known_deviations()) k.push_back({{"name", d.name}, {"description", d.description}});
        print_json({{"categories", j}, {"known_deviations", k}});
      } else {
        for (const auto& c : difftest::categories()) std::printf("%-11s %s\n", c.name.c_str(), c.what.c_str());
        std::printf("\nknown deviations:\n");
        for (const auto& d : difftest::known_deviations()) std::printf("%-34s %s\n", d.name.c_str(), d.description.c_str());
      }
      return;
    }
    o->gen.categories = difftest::select_categories(*only, *exclude);
    o->shrink = !*no_shrink && !*trace;
    auto log = [](const std::string& line) { std::fprintf(stderr, "fuzz: %s\n", line.c_str()); };
    difftest::Summary s;
    difftest::Stream one;
    if (!replay->empty()) {
      std::ifstream in(*replay);
      if (!in) throw std::invalid_argument("cannot read " + *replay);
      std::stringstream text;
      text << in.rdbuf();
      one = difftest::parse_text(text.str());
    } else if (*one_seed != 0) {
      one = difftest::generate(*one_seed, o->gen);
    }
    if (*trace) {
      if (one.empty()) throw std::invalid_argument("--trace needs --replay or --stream-seed");
      return print_trace(one, difftest::check(one, o->run), *json);
    }
    if (!one.empty()) {
      s = difftest::replay(one, *o, log);
    } else {
      s = difftest::fuzz(*o, log);
    }
    if (!out->empty()) {
      std::filesystem::create_directories(*out);
      for (size_t i = 0; i < s.findings.size(); ++i) {
        const auto& f = s.findings[i];
        const std::string base = *out + "/" + std::to_string(i) + "-" + slug(f.mismatch.key);
        std::ofstream(base + ".txt") << "# " << f.mismatch.key << ": " << f.mismatch.detail << "\n"
                                     << difftest::to_text(f.stream);
        std::ofstream(base + ".c") << "/* " << f.mismatch.key << ": " << f.mismatch.detail << " */\n"
                                   << difftest::to_c(f.stream);
      }
    }
    if (*json) {
      print_json(to_json(s, *o));
    } else {
      std::printf("%d streams, %d calls in %.1f s (%.0f streams a minute)\n", s.streams, s.calls, s.seconds,
                  s.seconds > 0 ? s.streams * 60 / s.seconds : 0.0);
      std::printf("crashes %d, hangs %d; streams with an unexplained mismatch %d\n", s.crashes, s.hangs,
                  s.unexplained_streams);
      for (const auto& [name, n] : s.known_by_name) std::printf("known deviation %-34s %d streams\n", name.c_str(), n);
      for (const auto& [kind, n] : s.mismatches_by_kind) std::printf("mismatch %-12s %d streams\n", kind.c_str(), n);
      for (const auto& f : s.findings) {
        std::printf("\n== %s (%d streams; stream seed %llu)\n   %s\n", f.mismatch.key.c_str(), f.streams,
                    static_cast<unsigned long long>(f.seed), f.mismatch.detail.c_str());
        std::printf("%s", difftest::to_c(f.stream).c_str());
      }
      std::printf(s.failed() ? "\nFAILED: unexplained mismatches\n" : "\nno unexplained mismatch\n");
    }
    if (s.failed()) throw CLI::RuntimeError(2);
  });
}

}  // namespace ffc::cli
