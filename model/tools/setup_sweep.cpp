// SPDX-License-Identifier: Apache-2.0
// setup_sweep: the hardware setup's unit width F against its contract
// (docs/setup_hw.md#widths): for each F, host::fixed::setup_fixed on the hard and
// near-degenerate spans, on random spans and on every span of the scenes, each checked by
// host::check_contract (the worst error as a fraction of the 0.01 % + 1 LSB allowance, the
// decisions that differ outside the guard bands, the decisions inside one).
//   setup_sweep [--frac 20,22,...] [--spans N] [--scenes DIR] [--json FILE]
// Exit 1 when the default F (host::fixed::kFrac) misses the contract on any span.
#include "cli_parse.hpp"
#include "geo_cases.hpp"
#include "raster.hpp"
#include "scene.hpp"
#include "setup_contract.hpp"
#include "setup_fixed.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace specular;
namespace fs = std::filesystem;

namespace {

struct Tally {
  size_t spans = 0, fails = 0, decision_diffs = 0, in_band = 0;
  double worst = 0.0, max_lsb = 0.0;
  nlohmann::json json() const {
    return {{"spans", spans}, {"fails", fails}, {"decision_diffs", decision_diffs}, {"in_band", in_band},
            {"worst", worst}, {"max_lsb", max_lsb}};
  }
};

void run(const std::vector<device::GeoSpan>& spans, const host::fixed::Widths& w, Tally& t) {
  for (const auto& g : spans) {
    const host::fixed::Result r = host::fixed::setup_fixed(g, geo_cases::kGeo, geo_cases::kFmt, w);
    const host::ContractCheck c = host::check_contract(
        g, r.status, {r.trace.opposite_normals, r.trace.flat, r.trace.opposite_halfway}, r.span.reg, geo_cases::kGeo,
        geo_cases::kFmt);
    ++t.spans;
    t.fails += !c.pixels.ok();
    t.decision_diffs += !c.decisions_equal;
    t.in_band += static_cast<size_t>(c.in_band);
    t.worst = std::max(t.worst, c.pixels.worst);
    t.max_lsb = std::max(t.max_lsb, c.pixels.max_abs_lsb);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The hardware setup's unit width against its contract (docs/setup_hw.md#widths)"};
  std::vector<int> fracs{20, 22, 24, 26, 28, 30};
  size_t n_random = 200000;
  std::string scenes_dir, json_path;
  app.add_option("--frac", fracs, "unit widths F to try (even, 20..30)")->delimiter(',');
  app.add_option("--spans", n_random, "random spans per width")->check(CLI::Range(size_t{1}, size_t{100000000}));
  app.add_option("--scenes", scenes_dir, "a folder of scene files (*.json): every span of each")->check(CLI::ExistingDirectory);
  app.add_option("--json", json_path, "write the results as JSON here");
  if (auto code = parse_command_line(app, argc, argv, "setup_sweep")) return *code;
  for (int f : fracs) {
    try {
      host::fixed::check_widths({f});
    } catch (const std::invalid_argument& e) {
      std::cerr << "setup_sweep: error: --frac: " << e.what() << "\n";
      return 2;
    }
  }

  std::vector<device::GeoSpan> hard = geo_cases::near_degenerate_spans();
  for (const auto& h : geo_cases::hard_cases()) hard.push_back(h.g);
  std::vector<std::pair<std::string, std::vector<device::GeoSpan>>> scenes;
  if (!scenes_dir.empty()) {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(scenes_dir))
      if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& p : files) {
      const Scene s = load_scene(p.string());
      const Raster r = rasterize(s);
      std::vector<device::GeoSpan> v;
      for (size_t i = 0; i < r.spans.size(); ++i)
        v.push_back(device::quantize_geo(r.spans[i].setup_in, geo_cases::kGeo, geo_cases::kFmt,
                                         static_cast<uint32_t>(i) & ((1u << geo_cases::kGeo.tag_bits) - 1)));
      scenes.emplace_back(s.name, std::move(v));
    }
  }
  const std::vector<device::GeoSpan> random = geo_cases::random_geo_spans(n_random, 20261205);

  nlohmann::json flat = nlohmann::json::object();
  for (const auto& [name, spans] : scenes)
    flat[name] = {{"spans", spans.size()},
                  {"flat_path", std::count_if(spans.begin(), spans.end(), host::fixed::takes_flat_path)},
                  {"one_pixel", std::count_if(spans.begin(), spans.end(), [](const auto& g) { return g.len == 0; })}};
  nlohmann::json out = nlohmann::json::array();
  bool default_ok = true;
  for (int f : fracs) {
    const host::fixed::Widths w{f};
    Tally th, tr;
    run(hard, w, th);
    run(random, w, tr);
    nlohmann::json row{{"frac", f}, {"hard", th.json()}, {"random", tr.json()}};
    std::cout << "F " << f << ": hard worst " << th.worst << " (" << th.decision_diffs << " decisions differ), random worst "
              << tr.worst << " (" << tr.fails << " fail, " << tr.decision_diffs << " decisions differ, " << tr.in_band
              << " in a band)";
    bool ok = th.fails + th.decision_diffs + tr.fails + tr.decision_diffs == 0;
    for (const auto& [name, spans] : scenes) {
      Tally ts;
      run(spans, w, ts);
      row["scenes"][name] = ts.json();
      std::cout << ", " << name << " " << ts.worst;
      ok = ok && ts.fails + ts.decision_diffs == 0;
    }
    std::cout << (ok ? "" : "  MISSES THE CONTRACT") << "\n";
    row["meets"] = ok;
    if (f == host::fixed::kFrac) default_ok = ok;
    out.push_back(row);
  }
  if (!json_path.empty()) {
    std::ofstream os(json_path + ".tmp");
    os << nlohmann::json{{"widths", out}, {"scene_spans", flat}, {"random_spans", n_random}, {"default_frac", host::fixed::kFrac}}.dump(2) << "\n";
    if (!os) {
      std::cerr << "setup_sweep: error: cannot write " << json_path << "\n";
      return 2;
    }
    os.close();
    fs::rename(json_path + ".tmp", json_path);
  }
  return default_ok ? 0 : 1;
}
