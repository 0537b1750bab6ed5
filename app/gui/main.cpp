// plumb: the desktop application. `plumb FILE...` opens files; `plumb --screenshot OUT.png
// FILE...` renders them and exits (tests, documentation).
#include <QApplication>
#include <QCommandLineParser>

#include <iostream>

#include "ui/main_window.hpp"
#include "ui/screenshot_run.hpp"
#include "ui/view/surface_format.hpp"

int main(int argc, char** argv) {
  plumb::ui::setDefaultSurfaceFormat();  // before QApplication (QT_VTK_NOTES.md)
  QApplication app(argc, argv);
  QCoreApplication::setOrganizationName("Plumb");
  QCoreApplication::setApplicationName("plumb");
  QCoreApplication::setApplicationVersion(PLUMB_VERSION);

  QCommandLineParser parser;
  parser.setApplicationDescription(
      "Plumb: registration of building survey data (scans to scans, scans to BIM)");
  parser.addHelpOption();
  parser.addVersionOption();
  QCommandLineOption screenshot("screenshot", "Render the files into OUT.png and exit.", "OUT.png");
  QCommandLineOption size("size", "Window size for --screenshot (default 1280x800).", "WxH",
                          "1280x800");
  parser.addOption(screenshot);
  parser.addOption(size);
  parser.addPositionalArgument("files", "Scans (E57, LAS, PLY, PCD, XYZ) or models (IFC, OBJ...).",
                               "[FILES...]");
  parser.process(app);

  plumb::ui::MainWindow window;
  if (parser.isSet(screenshot)) {
    const QStringList wh = parser.value(size).split('x');
    if (wh.size() != 2 || wh[0].toInt() <= 0 || wh[1].toInt() <= 0) {
      std::cerr << "plumb: error: --size expects WxH, e.g. 1280x800\n";
      return 2;
    }
    window.resize(wh[0].toInt(), wh[1].toInt());
    window.show();
    auto* run = new plumb::ui::ScreenshotRun(window, parser.value(screenshot), &window);
    run->start(parser.positionalArguments());
    return QApplication::exec();
  }
  window.show();
  window.openFiles(parser.positionalArguments());
  return QApplication::exec();
}
