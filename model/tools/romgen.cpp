// SPDX-License-Identifier: Apache-2.0
// romgen: writes the device ROMs (docs/device.md) from the golden-model formats.
//   romgen --out-dir roms                  the single-bank build: coef_minimax.hex and
//                                          cos_k_1_2_3_4_6_8_12_16_interp256.hex
//   romgen --config patent --out-dir roms/patent    coef_maclaurin.hex, cos_k_1_2_4_16.hex
//   romgen --all --out-dir roms            every configuration of build_configs() and the CMake
//                                          list of them, roms/build_configs.cmake (what
//                                          `make roms` runs; docs/pipeline.md#build-configurations)
//   romgen --out-dir d --policy kutlog:0.3 --cos-addr-bits 7 --banks 1,2,4 ...  others
// A bank set given without --bank-max-n gets the derived decoder table (decoder_table.hpp).
// Files are written whole (temp file + rename); on any error nothing is written and the
// exit code is 2 (bad arguments) or 1 (I/O).
#include "blend_rom.hpp"
#include "cli_parse.hpp"
#include "coefficients.hpp"
#include "decoder_table.hpp"
#include "device_model.hpp"
#include "rom_image.hpp"


#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

std::string coef_file_name(const std::string& policy) {
  std::string s = policy;
  std::replace(s.begin(), s.end(), ':', '_');
  return "coef_" + s + ".hex";
}

}  // namespace

struct Job {
  std::string dir;
  specular::device::Format f;
  std::vector<std::string> policies;
};

int main(int argc, char** argv) {
  using specular::device::Format;
  std::string config = "single";
  std::string out_dir = "roms";
  std::vector<std::string> policies;
  std::vector<int> banks, bank_max_n;
  bool quiet = false, all = false, direct = false, interp = false;
  // Overrides of the chosen configuration (-1: keep).
  int coef_bits = -1, coef_frac = -1, cos_addr_bits = -1, cos_data_bits = -1, cos_delta_bits = -1,
      cos_frac_bits = -1;

  CLI::App app{"Generate the coefficient ROM (ROM 9) and the cos^k ROM (ROM 12) hex files"};
  app.add_option("--config", config, "base configuration: single (the single-bank build: interpolated, 8 banks, "
                                      "minimax) or patent (direct table, {1,2,4,16}, maclaurin); the default build "
                                      "(a blend) is written by --all")
      ->check(CLI::IsMember({"single", "patent"}))
      ->capture_default_str();
  app.add_flag("--all", all, "write every build configuration (rom_image.hpp build_configs) under OUT_DIR: "
                             "each into its directory under OUT_DIR (build_configs' dir less its leading roms/)");
  app.add_option("--out-dir", out_dir, "output directory (created if missing)")->capture_default_str();
  app.add_option("--policy", policies, "coefficient policies: maclaurin, minimax, kutlog[:Q] (repeatable; "
                                       "default: minimax, maclaurin for --config patent)");
  app.add_option("--coef-bits", coef_bits, "ROM 9 word width")->check(CLI::Range(4, 31));
  app.add_option("--coef-frac", coef_frac, "ROM 9 fraction bits")->check(CLI::Range(3, 31));
  app.add_option("--cos-addr-bits", cos_addr_bits, "ROM 12 address bits per bank")->check(CLI::Range(1, 20));
  app.add_option("--cos-data-bits", cos_data_bits, "ROM 12 fraction bits of cos^k")->check(CLI::Range(1, 30));
  app.add_option("--cos-delta-bits", cos_delta_bits, "interpolated ROM 12: bits of the step to the next entry")
      ->check(CLI::Range(1, 24));
  app.add_option("--cos-frac-bits", cos_frac_bits, "interpolated ROM 12: bits of zeta weighting the step")
      ->check(CLI::Range(1, 24));
  auto* o_direct = app.add_flag("--direct", direct, "ROM 12 as a direct table (the patent's)");
  app.add_flag("--interp", interp, "ROM 12 interpolated (value + step)")->excludes(o_direct);
  app.add_option("--banks", banks, "k of each ROM 12 bank, increasing")->check(CLI::Range(1, 1000))->delimiter(',');
  app.add_option("--bank-max-n", bank_max_n, "decoder: bank j serves bank_max_n[j-1] < n <= bank_max_n[j] "
                                             "(default: derived from the bank set)")
      ->check(CLI::Range(1, 1000))
      ->delimiter(',')
      ->needs("--banks");
  app.add_flag("--quiet", quiet, "do not list the files written");
  if (const auto exit_code = specular::parse_command_line(app, argc, argv, "romgen")) return *exit_code;

  // Build every image before writing any file, so a bad policy or format writes nothing.
  std::vector<Job> jobs;
  std::vector<std::pair<std::string, std::vector<uint64_t>>> files;  // path, image
  auto wide = [](const std::vector<uint32_t>& v) { return std::vector<uint64_t>(v.begin(), v.end()); };
  std::vector<int> widths;
  try {
    auto make_job = [&](const std::string& cfg, const std::string& dir) {
      Job j;
      j.dir = dir;
      j.f = cfg == "patent" ? Format::patent() : Format{};
      j.policies = policies.empty() ? std::vector<std::string>{cfg == "patent" ? "maclaurin" : "minimax"} : policies;
      if (coef_bits >= 0) j.f.coef_bits = coef_bits;
      if (coef_frac >= 0) j.f.coef_frac = coef_frac;
      if (cos_addr_bits >= 0) j.f.cos_addr_bits = cos_addr_bits;
      if (cos_data_bits >= 0) j.f.cos_data_bits = cos_data_bits;
      if (cos_delta_bits >= 0) j.f.cos_delta_bits = cos_delta_bits;
      if (cos_frac_bits >= 0) j.f.cos_frac_bits = cos_frac_bits;
      if (direct) j.f.cos_interp = false;
      if (interp) j.f.cos_interp = true;
      if (j.f.coef_frac > j.f.coef_bits)
        throw std::invalid_argument("--coef-frac (" + std::to_string(j.f.coef_frac) + ") must be <= --coef-bits (" +
                                    std::to_string(j.f.coef_bits) + ")");
      if (!banks.empty()) {
        j.f.banks = banks;
        if (bank_max_n.empty()) {
          try {
            j.f.bank_max_n = specular::derive_bank_max_n(banks, specular::parse_coef_spec(j.policies.front()));
          } catch (const std::invalid_argument& e) {
            throw std::invalid_argument("--banks: " + std::string(e.what()));
          }
        } else {
          j.f.bank_max_n = bank_max_n;
        }
      }
      if (j.f.banks.size() != j.f.bank_max_n.size())
        throw std::invalid_argument("--banks and --bank-max-n must have the same number of entries");
      return j;
    };
    if (all) {
      for (const auto& bc : specular::build_configs()) {
        Job j;
        j.f = bc.f;
        j.policies = {bc.policy};
        // bc.dir is relative to the repository root and starts with "roms".
        const std::string sub = bc.dir.size() > 4 ? bc.dir.substr(5) : std::string();
        j.dir = sub.empty() ? out_dir : (std::filesystem::path(out_dir) / sub).string();
        jobs.push_back(j);
      }
    } else {
      jobs.push_back(make_job(config, out_dir));
    }
    for (const Job& j : jobs) {
      for (const auto& p : j.policies) {
        if (j.f.blend) {
          // ROM 9 of a blend build: {a1, a2, w} per n from the fits of its bank set
          // (docs/display_exact.md#coefficients).
          files.emplace_back((std::filesystem::path(j.dir) / coef_file_name(p)).string(),
                             specular::blend_coef_image(j.f, specular::blend_table_for(j.f)));
          widths.push_back(j.f.coef_word_bits());
          continue;
        }
        specular::CoefSpec spec;
        try {
          spec = specular::parse_coef_spec(p);
        } catch (const std::invalid_argument& e) {
          throw std::invalid_argument("--policy: " + std::string(e.what()));
        }
        files.emplace_back((std::filesystem::path(j.dir) / coef_file_name(p)).string(),
                           wide(specular::coef_rom_image(j.f, spec)));
        widths.push_back(j.f.coef_bits);
      }
      files.emplace_back((std::filesystem::path(j.dir) / specular::cos_rom_file_name(j.f)).string(),
                         wide(specular::cos_rom_image(j.f)));
      widths.push_back(j.f.cos_word_bits());
    }
  } catch (const std::invalid_argument& e) {
    std::cerr << "romgen: " << e.what() << "\n";
    return 2;
  }

  try {
    for (size_t i = 0; i < files.size(); ++i) {
      std::filesystem::create_directories(std::filesystem::path(files[i].first).parent_path());
      specular::write_hex_wide(files[i].first, files[i].second, widths[i]);
      if (!quiet)
        std::cout << "wrote " << files[i].first << " (" << files[i].second.size() << " x " << widths[i] << " bits)\n";
    }
    if (all) {
      // Whole or not at all, as the ROMs: a temporary file renamed over the old one.
      const std::filesystem::path path = std::filesystem::path(out_dir) / "build_configs.cmake";
      const std::filesystem::path tmp = path.string() + ".tmp";
      {
        std::ofstream out(tmp, std::ios::binary);
        out << specular::build_configs_cmake();
        if (!out.flush()) throw std::runtime_error("cannot write " + tmp.string());
      }
      std::filesystem::rename(tmp, path);
      if (!quiet) std::cout << "wrote " << path.string() << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "romgen: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
