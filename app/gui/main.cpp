// plumb: the desktop application.
//   plumb [FILE...] [--project P.plumb.json] [--register S,T] [--screenshot OUT.png]
// FILEs are scans or models (a *.plumb.json is opened as a project); --register registers file
// S onto file T after loading; --screenshot renders the view into OUT.png and exits (tests,
// documentation).
#include <QApplication>
#include <QCommandLineParser>

#include <iostream>
#include <optional>

#include "common/atomic_file.hpp"
#include "ui/main_window.hpp"
#include "ui/startup_run.hpp"
#include "ui/view/surface_format.hpp"

namespace {

void setApplicationInfo() {
  QCoreApplication::setOrganizationName("Plumb");
  QCoreApplication::setApplicationName("plumb");
  QCoreApplication::setApplicationVersion(PLUMB_VERSION);
}

/// The options of the command line (the parser reads their values through them).
struct CommandLine {
  QCommandLineOption screenshot{"screenshot", "Render the view into OUT.png and exit.", "OUT.png"};
  QCommandLineOption size{"size", "Window size for --screenshot (default 1280x800).", "WxH", "1280x800"};
  QCommandLineOption project{"project", "Open a project file (*.plumb.json).", "FILE"};
  QCommandLineOption reg{"register",
                         "After loading, register file SOURCE onto file TARGET (0-based indices "
                         "of the files given, or of a project's layers).",
                         "SOURCE,TARGET"};
  QCommandLineOption whole{"screenshot-window",
                           "With --screenshot: capture the whole window (docks included)."};
};

void describe(QCommandLineParser& parser, const CommandLine& c) {
  parser.setApplicationDescription(
      "Plumb: registration of building survey data (scans to scans, scans to BIM)");
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addOptions({c.screenshot, c.size, c.project, c.reg, c.whole});
  parser.addPositionalArgument("files", "Scans (E57, LAS, PLY, PCD, XYZ) or models (IFC, OBJ...).",
                               "[FILES...]");
}

/// What to do at startup; nullopt (after an error on stderr) when --register is malformed.
std::optional<plumb::ui::StartupOptions> startupOptions(const QCommandLineParser& parser,
                                                        const CommandLine& c) {
  plumb::ui::StartupOptions options;
  options.files = parser.positionalArguments();
  options.project = parser.value(c.project);
  for (const QString& f : parser.positionalArguments())
    if (f.endsWith(".plumb.json", Qt::CaseInsensitive) && options.project.isEmpty()) {
      options.project = f;
      options.files.removeAll(f);
    }
  options.screenshot = parser.value(c.screenshot);
  options.whole_window = parser.isSet(c.whole);
  if (parser.isSet(c.reg)) {
    options.register_pair = plumb::ui::parseRegisterPair(parser.value(c.reg));
    if (!options.register_pair) {
      std::cerr << "plumb: error: --register expects SOURCE,TARGET indices, e.g. 0,1\n";
      return std::nullopt;
    }
  }
  return options;
}

/// --size WxH (for --screenshot); false (after an error on stderr) when malformed.
bool resizeWindow(plumb::ui::MainWindow& window, const QString& size) {
  const QStringList wh = size.split('x');
  if (wh.size() != 2 || wh[0].toInt() <= 0 || wh[1].toInt() <= 0) {
    std::cerr << "plumb: error: --size expects WxH, e.g. 1280x800\n";
    return false;
  }
  window.resize(wh[0].toInt(), wh[1].toInt());
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  plumb::ui::setDefaultSurfaceFormat();  // before QApplication (docs/QT_VTK.md)
  QApplication app(argc, argv);
  // A session ended by SIGTERM/SIGINT/SIGHUP (logout, kill) during an export leaves no
  // temporary file next to the user's data, as with plumb-cli.
  plumb::removeTemporaryFilesOnSignals();
  setApplicationInfo();

  QCommandLineParser parser;
  const CommandLine command_line;
  describe(parser, command_line);
  parser.process(app);
  const auto options = startupOptions(parser, command_line);
  if (!options) return 2;
  // A batch run (--screenshot: tests, documentation) keeps its settings apart from the user's:
  // it must not rewrite their recent files or remembered folders.
  if (!options->screenshot.isEmpty()) QCoreApplication::setOrganizationName("Plumb-batch");

  plumb::ui::MainWindow window;
  if (!options->screenshot.isEmpty() && !resizeWindow(window, parser.value(command_line.size))) return 2;
  window.show();
  auto* run = new plumb::ui::StartupRun(window, *options, &window);
  run->start();
  return QApplication::exec();
}
