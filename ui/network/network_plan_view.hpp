#pragma once
// The network in plan (top view, x right, y up, in the registered frame): each placed station
// a dot in its scan colour (the reference a square) at its adjusted position, labelled; the
// links between them coloured by status (link_status.hpp): kept green, flagged orange, dropped
// red, rejected grey dashed, not accepted faint dotted, failed not drawn. Stations not placed or
// ambiguous have no position to trust: they are listed under the plan, never drawn at a made-up
// place. Clicking a station or a link selects it (the tables follow).
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

#include "ui/network/network_session.hpp"

class QPainter;

namespace plumb::ui {

class NetworkPlanView : public QWidget {
  Q_OBJECT
 public:
  explicit NetworkPlanView(QWidget* parent = nullptr);

  void setSession(std::shared_ptr<const NetworkSession> session);
  /// Highlights station i / link k (-1: none); emits nothing.
  void selectStation(int station);
  void selectLink(int link);
  int selectedStation() const { return station_; }
  int selectedLink() const { return link_; }

  /// The stations drawn (placed), and those listed under the plan (not placed, ambiguous).
  std::vector<std::size_t> drawnStations() const;
  std::vector<std::size_t> listedStations() const;
  /// Where station i is drawn, in widget coordinates (nullopt: not drawn).
  std::optional<QPointF> stationPoint(std::size_t station) const;
  /// The middle of link k's line (nullopt: not drawn).
  std::optional<QPointF> linkPoint(std::size_t link) const;
  /// The frame the plan is drawn in, written in its corner: "grid (control points)" when the
  /// run was georeferenced, else the reference's frame (empty before a run).
  QString frameLabel() const;

  QSize sizeHint() const override { return {420, 320}; }
  QSize minimumSizeHint() const override { return {200, 160}; }

 signals:
  void stationClicked(int station);
  void linkClicked(int link);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;

 private:
  struct Frame {
    double scale = 1.0;
    QPointF offset;  ///< widget point of plan (0, 0)
    QPointF map(const Eigen::Vector3d& p) const { return {offset.x() + scale * p.x(), offset.y() - scale * p.y()}; }
  };
  Frame frame() const;
  QRectF planArea() const;
  bool drawsLink(std::size_t link) const;
  QString listText() const;
  void drawLinks(QPainter& painter, const Frame& f) const;
  void drawStations(QPainter& painter, const Frame& f) const;
  void drawScaleBar(QPainter& painter, const Frame& f) const;
  std::shared_ptr<const NetworkSession> session_;
  int station_ = -1, link_ = -1;
};

}  // namespace plumb::ui
