// Image baselines of the handed-over report's pictures (issue 17): a report built by the core
// report builder from a fixed room (scan with seeded noise, triangle model, known transform,
// planes with known offsets) has its four SVG pictures (plan view, section through the overlap,
// distance histogram, per-feature residuals) drawn by QSvgRenderer as a browser would, and each
// drawing is compared with tests/gui/baselines/report_<name>.png (gui/image_baseline.hpp for the
// tolerance; PLUMB_UPDATE_BASELINES=1 rewrites them). Failed comparisons keep their pictures
// under <build>/test-artifacts/gui_report_pictures/.
#include <QPainter>
#include <QSvgRenderer>
#include <QTest>

#include <random>

#include "gui/image_baseline.hpp"
#include "gui/open_window.hpp"
#include "gui/room_scene.hpp"
#include "report/report_builder.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

/// At most this fraction of a picture's pixels may differ from its baseline. Tighter than the
/// 3D views' default: the plan and the section are sparse dots on white, so a source drawn
/// 30 cm off changes only about half a percent of the pixels; QSvgRenderer with the same fonts
/// draws the same pixels run after run.
constexpr double kMaxDiffering = 0.002;

/// The source's pose in the target's frame: the report moves the source by its inverse.
const RigidTransform kScanPose = RigidTransform::fromYaw(0.3, Eigen::Vector3d(2.0, -1.0, 0.5));

/// The room scan, every 10 cm, each point moved by up to 8 mm along x, y, z (fixed seed).
PointCloud noisyRoomScan() {
  PointCloud cloud = test::roomScan(0.1, kScanPose, "room_scan")->scans.front().cloud;
  std::mt19937 random(17);
  const auto jitter = [&random] { return float(0.008 * (double(random()) / double(random.max()) * 2.0 - 1.0)); };
  for (auto& p : cloud.positions) p += Eigen::Vector3f(jitter(), jitter(), jitter());
  return cloud;
}

PlanarPolygon plane(const Eigen::Vector3d& normal, const Eigen::Vector3d& centroid, double area) {
  PlanarPolygon p;
  p.normal = normal;
  p.centroid = p.origin = centroid;
  p.offset = normal.dot(centroid);
  p.area = area;
  return p;
}

/// The room's six faces as target planes; the source's are the same faces `i + 1` mm off
/// along their normals, in the scan's frame.
void roomPlanes(FeatureSet& source, FeatureSet& target) {
  const std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> faces = {
      {Eigen::Vector3d::UnitX(), {0, 3, 1.5}}, {-Eigen::Vector3d::UnitX(), {8, 3, 1.5}},
      {Eigen::Vector3d::UnitY(), {4, 0, 1.5}}, {-Eigen::Vector3d::UnitY(), {4, 6, 1.5}},
      {Eigen::Vector3d::UnitZ(), {4, 3, 0}},   {-Eigen::Vector3d::UnitZ(), {4, 3, 3}}};
  const RigidTransform to_scan = kScanPose;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const auto& [n, c] = faces[i];
    target.planes.push_back(plane(n, c, 20.0));
    const Eigen::Vector3d moved = c + 0.001 * double(i + 1) * n;
    source.planes.push_back(plane(to_scan.rotation() * n, to_scan.apply(moved), 20.0));
  }
}

/// What QSvgRenderer draws of `svg` on white, at the size the SVG declares (fixed by
/// svg_plots: 640 x 480 for the scatters, 640 x 300 for the bar charts).
QImage draw(const std::string& svg) {
  QSvgRenderer renderer(QByteArray::fromStdString(svg));
  if (!renderer.isValid()) return {};
  QImage image(renderer.defaultSize(), QImage::Format_RGB32);
  image.fill(Qt::white);
  QPainter painter(&image);
  renderer.render(&painter);
  return image;
}

}  // namespace

class GuiReportPicturesTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    source_ = noisyRoomScan();
    model_ = test::roomModel();
    PipelineResult result;
    result.report.success = true;
    result.report.level = VerdictLevel::Usable;
    result.report.transform = kScanPose.inverse();
    roomPlanes(result.source_features, result.target_features);
    report::ReportInputs inputs;
    inputs.source_file = "room_scan.e57", inputs.target_file = "room.ifc";
    inputs.source = &source_;
    inputs.target_model = model_.get();
    inputs.seed = 5;
    report_ = report::buildRegistrationReport(inputs, result);
    artefacts_ = test::scratchDir("gui_report_pictures");
    QCOMPARE(report_.pictures.size(), std::size_t(4));
  }

  void thePlanViewMatchesItsBaseline() { expectBaseline(0, "report_plan", QSize(640, 480)); }
  void theSectionMatchesItsBaseline() { expectBaseline(1, "report_section", QSize(640, 480)); }
  void theDistanceHistogramMatchesItsBaseline() { expectBaseline(2, "report_histogram", QSize(640, 300)); }

  // Six bars, 1 to 6 mm: the planes' offsets.
  void theResidualPlotMatchesItsBaseline() {
    QCOMPARE(report_.residuals.size(), std::size_t(6));
    for (std::size_t i = 0; i < 6; ++i) QVERIFY(std::abs(report_.residuals[i].distance_m - 0.001 * double(i + 1)) < 1e-6);
    expectBaseline(3, "report_residuals", QSize(640, 300));
  }

  // A changed picture does not pass: the plan view with the source 30 cm off, or the
  // histogram of other distances, differs from the drawings of this report.
  void aChangedPictureIsReportedAsDifferent() {
    const QImage plan = draw(report_.pictures[0].svg);
    QCOMPARE(test::compareImages(plan, plan).differing, 0.0);
    std::vector<Eigen::Vector3d> source, target;
    for (std::size_t i = 0; i < source_.size(); ++i) source.push_back(kScanPose.inverse().apply(source_.world(i)));
    for (const auto& v : model_->mesh.vertices) target.push_back(v);
    for (auto& p : source) p.x() += 0.3;
    expectDifferent(draw(report::planPicture(source, target).svg), plan);

    report::DistanceSummary other = report_.distances;
    std::reverse(other.histogram.begin(), other.histogram.end());
    expectDifferent(draw(report::histogramPicture(other).svg), draw(report_.pictures[2].svg));
  }

 private:
  void expectBaseline(std::size_t picture, const QString& name, QSize size) {
    const QImage image = draw(report_.pictures[picture].svg);
    QVERIFY2(!image.isNull(), qPrintable(name + ": QSvgRenderer cannot read the SVG"));
    QCOMPARE(image.size(), size);
    const test::BaselineCheck check = test::checkBaseline(image, name, artefacts_, kMaxDiffering);
    QVERIFY2(check.ok, qPrintable(check.message));
  }

  static void expectDifferent(const QImage& changed, const QImage& original) {
    const test::ImageDifference d = test::compareImages(changed, original);
    QVERIFY(d.problem.isEmpty());
    QVERIFY2(d.differing > kMaxDiffering, qPrintable(QString::number(d.differing)));
  }

  PointCloud source_;
  std::shared_ptr<const BimModel> model_;
  report::RegistrationReport report_;
  std::filesystem::path artefacts_;
};

int main(int argc, char** argv) { return test::runGuiTest<GuiReportPicturesTest>(argc, argv); }

#include "test_gui_report_pictures.moc"
