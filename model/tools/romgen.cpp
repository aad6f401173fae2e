// romgen: writes the device ROMs (SPEC section 5) from the golden-model formats.
//   romgen --out-dir roms                 coef_maclaurin.hex, coef_minimax.hex, cos_k_1_2_4_16.hex
//   romgen --out-dir d --policy kutlog:0.3 --cos-addr-bits 10 ...   other configurations
// Files are written whole (temp file + rename); on any error nothing is written and the
// exit code is 2 (bad arguments) or 1 (I/O).
#include "cli_parse.hpp"
#include "coefficients.hpp"
#include "device_model.hpp"
#include "rom_image.hpp"


#include <algorithm>
#include <filesystem>
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

int main(int argc, char** argv) {
  using specular::device::Format;
  Format f;
  std::string out_dir = "roms";
  std::vector<std::string> policies{"maclaurin", "minimax"};
  bool quiet = false;

  CLI::App app{"Generate the coefficient ROM (ROM 9) and the cos^k ROM (ROM 12) hex files"};
  app.add_option("--out-dir", out_dir, "output directory (created if missing)")->capture_default_str();
  app.add_option("--policy", policies, "coefficient policies: maclaurin, minimax, kutlog[:Q] (repeatable)")
      ->capture_default_str();
  app.add_option("--coef-bits", f.coef_bits, "ROM 9 word width")->check(CLI::Range(4, 31))->capture_default_str();
  app.add_option("--coef-frac", f.coef_frac, "ROM 9 fraction bits")->check(CLI::Range(3, 31))->capture_default_str();
  app.add_option("--cos-addr-bits", f.cos_addr_bits, "ROM 12 address bits per bank")
      ->check(CLI::Range(1, 20))
      ->capture_default_str();
  app.add_option("--cos-data-bits", f.cos_data_bits, "ROM 12 word width")->check(CLI::Range(1, 31))->capture_default_str();
  app.add_option("--banks", f.banks, "k of each ROM 12 bank")->check(CLI::Range(1, 1000))->delimiter(',');
  app.add_option("--bank-max-n", f.bank_max_n, "decoder: bank j serves bank_max_n[j-1] < n <= bank_max_n[j]")
      ->check(CLI::Range(1, 1000))
      ->delimiter(',');
  app.add_flag("--quiet", quiet, "do not list the files written");
  if (const auto exit_code = specular::parse_command_line(app, argc, argv, "romgen")) return *exit_code;

  // Build every image before writing any file, so a bad policy or format writes nothing.
  std::vector<std::pair<std::string, std::vector<uint32_t>>> coef_images;
  std::vector<uint32_t> cos_image;
  try {
    if (f.coef_frac > f.coef_bits)
      throw std::invalid_argument("--coef-frac (" + std::to_string(f.coef_frac) + ") must be <= --coef-bits (" +
                                  std::to_string(f.coef_bits) + ")");
    if (f.banks.size() != f.bank_max_n.size())
      throw std::invalid_argument("--banks and --bank-max-n must have the same number of entries");
    for (const auto& p : policies) {
      specular::CoefSpec spec;
      try {
        spec = specular::parse_coef_spec(p);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--policy: " + std::string(e.what()));
      }
      coef_images.emplace_back(coef_file_name(p), specular::coef_rom_image(f, spec));
    }
    cos_image = specular::cos_rom_image(f);
  } catch (const std::invalid_argument& e) {
    std::cerr << "romgen: " << e.what() << "\n";
    return 2;
  }

  try {
    std::filesystem::create_directories(out_dir);
    for (const auto& [name, img] : coef_images) {
      const std::string path = (std::filesystem::path(out_dir) / name).string();
      specular::write_hex(path, img, f.coef_bits);
      if (!quiet) std::cout << "wrote " << path << " (" << img.size() << " x " << f.coef_bits << " bits)\n";
    }
    const std::string path = (std::filesystem::path(out_dir) / specular::cos_rom_file_name(f)).string();
    specular::write_hex(path, cos_image, f.cos_data_bits);
    if (!quiet) std::cout << "wrote " << path << " (" << cos_image.size() << " x " << f.cos_data_bits << " bits)\n";
  } catch (const std::exception& e) {
    std::cerr << "romgen: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
