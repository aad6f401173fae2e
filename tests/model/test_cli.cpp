// SPDX-License-Identifier: Apache-2.0
// The `specular` CLI contract: headers, a known row per subcommand (values from closed forms
// or an independent brute-force computation), exit code 2 with a clear message on bad input.
#include "coefficients.hpp"
#include "metrics.hpp"

#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {
struct Run {
  int code = -1;
  std::string out, err;
};

Run run(const std::string& args) {
  const std::string errfile = "/tmp/specular_cli_test_" + std::to_string(::getpid()) + ".err";
  const std::string cmd = std::string(SPECULAR_CLI) + " " + args + " 2>" + errfile;
  Run r;
  FILE* p = ::popen(cmd.c_str(), "r");
  REQUIRE(p != nullptr);
  char buf[4096];
  std::size_t got;
  while ((got = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, got);
  const int status = ::pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream e(errfile);
  std::stringstream ss;
  ss << e.rdbuf();
  r.err = ss.str();
  std::remove(errfile.c_str());
  return r;
}

std::vector<std::string> lines(const std::string& s) {
  std::vector<std::string> v;
  std::istringstream in(s);
  std::string l;
  while (std::getline(in, l)) v.push_back(l);
  return v;
}

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> v;
  std::istringstream in(line);
  std::string c;
  while (std::getline(in, c, ',')) v.push_back(c);
  return v;
}

double brute_rel(double n, int k, double a) {
  const long double xe = specular::epicenter_end(n);
  long double worst = 0;
  for (int i = 0; i <= 20000; ++i) {
    const long double x = xe * i / 20000;
    const long double ref = std::pow(std::cos(x), static_cast<long double>(n));
    const long double z = a * x;
    const long double f = z < 1.5707963267948966L ? std::pow(std::cos(z), static_cast<long double>(k)) : 0.0L;
    worst = std::max(worst, std::abs(f - ref) / ref);
  }
  return static_cast<double>(worst);
}
}  // namespace

TEST_CASE("cli errors: header, closed-form rows, list syntax", "[cli]") {
  const Run r = run("errors --model patent --n 16,1000,1..3");
  REQUIRE(r.code == 0);
  const auto L = lines(r.out);
  REQUIRE(L.size() == 6);
  CHECK(L[0] == "model,n,k,a,max_rel_epicenter,max_abs_lobe");
  // n = k = 16 with maclaurin: a = 1, exact.
  CHECK(L[1] == "patent,16,16,1,0,0");
  const auto r1000 = cells(L[2]);
  CHECK(r1000[2] == "16");
  CHECK_THAT(std::stod(r1000[3]), WithinRel(std::sqrt(62.5), 1e-8));
  CHECK_THAT(std::stod(r1000[4]), WithinRel(brute_rel(1000, 16, std::sqrt(62.5)), 1e-4));
  CHECK(cells(L[3])[1] == "1");
  CHECK(cells(L[5])[2] == "4");  // n = 3 -> k = 4
  // at least 6 significant digits
  CHECK(r1000[4].size() >= 8);
}

TEST_CASE("cli errors: minimax and kutlog rows", "[cli]") {
  const Run r = run("errors --model patent --n 3 --coef minimax");
  REQUIRE(r.code == 0);
  const auto c = cells(lines(r.out)[1]);
  const double a = std::stod(c[3]);
  CHECK_THAT(a, WithinAbs(0.87219, 1e-5));  // the lead's independent script
  CHECK_THAT(std::stod(c[4]), WithinRel(brute_rel(3, 4, a), 1e-4));
  const Run k = run("errors --model kutlog --n 10 --k 2 --Q 0.5");
  REQUIRE(k.code == 0);
  const double ak = std::acos(std::sqrt(0.5)) / std::acos(std::pow(0.5, 0.1));
  CHECK_THAT(std::stod(cells(lines(k.out)[1])[3]), WithinRel(ak, 1e-8));
}

TEST_CASE("cli krange: header and the boundary rows against brute force", "[cli]") {
  const Run r = run("krange --tol 0.01 --k 4,16");
  REQUIRE(r.code == 0);
  const auto L = lines(r.out);
  REQUIRE(L.size() == 3);
  CHECK(L[0] == "k,n_min,n_max,count");
  for (int row = 1; row <= 2; ++row) {
    const auto c = cells(L[row]);
    const int k = std::stoi(c[0]), lo = std::stoi(c[1]), hi = std::stoi(c[2]);
    INFO(L[row]);
    CHECK(std::stoi(c[3]) == hi - lo + 1);  // the admissible set is an interval around n = k
    CHECK(brute_rel(lo, k, std::sqrt(double(lo) / k)) <= 0.01);
    CHECK(brute_rel(hi, k, std::sqrt(double(hi) / k)) <= 0.01);
    if (lo > 1) CHECK(brute_rel(lo - 1, k, std::sqrt(double(lo - 1) / k)) > 0.01);
    if (hi < specular::kMaxN) CHECK(brute_rel(hi + 1, k, std::sqrt(double(hi + 1) / k)) > 0.01);
  }
}

TEST_CASE("cli albedo: closed forms", "[cli]") {
  const Run r = run("albedo --model blinn --n 10,1000");
  REQUIRE(r.code == 0);
  const auto L = lines(r.out);
  REQUIRE(L.size() == 3);
  CHECK(L[0] == "model,n,albedo");
  CHECK_THAT(std::stod(cells(L[1])[2]), WithinRel(2 * M_PI / 12, 1e-8));
  CHECK_THAT(std::stod(cells(L[2])[2]), WithinRel(2 * M_PI / 1002, 1e-8));
  // own normalization, blinn convention: (n+8)/(8 pi) * 8 pi [2u^(n+4)/(n+4) - u^(n+2)/(n+2)]_{1/sqrt2}^1
  const Run b = run("albedo --model blinn --n 4 --convention blinn --norm own");
  REQUIRE(b.code == 0);
  auto P = [](double u) { return 2 * std::pow(u, 8) / 8 - std::pow(u, 6) / 6; };
  CHECK_THAT(std::stod(cells(lines(b.out)[1])[2]), WithinRel(12.0 * (P(1) - P(std::sqrt(0.5))), 1e-8));
  // kutlog with its exact coef integrates to 1 in the phong convention.
  const Run k = run("albedo --model kutlog --n 50 --k 3 --Q 0.5 --norm own");
  REQUIRE(k.code == 0);
  CHECK_THAT(std::stod(cells(lines(k.out)[1])[2]), WithinRel(1.0, 1e-8));
}

TEST_CASE("cli setup: header, a hand-computed row and the pixel table", "[cli]") {
  // N1 = N2 = H1 = z, He tilted by 0.3 rad: A = 1, lambda = 0, gamma = 0.3, dpsi = 0.1.
  const Run r = run("setup --n1 0,0,1 --n2 0,0,1 --h1 0,0,1 --he 0.29552020666133955,0,0.9553364891256060 "
                    "--len 3 --exp 10 --pixels");
  REQUIRE(r.code == 0);
  const auto L = lines(r.out);
  REQUIRE(L.size() == 8);
  CHECK(L[0] == "A,lambda,gamma,C,psi0,dpsi");
  const auto c = cells(L[1]);
  CHECK_THAT(std::stod(c[0]), WithinRel(1.0, 1e-12));
  CHECK_THAT(std::stod(c[1]), WithinAbs(0.0, 1e-12));
  CHECK_THAT(std::stod(c[2]), WithinRel(0.3, 1e-9));
  CHECK_THAT(std::stod(c[5]), WithinRel(0.1, 1e-9));
  CHECK(L[2].empty());
  CHECK(L[3] == "i,psi,blinn,device_float,truth");
  const auto p1 = cells(L[5]);
  CHECK(p1[0] == "1");
  CHECK_THAT(std::stod(p1[2]), WithinRel(std::pow(std::cos(0.1), 10), 1e-8));
  // device: k = 16, a = sqrt(10/16)
  CHECK_THAT(std::stod(p1[3]), WithinRel(std::pow(std::cos(0.1 * std::sqrt(10.0 / 16)), 16), 1e-8));
  // truth at i = 3 is the end: (N2 . He)^10
  CHECK_THAT(std::stod(cells(L[7])[4]), WithinRel(std::pow(0.9553364891256060, 10), 1e-8));
}

TEST_CASE("cli: every kind of bad argument exits 2, names it, prints nothing on stdout", "[cli]") {
  struct Bad {
    const char* args;
    const char* names;
  };
  const std::vector<Bad> cases{
      {"", "subcommand"},
      {"frobnicate", "frobnicate"},
      {"errors --n 5", "--model"},
      {"errors --model phongx --n 5", "--model"},
      {"errors --model blinn --n 0", "--n"},
      {"errors --model blinn --n 1001", "--n"},
      {"errors --model blinn --n 5..2", "--n"},
      {"errors --model blinn --n 1,x", "--n"},
      {"errors --model blinn --n 2 --bogus 1", "--bogus"},
      {"errors --model kutlog --n 5 --k 2", "--Q"},
      {"errors --model kutlog --n 5 --Q 0.5", "--k"},
      {"errors --model kutlog --n 5 --k 9 --Q 0.5", "--k"},
      {"errors --model kutlog --n 5 --k 2 --Q 1.5", "--Q"},
      {"errors --model patent --n 5 --coef minmax", "--coef"},
      {"errors --model patent --n 5 --coef kutlog", "--Q"},
      {"errors --model schlick --n 5 --k 2", "--k"},
      {"errors --model lyon --n 5 --m 3", "--m"},
      {"krange --tol 0", "--tol"},
      {"krange --tol 2", "--tol"},
      {"krange --tol 0.01 --k 0", "--k"},
      {"albedo --model blinn --n 5 --convention foo", "--convention"},
      {"albedo --model blinn --n 5 --norm fit", "--norm"},
      {"albedo --model kutlog --n 5 --k 2 --Q 0.45 --norm fit", "--Q"},
      {"setup --n1 0,0,1 --n2 0,0,1 --h1 0,nan,1 --len 3 --exp 10", "--h1"},
      {"setup --n1 0,0 --n2 0,0,1 --h1 0,0,1 --len 3 --exp 10", "--n1"},
      {"setup --n1 0,0,0 --n2 0,0,1 --h1 0,0,1 --len 3 --exp 10", "--n1"},
      {"setup --n1 0,0,1 --n2 0,0,1 --h1 0,0,1 --len 2048 --exp 10", "--len"},
      {"setup --n1 0,0,1 --n2 0,0,1 --h1 0,0,1 --len 3 --exp 0", "--exp"},
      {"setup --n1 0,0,1 --n2 0,0,1 --h1 0,0,1 --len 3 --exp 10 --is -1", "--is"},
      {"setup --n1 0,0,1 --n2 0,0,1 --h1 0,0,1 --len 3", "--exp"},
  };
  for (const auto& b : cases) {
    const Run r = run(b.args);
    INFO("args: " << b.args << "\nstderr: " << r.err);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(b.names) != std::string::npos);
  }
  // The allowed range is named too.
  CHECK(run("errors --model blinn --n 0").err.find("1..1000") != std::string::npos);
  CHECK(run("setup --n1 0,0,1 --n2 0,0,1 --h1 0,0,1 --len 2048 --exp 10").err.find("0..2047") != std::string::npos);
}

// Speed is measured by the benchmark and the report, not asserted here (a loaded CI
// machine would make a wall-clock bound flaky).
TEST_CASE("cli: errors --model patent --n 1..1000 gives one row per n", "[cli]") {
  const Run r = run("errors --model patent --n 1..1000");
  REQUIRE(r.code == 0);
  const auto ls = lines(r.out);
  REQUIRE(ls.size() == 1001);
  for (int n = 1; n <= 1000; n += 111) CHECK(cells(ls[n])[1] == std::to_string(n));
}

// With 9 significant digits, C cos^n(psi0) recomputed from the CSV differed from
// (N1.H1)^n by up to 4e-8 relative at n = 1000. The CSV now prints the shortest text that
// parses back to the same double, so the recomputation is limited only by the setup's own
// double arithmetic: A = hypot(.,.), lambda = atan2(.,.) carry a few ulp each, raised to
// the n-th power: about n * 4 ulp = 1000 * 9e-16 ~ 1e-12. The tolerance 1e-11 is 4000 times
// tighter than the 9-digit error, so the old format fails it.
TEST_CASE("cli: setup CSV round-trips: C cos^n(psi0) from the CSV equals (N1.H1)^n", "[cli][roundtrip]") {
  struct Case {
    const char *n1, *n2, *h1;
    int n;
  };
  const Case cases[] = {
      {"0,0,1", "0.3,0,1", "0.01,0.02,1", 1000},
      {"0.1,-0.2,1", "0.3,0.1,0.9", "0.11,-0.19,1.02", 1000},
      {"0.3,0.4,0.5", "0,0.1,1", "0.31,0.39,0.52", 777},
      {"0,0,1", "0.3,0,1", "0.1,0,1", 50},
      {"1,2,3", "1,2,3.1", "1.05,2,2.9", 1},
  };
  for (const Case& c : cases) {
    const Run r = run(std::string("setup --n1 ") + c.n1 + " --n2 " + c.n2 + " --h1 " + c.h1 + " --len 16 --exp " +
                      std::to_string(c.n) + " --pixels");
    INFO("n1 " << c.n1 << " h1 " << c.h1 << " n " << c.n << "\n" << r.out);
    REQUIRE(r.code == 0);
    const auto ls = lines(r.out);
    REQUIRE(ls.size() >= 5);
    REQUIRE(ls[0] == "A,lambda,gamma,C,psi0,dpsi");
    const auto v = cells(ls[1]);
    REQUIRE(v.size() == 6);
    const long double C = std::strtold(v[3].c_str(), nullptr), psi0 = std::strtold(v[4].c_str(), nullptr);
    // (N1.H1)^n from the command-line vectors, normalized in long double.
    auto vec = [](const char* s) {
      std::vector<long double> x;
      for (const auto& t : cells(s)) x.push_back(std::strtold(t.c_str(), nullptr));
      const long double len = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      for (auto& e : x) e /= len;
      return x;
    };
    const auto N1 = vec(c.n1), H1 = vec(c.h1);
    const long double cos_t1 = N1[0] * H1[0] + N1[1] * H1[1] + N1[2] * H1[2];
    const long double want = std::pow(cos_t1, static_cast<long double>(c.n));
    const long double got = C * std::pow(std::cos(psi0), static_cast<long double>(c.n));
    REQUIRE(want > 0.05L);  // a lobe value, not an underflow
    CHECK(static_cast<double>(std::fabs(got - want) / want) < 1e-11);
    // The pixel table: blinn_0 is C cos^n(psi_0), recomputed from its own row just as tightly.
    REQUIRE(ls[3] == "i,psi,blinn,device_float,truth");
    const auto p0 = cells(ls[4]);
    const long double psi_0 = std::strtold(p0[1].c_str(), nullptr), blinn_0 = std::strtold(p0[2].c_str(), nullptr);
    CHECK(static_cast<double>(std::fabs(C * std::pow(std::cos(psi_0), static_cast<long double>(c.n)) - blinn_0) /
                              blinn_0) < 1e-11);
  }
}

// `specular setup-batch` (docs/scanline_setup.md#batched-setup).
namespace {
std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = "/tmp/specular_cli_test_" + std::to_string(::getpid()) + "_" + name;
  std::ofstream(path) << text;
  return path;
}
const std::string kSpanHeader = "n1x,n1y,n1z,n2x,n2y,n2z,h1x,h1y,h1z,hex,hey,hez,n,l,scale\n";
}  // namespace

TEST_CASE("CLI setup-batch: registers of the scalar and the batched setup, decoded values", "[cli]") {
  // N1 = N2 = H1 = He = z: A = 1, lambda = gamma = 0, so C = scale exactly rounded, psi0 = dpsi = 0.
  // The second span is N1 = -N2 (opposite_normals), the third invalid (zero normal).
  const std::string in = write_temp("spans.csv", kSpanHeader + "0,0,1,0,0,1,0,0,1,0,0,1,50,7,0.75\n"
                                                               "0,0,1,0,0,-1,0.1,0,1,0.1,0,1,50,4,1\n"
                                                               "\n"
                                                               "0,0,0,0,0,1,0,0,1,0,0,1,50,4,1\r\n");
  const Run s = run("setup-batch --in " + in + " --method scalar");
  const Run b = run("setup-batch --in " + in);
  REQUIRE(s.code == 0);
  REQUIRE(b.code == 0);
  const auto ls = lines(s.out), lb = lines(b.out);
  REQUIRE(ls.size() == 4);
  CHECK(ls[0] == "status,c_code,psi0_code,dpsi_code,n,l,C,psi0,dpsi");
  CHECK(ls[1] == "ok,24576,0,0,50,7,0.75,0,0");  // 0.75 * 2^15 = 24576
  CHECK(cells(ls[2])[0] == "opposite_normals");
  CHECK(ls[3] == "invalid_input,0,0,0,50,4,0,0,0");
  // The batch gives the same statuses; these spans are exact or hard cases, so the same codes.
  CHECK(lb == ls);
  // Decoded values are the codes times 2^-frac exactly.
  const auto c = cells(ls[2]);
  CHECK(std::stod(c[6]) == std::ldexp(std::stod(c[1]), -15));
  CHECK(std::stod(c[7]) == std::ldexp(std::stod(c[2]), -28));
  CHECK(std::stod(c[8]) == std::ldexp(std::stod(c[3]), -28));
  std::remove(in.c_str());
}

TEST_CASE("CLI setup-batch: bad input names the line and column, exit 2, nothing written", "[cli]") {
  const std::string out = "/tmp/specular_cli_test_" + std::to_string(::getpid()) + "_regs.csv";
  struct Case {
    std::string text, expect;
  };
  const std::vector<Case> cases{
      {kSpanHeader + "0,0,1,0,0,1,0,0,1,0,0,1,50,7,0.75\n0,0,1,0,0,1,0,0,1,0,x,1,50,7,1\n", ":3: column hey: 'x' is not a number"},
      {kSpanHeader + "0,0,1,0,0,1,0,0,1,0,0,1,50,7.5,1\n", ":2: column l: '7.5' is not an integer"},
      {kSpanHeader + "0,0,1,0,0,1,0,0,1,0,0,1,50,7\n", ":2: has 14 columns; expected 15"},
      {kSpanHeader + "0,0,1,0,0,1,0,0,1,0,0,1,50,7,1,2\n", ":2: has more than 15 columns"},
      {kSpanHeader + "0,0,1,0,0,1,0,0,1,0,0,1,50,,1\n", ":2: column l: '' is not a number"},
      {"n1x,n1y\n", ":1: the header must be exactly n1x,n1y,n1z"},
      {"", ":1: no header line"},
  };
  for (const auto& c : cases) {
    const std::string in = write_temp("bad.csv", c.text);
    const Run r = run("setup-batch --in " + in + " --out " + out);
    INFO(c.text);
    CHECK(r.code == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(in + c.expect) != std::string::npos);
    CHECK_FALSE(std::ifstream(out).good());
    std::remove(in.c_str());
  }
  const Run missing = run("setup-batch --in /nonexistent/spans.csv");
  CHECK(missing.code == 2);
  CHECK(missing.err.find("--in: cannot read '/nonexistent/spans.csv'") != std::string::npos);
  const std::string in = write_temp("ok.csv", kSpanHeader + "0,0,1,0,0,1,0,0,1,0,0,1,50,7,0.75\n");
  const Run method = run("setup-batch --in " + in + " --method fast");
  CHECK(method.code == 2);
  CHECK(method.err.find("--method: 'fast' is not allowed; allowed scalar, batch") != std::string::npos);
  const Run ok = run("setup-batch --in " + in + " --out " + out);
  CHECK(ok.code == 0);
  CHECK(ok.out.empty());
  std::ifstream written(out);
  std::stringstream ss;
  ss << written.rdbuf();
  CHECK(ss.str() == "status,c_code,psi0_code,dpsi_code,n,l,C,psi0,dpsi\nok,24576,0,0,50,7,0.75,0,0\n");
  std::remove(in.c_str());
  std::remove(out.c_str());
}
