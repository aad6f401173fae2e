// SPDX-License-Identifier: Apache-2.0
// `specular`: command-line front end of the reference model. Its CSV output is a contract
// (the report and outside scripts parse it): exact headers, every number the shortest
// text that parses back to the same double (cli::num), errors on stderr with exit code 2 and nothing on stdout.
#include "cli_parse.hpp"
#include "brdf.hpp"
#include "coefficients.hpp"
#include "metrics.hpp"
#include "scanline_setup.hpp"
#include "shade_command.hpp"
#include "span_csv.hpp"

#include <glm/vec3.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iterator>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace specular;

namespace {

// Argument parsers and the shortest round-trip number format: model/cli_parse.hpp.
using cli::bad;
using cli::num;
using cli::parse_int;
using cli::parse_list;
using cli::parse_real;
using cli::parse_vec;
using cli::UsageError;

CoefSpec coef_from(const std::string& coef, const std::string& q_text, bool q_given) {
  CoefSpec spec;
  try {
    spec = parse_coef_spec(coef);
  } catch (const std::invalid_argument&) {
    bad("--coef", "'" + coef + "' is not allowed; allowed maclaurin, minimax, kutlog (with --Q) or kutlog:Q, Q in (0, 1)");
  }
  if (spec.policy == CoefPolicy::kutlog && coef == "kutlog") {
    if (!q_given) bad("--Q", "required with --coef kutlog; allowed (0, 1) exclusive");
    spec.Q = parse_real("--Q", q_text, 1e-300, 1.0 - 1e-16, "(0, 1) exclusive");
  }
  return spec;
}

// The model options errors and albedo share: --k (patent, kutlog), --coef (patent), --Q
// (kutlog, or patent with --coef kutlog), --m (lyon). coef_given: --coef was on the command
// line. kutlog_q parses --Q of kutlog (albedo's --norm fit narrows its range).
ModelParams model_params(Model model, bool coef_given, const std::string& k, const std::string& coef,
                         const std::string& q, const std::string& m,
                         const std::function<double(const std::string&)>& kutlog_q) {
  const bool is_patent = model == Model::patent, is_kutlog = model == Model::kutlog;
  if (!k.empty() && !is_patent && !is_kutlog) bad("--k", "applies to --model patent or kutlog only");
  if (coef_given && !is_patent) bad("--coef", "applies to --model patent only");
  if (!q.empty() && !is_kutlog && !(is_patent && coef == "kutlog"))
    bad("--Q", "applies to --model kutlog or --coef kutlog only");
  if (!m.empty() && model != Model::lyon) bad("--m", "applies to --model lyon only");
  ModelParams p;
  if (is_patent) {
    if (!k.empty()) p.k = parse_int("--k", k, 1, 64);
    p.coef = coef_from(coef, q, !q.empty());
  }
  if (is_kutlog) {
    if (k.empty()) bad("--k", "required for --model kutlog; allowed 1..5");
    if (q.empty()) bad("--Q", "required for --model kutlog; allowed (0, 1) exclusive");
    p.k = parse_int("--k", k, 1, 5);
    p.Q = kutlog_q(q);
  }
  if (model == Model::lyon && !m.empty()) {
    p.m = parse_int("--m", m, 1, 1024);
    if ((p.m & (p.m - 1)) != 0) bad("--m", "'" + m + "' is not a power of two; allowed 1, 2, 4, ..., 1024");
  }
  return p;
}

struct Out {
  std::string text;
  void row(const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) text += (i ? "," : "") + cells[i];
    text += "\n";
  }
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Reference model of the specular-intensity device (patent UA 71489): error tables, "
               "decoder design table, albedo, scanline setup. CSV on stdout."};
  app.require_subcommand(1);

  // --- errors ---
  auto* err = app.add_subcommand("errors",
                                 "Shape errors of a model against cos^n: model,n,k,a,max_rel_epicenter,max_abs_lobe "
                                 "(fractions). k and a describe the cos^k(a x) form (blinn: k = n, a = 1; lyon/f16: "
                                 "k = m, a = nan; schlick, schlick-mod: nan)");
  const std::string all_n = "1.." + std::to_string(kMaxN);  // every exponent of the patent
  std::string e_model, e_n = all_n, e_k, e_coef = "maclaurin", e_q, e_m;
  err->add_option("--model", e_model, "blinn, patent, prototype, schlick, schlick-mod, lyon, f16, kutlog")->required();
  err->add_option("--n", e_n, "exponents, e.g. " + all_n + " or 1,2,7 (" + all_n + ")");
  err->add_option("--k", e_k, "patent: bank override (1..64, default: decoder); kutlog: required (1..5)");
  err->add_option("--coef", e_coef, "patent: maclaurin (default), minimax, kutlog (needs --Q) or kutlog:Q");
  err->add_option("--Q", e_q, "kutlog: level in (0, 1)");
  err->add_option("--m", e_m, "lyon: power m = 2^w in 1..1024 (default 16)");

  // --- krange ---
  auto* kr = app.add_subcommand("krange",
                                "Decoder design table: for each k, the n in 1..1000 whose max relative epicenter error of "
                                "cos^k(a x) is <= tol: k,n_min,n_max,count (n_min = n_max = 0 when count = 0)");
  std::string k_tol, k_k = "1,2,4,16", k_coef = "maclaurin", k_q;
  kr->add_option("--tol", k_tol, "tolerance as a fraction, (0, 1]")->required();
  kr->add_option("--k", k_k, "banks to tabulate (1..64), default 1,2,4,16");
  kr->add_option("--coef", k_coef, "maclaurin (default), minimax, kutlog (needs --Q) or kutlog:Q");
  kr->add_option("--Q", k_q, "kutlog: level in (0, 1)");

  // --- albedo ---
  auto* al = app.add_subcommand("albedo",
                                "Hemispherical albedo 2 pi int F cos sin with light at the normal: model,n,albedo");
  std::string a_model, a_n = all_n, a_conv = "phong", a_norm = "none", a_k, a_q, a_coef = "maclaurin", a_m;
  al->add_option("--model", a_model, "blinn, patent, prototype, schlick, schlick-mod, lyon, f16, kutlog")->required();
  al->add_option("--n", a_n, "exponents (" + all_n + ")");
  al->add_option("--convention", a_conv, "phong (angle = theta, default) or blinn (angle = theta/2)");
  al->add_option("--norm", a_norm,
                 "none (default), own (blinn, patent, prototype, schlick, schlick-mod, lyon: (n+8)/(8 pi); "
                 "f16: (n+6)/24.55; kutlog: exact coef) or fit (kutlog only: the paper's curve fit)");
  al->add_option("--k", a_k, "patent: bank override (1..64); kutlog: required (1..5)");
  al->add_option("--Q", a_q, "kutlog: level in (0, 1)");
  al->add_option("--coef", a_coef, "patent: coefficient policy");
  al->add_option("--m", a_m, "lyon: power m (default 16)");

  // --- setup ---
  auto* su = app.add_subcommand("setup",
                                "Scanline setup (docs/scanline_setup.md): A,lambda,gamma,C,psi0,dpsi; with --pixels also "
                                "i,psi,blinn,device_float,truth");
  std::string s_n1, s_n2, s_h1, s_he, s_len, s_exp, s_is = "1", s_ks = "1", s_norm = "none", s_coef = "maclaurin", s_q;
  bool s_pixels = false;
  su->add_option("--n1", s_n1, "unit normal at the first pixel, X,Y,Z")->required();
  su->add_option("--n2", s_n2, "unit normal at the last pixel, X,Y,Z")->required();
  su->add_option("--h1", s_h1, "halfway vector at the first pixel, X,Y,Z")->required();
  su->add_option("--he", s_he, "halfway vector at the last pixel (default --h1)");
  su->add_option("--len", s_len, "l = X_end - X_start, 0.." + std::to_string(kMaxLen) + " (l + 1 pixels)")->required();
  su->add_option("--exp", s_exp, "specular exponent n, [1, " + std::to_string(kMaxN) + "]")->required();
  su->add_option("--is", s_is, "light intensity Is >= 0 (default 1)");
  su->add_option("--ks", s_ks, "specular coefficient ks >= 0 (default 1)");
  su->add_option("--norm", s_norm, "none (default) or own (Blinn-Phong (n+8)/(8 pi))");
  su->add_option("--coef", s_coef, "coefficient policy of device_float (default maclaurin)");
  su->add_option("--Q", s_q, "kutlog: level in (0, 1)");
  su->add_flag("--pixels", s_pixels, "also print the per-pixel table");

  // --- shade ---
  auto* sh = app.add_subcommand("shade",
                                "One span through one evaluator: i,psi,value with value ~ C cos^n(psi_i), "
                                "psi_i = psi0 + i dpsi (see model/tools/shade_command.hpp)");
  shade_cli::Args sh_args;
  shade_cli::add_options(sh, sh_args);

  // --- setup-batch ---
  auto* sb = app.add_subcommand("setup-batch",
                                "Scanline setup of many spans to the default build's register codes "
                                "(docs/scanline_setup.md#batched-setup). Input CSV with the header "
                                "n1x,n1y,n1z,n2x,n2y,n2z,h1x,h1y,h1z,hex,hey,hez,n,l,scale (scale = Is ks s(n)); "
                                "output status,c_code,psi0_code,dpsi_code,n,l,C,psi0,dpsi, one line per span");
  std::string b_in, b_method = "batch", b_out;
  sb->add_option("--in", b_in, "span CSV file")->required();
  sb->add_option("--method", b_method, "scalar (scanline_setup, the reference) or batch (default, vectorized)");
  sb->add_option("--out", b_out, "output file (default: standard output); written whole or not at all");

  // Name an unknown command instead of CLI11's generic "a subcommand is required".
  if (argc > 1 && argv[1][0] != '-') {
    const std::string c = argv[1];
    if (c != "errors" && c != "krange" && c != "albedo" && c != "setup" && c != "shade" && c != "setup-batch") {
      std::cerr << "specular: error: '" << c
                << "' is not a command; allowed errors, krange, albedo, setup, shade, setup-batch\n";
      return 2;
    }
  }
  if (const auto exit_code = specular::parse_command_line(app, argc, argv, "specular")) return *exit_code;

  std::string cmd = "specular";
  Out out;
  try {
    if (*err) {
      cmd += " errors";
      const auto model = parse_model(e_model);
      if (!model || *model == Model::phong)
        bad("--model", "'" + e_model + "' is not allowed; allowed blinn, patent, prototype, schlick, schlick-mod, lyon, f16, kutlog");
      const auto ns = parse_list("--n", e_n, 1, kMaxN, true);
      ModelParams p = model_params(*model, err->count("--coef") > 0, e_k, e_coef, e_q, e_m, [](const std::string& q) {
        return parse_real("--Q", q, 1e-300, 1.0 - 1e-16, "(0, 1) exclusive");
      });
      out.row({"model", "n", "k", "a", "max_rel_epicenter", "max_abs_lobe"});
      for (double n : ns) {
        p.n = n;
        const ModelEvaluator ev = make_evaluator(*model, p);
        const ShapeError se = shape_error(ev, n);
        std::string k = ev.k > 0 ? std::to_string(ev.k) : "nan";
        if (*model == Model::blinn) k = num(n);
        out.row({e_model, num(n), k, num(ev.a), num(se.max_rel_epicenter), num(se.max_abs_lobe)});
      }
    } else if (*kr) {
      cmd += " krange";
      const double tol = parse_real("--tol", k_tol, 1e-300, 1.0, "(0, 1]");
      const auto ks = parse_list("--k", k_k, 1, 64, false);
      if (!k_q.empty() && k_coef != "kutlog") bad("--Q", "applies to --coef kutlog only");
      const CoefSpec spec = coef_from(k_coef, k_q, !k_q.empty());
      out.row({"k", "n_min", "n_max", "count"});
      for (double kd : ks) {
        const int k = static_cast<int>(kd);
        int n_min = 0, n_max = 0, count = 0;
        for (int n = 1; n <= kMaxN; ++n) {
          const double a = coefficient(n, k, spec);
          const double e = max_rel_epicenter([&](double x) { return cosk_shape(x, k, a); }, n);
          if (e <= tol) {
            if (count == 0) n_min = n;
            n_max = n;
            ++count;
          }
        }
        out.row({std::to_string(k), std::to_string(n_min), std::to_string(n_max), std::to_string(count)});
      }
    } else if (*al) {
      cmd += " albedo";
      const auto model = parse_model(a_model);
      if (!model || *model == Model::phong)
        bad("--model", "'" + a_model + "' is not allowed; allowed blinn, patent, prototype, schlick, schlick-mod, lyon, f16, kutlog");
      const auto ns = parse_list("--n", a_n, 1, kMaxN, true);
      if (a_conv != "phong" && a_conv != "blinn") bad("--convention", "'" + a_conv + "' is not allowed; allowed phong, blinn");
      if (a_norm != "none" && a_norm != "own" && a_norm != "fit")
        bad("--norm", "'" + a_norm + "' is not allowed; allowed none, own, fit");
      const bool is_kutlog = *model == Model::kutlog;
      if (a_norm == "fit" && !is_kutlog) bad("--norm", "fit applies to --model kutlog only; allowed none, own");
      const bool fit = a_norm == "fit";
      ModelParams p = model_params(*model, al->count("--coef") > 0, a_k, a_coef, a_q, a_m, [&](const std::string& q) {
        if (!fit) return parse_real("--Q", q, 1e-300, 1.0 - 1e-16, "(0, 1) exclusive");
        const double Q = parse_real("--Q", q, 0.1, 0.9, "[0.1, 0.4] or [0.5, 0.9] with --norm fit");
        if (Q > 0.4 && Q < 0.5) bad("--Q", "'" + q + "' is between the fits' ranges; allowed [0.1, 0.4] or [0.5, 0.9] with --norm fit");
        return Q;
      });
      const Convention conv = a_conv == "phong" ? Convention::phong : Convention::blinn;
      out.row({"model", "n", "albedo"});
      for (double n : ns) {
        p.n = n;
        const ModelEvaluator ev = make_evaluator(*model, p);
        const double raw = albedo(ev, conv, n);
        double s = 1.0;
        if (a_norm == "own") s = *model == Model::kutlog ? 1.0 / albedo(ev, Convention::phong, n) : ev.own_norm();
        if (a_norm == "fit") s = kutlog_coef_fit(n, p.k, p.Q);
        out.row({a_model, num(n), num(s * raw)});
      }
    } else if (*su) {
      cmd += " setup";
      ScanlineInput in;
      in.n1 = parse_vec("--n1", s_n1);
      in.n2 = parse_vec("--n2", s_n2);
      in.h1 = parse_vec("--h1", s_h1);
      in.he = s_he.empty() ? in.h1 : parse_vec("--he", s_he);
      auto zero = [](const glm::dvec3& v) { return v.x == 0 && v.y == 0 && v.z == 0; };
      if (zero(in.n1)) bad("--n1", "is the zero vector; a normal must have nonzero length");
      if (zero(in.n2)) bad("--n2", "is the zero vector; a normal must have nonzero length");
      in.l = parse_int("--len", s_len, 0, kMaxLen);
      in.n = parse_real("--exp", s_exp, 1.0, kMaxN, "[1, " + std::to_string(kMaxN) + "]");
      in.is = parse_real("--is", s_is, 0.0, 1e300, "[0, 1e300]");
      in.ks = parse_real("--ks", s_ks, 0.0, 1e300, "[0, 1e300]");
      if (s_norm != "none" && s_norm != "own") bad("--norm", "'" + s_norm + "' is not allowed; allowed none, own");
      in.norm = s_norm == "own" ? blinn_phong_norm(in.n) : 1.0;
      if (!s_q.empty() && s_coef != "kutlog") bad("--Q", "applies to --coef kutlog only");
      const CoefSpec spec = coef_from(s_coef, s_q, !s_q.empty());
      const ScanlineSetup s = scanline_setup(in);
      if (s.status == SetupStatus::invalid_input) bad("setup", s.note);
      if (!s.note.empty()) std::cerr << cmd << ": note (" << to_string(s.status) << "): " << s.note << "\n";
      out.row({"A", "lambda", "gamma", "C", "psi0", "dpsi"});
      out.row({num(s.A), num(s.lambda), num(s.gamma), num(s.C), num(s.psi0), num(s.dpsi)});
      if (s_pixels) {
        const int k = decoder_k_real(in.n);
        const double a = coefficient(in.n, k, spec);
        out.text += "\n";
        out.row({"i", "psi", "blinn", "device_float", "truth"});
        for (int i = 0; i <= in.l; ++i) {
          const double psi = pixel_psi(s, i);
          out.row({std::to_string(i), num(psi), num(pixel_blinn(s, in.n, i)), num(s.C * cosk_shape(psi, k, a)),
                   num(phong_truth(in, i))});
        }
      }
    } else if (*sh) {
      cmd += " shade";
      out.text = shade_cli::run(sh_args);
    } else if (*sb) {
      cmd += " setup-batch";
      if (b_method != "scalar" && b_method != "batch")
        bad("--method", "'" + b_method + "' is not allowed; allowed scalar, batch");
      std::ifstream file(b_in, std::ios::binary);
      if (!file) bad("--in", "cannot read '" + b_in + "'");
      const std::string text{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
      if (file.bad()) bad("--in", "cannot read '" + b_in + "'");
      const host::SpanBatch spans = host::parse_span_csv(text, b_in);
      const device::Format f;
      host::RegisterBatch regs;
      if (b_method == "scalar")
        host::setup_scalar(spans, f, regs);
      else
        host::setup_batch(spans, f, regs);
      out.text = host::register_csv(regs, f);
      if (!b_out.empty()) {
        // Whole file or nothing: a temporary next to it, renamed into place.
        const std::string tmp = b_out + ".tmp";
        {
          std::ofstream o(tmp, std::ios::binary | std::ios::trunc);
          if (!o) bad("--out", "cannot write '" + b_out + "'");
          o << out.text;
          o.close();
          if (!o) {
            std::remove(tmp.c_str());
            bad("--out", "cannot write '" + b_out + "'");
          }
        }
        if (std::rename(tmp.c_str(), b_out.c_str()) != 0) {
          std::remove(tmp.c_str());
          bad("--out", "cannot write '" + b_out + "'");
        }
        out.text.clear();
      }
    }
  } catch (const UsageError& e) {
    std::cerr << cmd << ": error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << cmd << ": error: " << e.what() << "\n";
    return 2;
  }
  std::fwrite(out.text.data(), 1, out.text.size(), stdout);
  return 0;
}
