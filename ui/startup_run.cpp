#include "ui/startup_run.hpp"

#include <QCoreApplication>
#include <QTimer>

#include <iostream>

#include "common/error.hpp"
#include "registration/auto/registration_pipeline.hpp"

#include "ui/layers/layer_transform.hpp"
#include "ui/layers/scene.hpp"
#include "ui/main_window.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/project/project_file.hpp"
#include "ui/registration/registration_panel.hpp"
#include "ui/tasks/load_files.hpp"
#include "ui/view/screenshot.hpp"
#include "ui/view/scene_framing.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {


std::optional<std::pair<int, int>> parseRegisterPair(const QString& text) {
  const QStringList parts = text.split(',');
  if (parts.size() != 2) return std::nullopt;
  bool a_ok = false, b_ok = false;
  const int a = parts[0].trimmed().toInt(&a_ok), b = parts[1].trimmed().toInt(&b_ok);
  if (!a_ok || !b_ok || a < 0 || b < 0) return std::nullopt;
  return std::pair{a, b};
}

StartupRun::StartupRun(MainWindow& window, StartupOptions options, QObject* parent)
    : QObject(parent), window_(window), options_(std::move(options)) {
  if (!options_.screenshot.isEmpty())
    connect(&window_.context().log, &LogPanel::logged, this,
            [](LogLevel level, const QString& message) {
              if (level == LogLevel::Error)
                std::cerr << "plumb: error: " << message.toStdString() << "\n";
            });
}

void StartupRun::start() {
  AppContext& app = window_.context();
  if (!options_.project.isEmpty()) {
    try {
      openProject(app, options_.project,
                  [this](bool ok, const std::vector<Layer*>& layers) {
                    layers_ = layers;
                    loaded(ok);
                  });
    } catch (const std::exception& e) {
      app.log.error(QString::fromUtf8(e.what()));
      QTimer::singleShot(0, this, [this] { finish(false); });
    }
    return;
  }
  if (options_.files.isEmpty()) {
    QTimer::singleShot(0, this, [this] { loaded(true); });
    return;
  }
  layers_.assign(std::size_t(options_.files.size()), nullptr);
  remaining_ = int(options_.files.size());
  loadFiles(
      app, options_.files,
      [this](Layer& layer, const QString& path) {
        for (int i = 0; i < options_.files.size(); ++i)
          if (options_.files[i] == path && !layers_[std::size_t(i)]) {
            layers_[std::size_t(i)] = &layer;
            break;
          }
      },
      [this](const QString&, bool ok) {
        ok_ = ok_ && ok;
        if (--remaining_ == 0) loaded(ok_);
      });
}

void StartupRun::loaded(bool ok) {
  ok_ = ok_ && ok;
  if (options_.register_pair && ok_) {
    registerPair();
    return;
  }
  if (options_.register_pair) window_.context().log.error(tr("--register: not every file loaded"));
  finish(ok_ && !options_.register_pair);
}

void StartupRun::registerPair() {
  AppContext& app = window_.context();
  const auto [s, t] = *options_.register_pair;
  // Files: command-line order; project: its layers' order.
  const std::vector<Layer*>& layers = layers_;
  const int n = int(layers.size());
  if (s >= n || t >= n || s == t || !layers[std::size_t(s)] || !layers[std::size_t(t)]) {
    app.log.error(tr("--register %1,%2: needs two different indices below %3").arg(s).arg(t).arg(n));
    finish(false);
    return;
  }
  RegistrationPanel& panel = *app.registration;
  panel.setSourceLayer(layers[std::size_t(s)]);
  panel.setTargetLayer(layers[std::size_t(t)]);
  connect(&panel, &RegistrationPanel::registrationFinished, this, [this](bool success) {
    finish(success);
  }, Qt::QueuedConnection);
  if (!panel.startRegistration()) finish(false);
}

int StartupRun::exitCode(bool ok) const {
  const int plain = ok && window_.context().log.errorCount() == 0 ? 0 : 1;
  const auto result = options_.register_pair ? window_.context().registration->lastResult() : nullptr;
  if (!result) return plain;
  // The registration ran: its verdict level decides (2 failed or ambiguous, 3 check visually),
  // as for plumb-cli register; a usable one still exits 1 when something else went wrong.
  const int level = verdictExitCode(result->report.level);
  return level != 0 ? level : plain;
}

void StartupRun::finish(bool ok) {
  if (options_.screenshot.isEmpty()) {
    deleteLater();
    return;
  }
  AppContext& app = window_.context();
  frameScene(app.scene, app.view);
  // After a registration: frame the registered source (far-reaching outdoor scans would make
  // the building a speck).
  RegistrationPanel& panel = *app.registration;
  if (options_.register_pair && panel.sourceLayer() && panel.targetLayer()) {
    // The bulk of the registered source, with a margin (scans see far ground through windows).
    Bounds b = bulkBounds(*panel.sourceLayer());
    const Eigen::Vector3d margin = 0.15 * b.size();
    b.extend(Eigen::Vector3d(b.min - margin));
    b.extend(Eigen::Vector3d(b.max + margin));
    double rb[6];
    app.scene.renderBounds(b, rb);
    applyStandardView(app.view.renderer(), StandardView::Iso);
    zoomToBounds(app.view.renderer(), rb);
  }
  int code = exitCode(ok);
  try {
    if (options_.whole_window) {
      grabView(app.view);  // renders the view first
      if (!window_.grab().save(options_.screenshot, "PNG"))
        throw FileError(options_.screenshot.toStdString(), "cannot write the PNG");
    } else {
      saveScreenshot(app.view, options_.screenshot);
    }
  } catch (const std::exception& e) {
    std::cerr << "plumb: error: " << e.what() << "\n";
    code = 1;
  }
  QCoreApplication::exit(code);
}

}  // namespace plumb::ui
