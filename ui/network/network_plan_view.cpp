#include "ui/network/network_plan_view.hpp"

#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

#include "ui/layers/color_ramp.hpp"
#include "ui/network/link_status.hpp"

namespace plumb::ui {

namespace {
constexpr double kMargin = 36.0;       ///< px around the stations: room for the labels
constexpr double kStationRadius = 6.0;  ///< px
constexpr double kPickDistance = 7.0;   ///< px: a click this close selects

double segmentDistance(QPointF p, QPointF a, QPointF b) {
  const QPointF ab = b - a;
  const double len2 = QPointF::dotProduct(ab, ab);
  const double t = len2 > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  const QPointF d = p - (a + t * ab);
  return std::hypot(d.x(), d.y());
}

/// 1, 2 or 5 times a power of ten: a round scale bar length near `metres`.
double roundLength(double metres) {
  const double p = std::pow(10.0, std::floor(std::log10(metres)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= metres) return m * p;
  return p;
}

QPen linkPen(LinkStatus status, bool selected) {
  QPen pen(linkStatusColour(status), status == LinkStatus::Flagged ? 3.0 : 2.0);
  if (status == LinkStatus::Rejected) pen.setStyle(Qt::DashLine);
  if (status == LinkStatus::NotAccepted) pen.setStyle(Qt::DotLine), pen.setWidthF(1.0);
  if (selected) pen.setWidthF(pen.widthF() + 3.0);
  return pen;
}

}  // namespace

NetworkPlanView::NetworkPlanView(QWidget* parent) : QWidget(parent) {
  setObjectName("networkPlan");
  setToolTip(tr("The network in plan (top view of the registered frame). Green: kept links; orange: flagged; "
                "red: dropped; grey dashed: rejected by you; dotted: not accepted. Click a station or a link."));
}

void NetworkPlanView::setSession(std::shared_ptr<const NetworkSession> session) {
  session_ = std::move(session);
  update();
}

void NetworkPlanView::selectStation(int station) {
  station_ = station;
  link_ = -1;
  update();
}

void NetworkPlanView::selectLink(int link) {
  link_ = link;
  station_ = -1;
  update();
}

std::vector<std::size_t> NetworkPlanView::drawnStations() const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < (session_ ? session_->stationCount() : 0); ++i)
    if (session_->result->placed(i)) out.push_back(i);
  return out;
}

std::vector<std::size_t> NetworkPlanView::listedStations() const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < (session_ ? session_->stationCount() : 0); ++i)
    if (!session_->result->placed(i)) out.push_back(i);
  return out;
}

QString NetworkPlanView::listText() const {
  QStringList unplaced, ambiguous;
  for (std::size_t i : listedStations()) {
    const QString name = QString::fromStdString((*session_->stations)[i].name);
    (session_->result->isAmbiguous(i) ? ambiguous : unplaced) << name;
  }
  QStringList lines;
  if (!unplaced.isEmpty()) lines << tr("Not placed: %1").arg(unplaced.join(", "));
  if (!ambiguous.isEmpty()) lines << tr("Ambiguous (not drawn): %1").arg(ambiguous.join(", "));
  return lines.join("\n");
}

QRectF NetworkPlanView::planArea() const {
  const int lines = int(listText().count('\n')) + (listText().isEmpty() ? 0 : 1);
  return QRectF(rect()).adjusted(kMargin, kMargin, -kMargin, -kMargin - 18.0 * lines);
}

NetworkPlanView::Frame NetworkPlanView::frame() const {
  Frame f;
  const auto drawn = drawnStations();
  if (drawn.empty()) return f;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (std::size_t i : drawn) {
    const Eigen::Vector3d t = session_->result->adjustment.poses[i]->translation();
    x0 = std::min(x0, t.x()), x1 = std::max(x1, t.x()), y0 = std::min(y0, t.y()), y1 = std::max(y1, t.y());
  }
  const QRectF area = planArea();
  const double w = std::max(x1 - x0, 1.0), h = std::max(y1 - y0, 1.0);  // one station: a 1 m square
  f.scale = std::max(1e-6, std::min(area.width() / w, area.height() / h));
  const QPointF centre = area.center();
  f.offset = QPointF(centre.x() - f.scale * (x0 + x1) / 2, centre.y() + f.scale * (y0 + y1) / 2);
  return f;
}

std::optional<QPointF> NetworkPlanView::stationPoint(std::size_t station) const {
  if (!session_ || station >= session_->stationCount() || !session_->result->placed(station)) return std::nullopt;
  return frame().map(session_->result->adjustment.poses[station]->translation());
}

bool NetworkPlanView::drawsLink(std::size_t link) const {
  const Link& l = session_->result->links[link];
  const LinkStatus status = linkStatus(session_->report["links"][link]);
  return status != LinkStatus::Failed && stationPoint(l.a) && stationPoint(l.b);
}

std::optional<QPointF> NetworkPlanView::linkPoint(std::size_t link) const {
  if (!session_ || link >= session_->linkCount() || !drawsLink(link)) return std::nullopt;
  const Link& l = session_->result->links[link];
  return (*stationPoint(l.a) + *stationPoint(l.b)) / 2;
}

QString NetworkPlanView::frameLabel() const {
  if (!session_) return {};
  const auto& report = session_->report;
  if (report.contains("georeference") && report["georeference"]["done"].get<bool>()) return tr("grid (control points)");
  const auto& reference = report["stations"][session_->result->reference];
  const QString name = QString::fromStdString(reference["name"].get<std::string>());
  return reference.value("model", false) ? tr("model frame (%1)").arg(name) : tr("frame of station %1").arg(name);
}

void NetworkPlanView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.fillRect(rect(), Qt::white);
  if (!session_) {
    painter.setPen(Qt::gray);
    painter.drawText(rect(), Qt::AlignCenter, tr("Register the stations as a network to see its plan"));
    return;
  }
  const Frame f = frame();
  drawLinks(painter, f);
  drawStations(painter, f);
  drawScaleBar(painter, f);
  painter.setPen(Qt::darkGray);
  painter.drawText(QRectF(rect()).adjusted(8, 6, -8, 0), Qt::AlignLeft | Qt::AlignTop, frameLabel());
  painter.setPen(Qt::darkRed);
  const QString list = listText();
  painter.drawText(QRectF(rect()).adjusted(8, 0, -8, -6), Qt::AlignLeft | Qt::AlignBottom, list);
}

void NetworkPlanView::drawLinks(QPainter& painter, const Frame& f) const {
  const auto& links = session_->result->links;
  for (std::size_t k = 0; k < links.size(); ++k) {
    if (!drawsLink(k)) continue;
    const auto& poses = session_->result->adjustment.poses;
    painter.setPen(linkPen(linkStatus(session_->report["links"][k]), int(k) == link_));
    painter.drawLine(f.map(poses[links[k].a]->translation()), f.map(poses[links[k].b]->translation()));
  }
}

void NetworkPlanView::drawStations(QPainter& painter, const Frame& f) const {
  const auto& report = session_->report["stations"];
  for (std::size_t i : drawnStations()) {
    const QPointF p = f.map(session_->result->adjustment.poses[i]->translation());
    const Rgb c = categoryColor(session_->sources[i].colour_index);
    painter.setBrush(session_->sources[i].model ? QColor(Qt::lightGray) : QColor(c[0], c[1], c[2]));
    painter.setPen(QPen(Qt::black, int(i) == station_ ? 3.0 : 1.0));
    const QRectF dot(p.x() - kStationRadius, p.y() - kStationRadius, 2 * kStationRadius, 2 * kStationRadius);
    if (i == session_->result->reference) painter.drawRect(dot);
    else painter.drawEllipse(dot);
    QString label = QString::fromStdString(report[i]["name"].get<std::string>());
    if (report[i].value("locked", false)) label += tr(" (locked)");
    painter.drawText(p + QPointF(kStationRadius + 3, -kStationRadius - 2), label);
  }
}

void NetworkPlanView::drawScaleBar(QPainter& painter, const Frame& f) const {
  if (drawnStations().size() < 2) return;
  const double metres = roundLength(width() / 5.0 / f.scale);
  const QPointF a(rect().right() - 12 - metres * f.scale, 14), b(rect().right() - 12, 14);
  painter.setPen(QPen(Qt::black, 2));
  painter.drawLine(a, b);
  painter.drawText(QRectF(a.x(), b.y() + 2, b.x() - a.x(), 16), Qt::AlignHCenter | Qt::AlignTop,
                   tr("%1 m").arg(metres));
}

void NetworkPlanView::mousePressEvent(QMouseEvent* event) {
  if (!session_) return;
  const QPointF p = event->position();
  for (std::size_t i : drawnStations()) {
    const QPointF d = *stationPoint(i) - p;
    if (std::hypot(d.x(), d.y()) <= kStationRadius + 2) {
      selectStation(int(i));
      emit stationClicked(int(i));
      return;
    }
  }
  const Frame f = frame();
  const auto& links = session_->result->links;
  for (std::size_t k = 0; k < links.size(); ++k) {
    if (!drawsLink(k)) continue;
    const auto& poses = session_->result->adjustment.poses;
    if (segmentDistance(p, f.map(poses[links[k].a]->translation()), f.map(poses[links[k].b]->translation())) <=
        kPickDistance) {
      selectLink(int(k));
      emit linkClicked(int(k));
      return;
    }
  }
}

}  // namespace plumb::ui
