// Command-line parsing shared by the tools (model/tools/*, sim_regression): help exits 0,
// a bad argument exits 2 with "<tool>: error: <what>" on stderr, the project's contract
// for bad input. Header-only so that the model library itself does not need CLI11.
#pragma once

#include <CLI/CLI.hpp>

#include <iostream>
#include <optional>
#include <string_view>

namespace specular {

// The exit code when parsing ends the program (help, bad argument); nothing when the
// program should go on.
inline std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv, std::string_view tool) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << tool << ": error: " << e.what() << " (see " << tool << " --help)\n";
    return 2;
  }
  return std::nullopt;
}

}  // namespace specular
