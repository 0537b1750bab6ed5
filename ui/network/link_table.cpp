#include "ui/network/link_table.hpp"

#include <QHeaderView>

#include "ui/network/link_status.hpp"
#include "ui/network/row_table.hpp"

namespace plumb::ui {

namespace {

using row_table::cell;

/// `key` times `factor` with `decimals`, or "" when the link has no such figure.
QString figure(const nlohmann::json& link, const char* key, double factor, int decimals) {
  if (!link.contains(key)) return {};
  return QString::number(factor * link[key].get<double>(), 'f', decimals);
}

LinkDecision appliedDecision(const nlohmann::json& link) {
  const std::string d = link.value("decision", std::string());
  if (d == "accepted") return LinkDecision::Accept;
  if (d == "rejected") return LinkDecision::Reject;
  return LinkDecision::None;
}

QString decisionWord(LinkDecision d) {
  switch (d) {
    case LinkDecision::Accept: return QObject::tr("accepted");
    case LinkDecision::Reject: return QObject::tr("rejected");
    case LinkDecision::None: break;
  }
  return {};
}

}  // namespace

QString decisionText(const nlohmann::json& link, LinkDecision pending) {
  const LinkDecision applied = appliedDecision(link);
  if (applied == pending) return decisionWord(applied);
  const QString next = pending == LinkDecision::None ? QObject::tr("cleared") : decisionWord(pending);
  return QObject::tr("%1 (re-run to apply)").arg(next);
}

LinkTable::LinkTable(QWidget* parent) : QTableWidget(0, Columns, parent) {
  setObjectName("networkLinks");
  setHorizontalHeaderLabels({tr("A"), tr("B"), tr("Verdict"), tr("Method"), tr("Overlap (%)"), tr("RMS (mm)"),
                             tr("Weakest resistance"), tr("Residual (mm)"), tr("Residual (deg)"), tr("Status"),
                             tr("Decision")});
  row_table::setUp(*this);
  connect(this, &QTableWidget::itemSelectionChanged, this, [this] {
    if (!filling_) emit linkSelected(selectedLink());
  });
}

void LinkTable::setSession(std::shared_ptr<const NetworkSession> session, const NetworkDecisions& decisions) {
  const int selected = selectedLink();
  filling_ = true;
  setRowCount(session ? int(session->linkCount()) : 0);
  for (int k = 0; k < rowCount(); ++k) {
    const Link& l = session->result->links[std::size_t(k)];
    fillRow(k, session->report["links"][std::size_t(k)], decisionOf(decisions, {l.a, l.b}));
  }
  filling_ = false;
  selectLink(selected < rowCount() ? selected : -1);
}

void LinkTable::fillRow(int row, const nlohmann::json& link, LinkDecision pending) {
  setItem(row, A, cell(QString::fromStdString(link["a"].get<std::string>())));
  setItem(row, B, cell(QString::fromStdString(link["b"].get<std::string>())));
  QTableWidgetItem* verdict = cell(QString::fromStdString(link["verdict_level"].get<std::string>()));
  verdict->setToolTip(QString::fromStdString(link.value("verdict", std::string())));
  setItem(row, Verdict, verdict);
  setItem(row, Method, cell(QString::fromStdString(link.value("method", std::string()))));
  const bool registered = link.contains("transform");
  setItem(row, Overlap, cell(registered ? figure(link, "overlap", 100.0, 1) : QString()));
  setItem(row, Rms, cell(registered ? figure(link, "point_rms_m", 1000.0, 1) : QString()));
  setItem(row, Resistance, cell(registered ? figure(link, "weakest_resistance", 1.0, 3) : QString()));
  setItem(row, ResidualMm, cell(figure(link, "residual_translation_m", 1000.0, 2)));
  setItem(row, ResidualDeg, cell(figure(link, "residual_rotation_deg", 1.0, 4)));
  const LinkStatus status = linkStatus(link);
  QTableWidgetItem* s = cell(linkStatusName(status));
  s->setBackground(linkStatusColour(status).lighter(150));
  if (status == LinkStatus::Failed) s->setToolTip(QString::fromStdString(link.value("status", std::string())));
  setItem(row, Status, s);
  setItem(row, Decision, cell(decisionText(link, pending)));
}

int LinkTable::selectedLink() const { return row_table::selectedRow(*this); }

void LinkTable::selectLink(int link) { row_table::selectQuietly(*this, link); }

}  // namespace plumb::ui
