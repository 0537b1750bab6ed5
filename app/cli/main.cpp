// plumb-cli: the headless front end of the Plumb core. Same core, same results as the GUI.
#include <iostream>

#include "cli/command.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"Plumb: registration of building survey data (scans to scans, scans to BIM)",
               "plumb-cli"};
  app.set_version_flag("--version", std::string("plumb-cli ") + PLUMB_VERSION);
  app.require_subcommand(1);
  plumb::removeTemporaryFilesOnSignals();  // an interrupted write leaves no temporary file
  plumb::cli::Action action;
  // One line per subcommand (each defined in its own cli/<name>_command.cpp).
  plumb::cli::addInfoCommand(app, action);
  plumb::cli::addConvertCommand(app, action);
  plumb::cli::addFeaturesCommand(app, action);
  plumb::cli::addSimulateCommand(app, action);
  plumb::cli::addRegisterCommand(app, action);
  plumb::cli::addNetworkCommand(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return action ? action() : 0;
  } catch (const plumb::Canceled&) {
    std::cerr << "plumb-cli: cancelled\n";
    return 130;
  } catch (const std::exception& e) {
    std::cerr << "plumb-cli: error: " << e.what() << "\n";
    return 1;
  }
}
