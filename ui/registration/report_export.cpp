#include "ui/registration/report_export.hpp"

#include "common/error.hpp"
#include "registration/auto/registration_input.hpp"
#include "report/report_file.hpp"
#include "ui/app_context.hpp"
#include "ui/panels/log_panel.hpp"
#include "ui/registration/registration_runner.hpp"
#include "ui/registration/registration_tasks.hpp"
#include "ui/registration/report_pdf.hpp"
#include "ui/tasks/task_manager.hpp"

namespace plumb::ui {

namespace {
/// The layer the record names, placed where it was when the registration started.
LayerData placedData(const LayerRef& ref, const RigidTransform& to_world) {
  const Layer* layer = ref.get();
  if (!layer)
    throw InputError("export report: a layer the last registration ran on was removed");
  LayerData d = dataOf(*layer);
  d.to_world = to_world;
  return d;
}

/// The report file at `path`: PDF here (Qt draws it), JSON or HTML by the core.
void writeReport(const QString& path, const LayerData& source, const LayerData& target,
                 const PipelineResult& result, std::uint64_t seed, Progress& progress) {
  const RegistrationInput s = inputOf(source, source.to_world);
  const RegistrationInput t = inputOf(target, target.to_world);
  const std::string file = path.toStdString(), s_name = source.name.toStdString(),
                    t_name = target.name.toStdString();
  if (report::isPdfReportPath(file))
    writeReportPdf(path, report::reportOfRegistration(s, t, s_name, t_name, result, seed, &progress));
  else
    report::writeReportFile(file, s, t, s_name, t_name, result, seed, &progress);
}
}  // namespace

Task* exportRegistrationReport(AppContext& app, const RegistrationRecord& record,
                               const QString& path) {
  if (!record.result)
    throw InputError("export report: no registration result (register first; an undone or "
                     "withdrawn result has no report)");
  report::checkReportPath(path.toStdString(), "export report:", true);
  const LayerData source = placedData(record.source, record.source_start);
  LayerData target = placedData(record.target, record.target_start);
  target.elements = record.target_elements;  // the report says what the registration rested on
  const auto result = record.result;
  const std::uint64_t seed = record.seed;
  Task* task = app.tasks.run(QObject::tr("Exporting the registration report"),
                             [source, target, result, seed, path](Progress& progress) -> Task::Apply {
                               writeReport(path, source, target, *result, seed, progress);
                               return {};
                             });
  QObject::connect(task, &Task::finished, &app.log, [&app, path](bool ok, const QString& msg) {
    if (ok) app.log.info(QObject::tr("Registration report written to %1").arg(path));
    else app.log.error(QObject::tr("Cannot write %1: %2").arg(path, msg));
  });
  return task;
}

}  // namespace plumb::ui
