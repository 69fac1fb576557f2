// The `sweep` and `export` subcommands of the isopound command line (parametric studies).
// Exit codes as the rest of the CLI: 0 ok, 1 failure, 2 bad input (file:line:col: key: what), 130
// interrupted.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <optional>

namespace isopound {

struct StudyCommandOptions;  // filled by the parser (study_cli.cpp)

struct StudyCommands {
  CLI::App* sweep = nullptr;
  CLI::App* export_tables = nullptr;
  std::shared_ptr<StudyCommandOptions> options;
};

// Registers `sweep` and `export` on the app; call before parsing.
StudyCommands add_study_commands(CLI::App& app);

// After parsing: runs the study subcommand that was chosen and returns its exit code, or
// nullopt when another subcommand was chosen.
std::optional<int> run_study_command(const StudyCommands& commands);

}  // namespace isopound
