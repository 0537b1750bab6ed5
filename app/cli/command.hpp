#pragma once
// Each plumb-cli subcommand lives in its own file and registers itself with CLI11 through one
// function declared here. main.cpp calls them all; a command's handler returns the exit code.
#include <CLI/CLI.hpp>

#include <functional>

namespace plumb::cli {

/// Set by a subcommand's callback; main() runs it after parsing.
using Action = std::function<int()>;

// void addInfoCommand(CLI::App& app, Action& action);   (one declaration per subcommand)
void addInfoCommand(CLI::App& app, Action& action);
void addConvertCommand(CLI::App& app, Action& action);
void addFeaturesCommand(CLI::App& app, Action& action);
void addSimulateCommand(CLI::App& app, Action& action);
void addRegisterCommand(CLI::App& app, Action& action);
void addNetworkCommand(CLI::App& app, Action& action);

}  // namespace plumb::cli
