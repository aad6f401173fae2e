// report_data CLI: bad arguments exit 2 and write nothing; the hard-case section is
// complete and finite.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {
int run(const std::string& args) {
  const std::string cmd = std::string(REPORT_DATA_CLI) + " " + args + " > /dev/null 2>&1";
  const int st = std::system(cmd.c_str());
  return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}
std::filesystem::path tmp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("report_test_" + std::to_string(::getpid()) + "_" + name);
}
}  // namespace

TEST_CASE("report_data: bad arguments give exit 2 and no output file", "[report_data]") {
  const auto out = tmp_file("bad.json");
  std::filesystem::remove(out);
  for (const std::string bad : {"--n-step 0", "--n-step 1000", "--section nonsense", "--n-step x", "--bogus"}) {
    INFO(bad);
    CHECK(run(bad + " --out " + out.string()) == 2);
    CHECK_FALSE(std::filesystem::exists(out));
  }
}

TEST_CASE("report_data: hard cases are all present and finite", "[report_data]") {
  const auto out = tmp_file("hard.json");
  REQUIRE(run("--section hardcases --out " + out.string()) == 0);
  std::ifstream is(out);
  const nlohmann::json j = nlohmann::json::parse(is);
  std::filesystem::remove(out);
  const auto& cases = j.at("hardcases");
  CHECK(cases.size() >= 18);
  for (const auto& c : cases) {
    INFO(c.at("case").get<std::string>());
    CHECK(c.at("finite").get<bool>());
    // A line never exceeds C < 2 and zero-C cases output nothing.
    CHECK(c.at("device_peak").get<double>() < 2.0);
    if (c.at("C").is_number() && c.at("C").get<double>() == 0.0) CHECK(c.at("device_peak").get<double>() == 0.0);
  }
}
