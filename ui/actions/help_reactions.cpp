#include "ui/actions/help_reactions.hpp"

#include <QMainWindow>
#include <QMessageBox>

#include "ui/app_context.hpp"

namespace plumb::ui {
namespace {

QString gettingStarted() {
  return QObject::tr(
      "<b>Register a scan onto another scan or a BIM</b><ol>"
      "<li><b>File &gt; Open</b> (or drop files on the window): scans (E57, LAS, PLY, PCD, XYZ) and "
      "models (IFC, OBJ, PLY mesh).</li>"
      "<li>In the <b>Registration</b> panel choose the <i>source</i> (the scan to move) and the "
      "<i>target</i> (the reference: another scan, the MMS pass or the BIM).</li>"
      "<li><b>Registration &gt; Detect features</b> shows the planes, openings and edges found; adjust "
      "the thresholds if walls or windows are missing.</li>"
      "<li><b>Registration &gt; Register</b>. The quality panel gives the verdict: <i>usable</i>, "
      "<i>check visually</i> or <i>failed</i>, with the figures behind it.</li>"
      "<li><b>Colour by distance</b> to check the fit, then <b>Accept</b> or <b>Revert</b>.</li>"
      "<li><b>File &gt; Export registered cloud</b>, <b>Export transform</b> and <b>Export "
      "registration report</b> (HTML to hand over).</li></ol>"
      "The same runs headless: <tt>plumb-cli register SOURCE TARGET --report R.html</tt>; a campaign "
      "of stations: <tt>plumb-cli network</tt>.");
}

QString about() {
  return QObject::tr(
             "<b>Plumb %1</b><br>Registration of building surveys: indoor scans to outdoor scans, scans "
             "to BIM, and campaigns of stations as one network.<br><br>Methods: planar-polygon "
             "matching (2021) and a robust distance between 3D segment sets minimised by RANSAC "
             "(2023), with Plumb's own verdict evidence.<br><br>Built on Qt, VTK, PCL, CGAL, Eigen, "
             "Embree, TBB, Ceres, PROJ and assimp.")
      .arg(PLUMB_UI_VERSION);
}

}  // namespace

HelpReaction::HelpReaction(QAction* action, AppContext& app, Topic topic) : Reaction(action, app), topic_(topic) {}

void HelpReaction::onTriggered() {
  const bool start = topic_ == Topic::GettingStarted;
  auto* box = new QMessageBox(QMessageBox::Information, start ? tr("Getting started") : tr("About Plumb"),
                              start ? gettingStarted() : about(), QMessageBox::Close, &app().window);
  box->setObjectName(start ? "gettingStarted" : "aboutPlumb");
  box->setTextFormat(Qt::RichText);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->setModal(false);
  box->show();
}

}  // namespace plumb::ui
