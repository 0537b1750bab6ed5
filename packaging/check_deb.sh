#!/bin/sh
# Builds the .deb from a configured and built tree (plumb and plumb-cli must be built) and checks
# it: contents (binaries with the plumb-import helper for models and PCD, desktop entry, icon, MIME types for .e57/.las/.ply/.ifc and the
# project file), the Depends line computed by dpkg-shlibdeps, and the installed binaries run
# from a temporary root (plumb-cli --version and info on a real LAS file; plumb links Qt6, not
# Qt5; with a display, plumb --screenshot renders the file). Registered as the CTest
# `package_deb` (LABELS package); also usable by hand:
#   packaging/check_deb.sh BUILD_DIR [LAS_FILE]
set -eu
build=$(cd "$1" && pwd)
las=${2:-$(dirname "$0")/../../shared/data/las/1.2-with-color.las}
work=$(mktemp -d "${TMPDIR:-/tmp}/plumb-deb.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "check_deb: FAIL: $*" >&2; exit 1; }

cd "$work"
cpack -G DEB -B "$work/out" --config "$build/CPackConfig.cmake" >cpack.log 2>&1 ||
  { cat cpack.log >&2; fail "cpack failed"; }
deb=$(ls "$work"/out/*.deb 2>/dev/null | head -n 1)
[ -n "$deb" ] || fail "no .deb produced in $work/out"
echo "package: $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB)"

dpkg-deb -c "$deb" | awk '{print $NF}' >contents.txt
for f in ./usr/bin/plumb ./usr/bin/plumb-cli ./usr/bin/plumb-import ./usr/share/applications/plumb.desktop \
         ./usr/share/icons/hicolor/scalable/apps/plumb.svg ./usr/share/mime/packages/plumb.xml; do
  grep -qx "$f" contents.txt || fail "$f missing from the package"
done
echo "contents: $(wc -l <contents.txt) entries, binaries + desktop entry + icon + MIME types"

dpkg-deb -f "$deb" Package Version Architecture Depends >control.txt
cat control.txt
depends=$(sed -n 's/^Depends: //p' control.txt)
for lib in libc6 libstdc++6 libqt6widgets6 libqt6openglwidgets6 libqt6svg6 libvtk9.1 libproj25 libifcplusplus; do
  echo "$depends" | grep -q "$lib" || fail "Depends lacks $lib (shlibdeps): $depends"
done
echo "$depends" | grep -qi "qt5" && fail "Depends names a Qt5 package: $depends"

dpkg-deb -x "$deb" root
mime=root/usr/share/mime/packages/plumb.xml
for glob in '*.e57' '*.las' '*.ply' '*.ifc' '*.plumb.json'; do
  grep -qF "pattern=\"$glob\"" "$mime" || fail "MIME XML has no glob $glob"
done
desktop=root/usr/share/applications/plumb.desktop
grep -q '^Exec=plumb %F' "$desktop" || fail "desktop entry does not run plumb with files"
for type in application/x-e57 application/vnd.las application/x-ply application/x-step-ifc \
            application/x-plumb-project; do
  grep -q "^MimeType=.*$type;" "$desktop" || fail "desktop entry lacks MIME type $type"
  grep -q "type=\"$type\"" "$mime" || fail "MIME XML lacks $type"
done
desktop-file-validate "$desktop" || fail "desktop entry does not validate"

version=$(root/usr/bin/plumb-cli --version) || fail "installed plumb-cli --version failed"
echo "installed plumb-cli --version: $version"
root/usr/bin/plumb-cli info "$las" >info.txt || fail "installed plumb-cli info $las failed"
grep -q "1065" info.txt || { cat info.txt >&2; fail "plumb-cli info does not report 1065 points"; }
echo "installed plumb-cli info $(basename "$las"): 1065 points"
# Models are imported by the plumb-import helper installed next to plumb-cli.
ifc=$(dirname "$las")/../ifc/IfcOpenHouse_IFC4.ifc
if [ -f "$ifc" ]; then
  root/usr/bin/plumb-cli info "$ifc" >ifc.txt || fail "installed plumb-cli info $ifc failed (plumb-import?)"
  grep -q "IfcWall: 4" ifc.txt || { cat ifc.txt >&2; fail "plumb-cli info does not report the 4 walls"; }
  echo "installed plumb-cli info $(basename "$ifc"): 4 walls, through the installed plumb-import"
fi
# PCD files are read by PCL inside the same helper (plumb-import --pcd).
pcd=$(dirname "$las")/../pcd/room_scan1.pcd
if [ -f "$pcd" ]; then
  root/usr/bin/plumb-cli info "$pcd" >pcd.txt || fail "installed plumb-cli info $pcd failed (plumb-import --pcd?)"
  grep -q "112586" pcd.txt || { cat pcd.txt >&2; fail "plumb-cli info does not report the 112586 points"; }
  echo "installed plumb-cli info $(basename "$pcd"): 112586 points, through the installed plumb-import --pcd"
fi
ldd root/usr/bin/plumb >ldd.txt
grep -q "libQt6Widgets" ldd.txt || fail "installed plumb does not link Qt6 Widgets"
if grep -q "Qt5" ldd.txt; then grep Qt5 ldd.txt >&2; fail "installed plumb loads Qt5"; fi
grep -q "not found" ldd.txt && { grep "not found" ldd.txt >&2; fail "unresolved libraries"; }
if [ -n "${DISPLAY:-}" ]; then  # CI runs CTest under xvfb-run
  root/usr/bin/plumb --screenshot "$work/shot.png" "$las" || fail "installed plumb --screenshot failed"
  [ -s "$work/shot.png" ] || fail "installed plumb wrote no screenshot"
  echo "installed plumb --screenshot: $(du -k "$work/shot.png" | cut -f1) KiB PNG"
fi
echo "check_deb: OK"
