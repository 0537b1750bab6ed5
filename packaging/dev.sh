#!/usr/bin/env bash
# Plumb developer entry point (Debian 12, as root or with sudo).
#   packaging/dev.sh demo   install dependencies, build, run the demo registration
#                           (the GUI when a display exists, headless otherwise)
#   packaging/dev.sh test   install dependencies, build, run the whole test suite
#   packaging/dev.sh deps | build | package
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD=${PLUMB_BUILD_DIR:-$ROOT/build}
JOBS=${PLUMB_JOBS:-$(nproc)}
# ccache: paths under the checkout are hashed relative to it, and the working directory is not
# hashed, so a fresh clone elsewhere (CI's) and git worktrees reuse this machine's cache; the
# sanitizer, TSan and fuzz trees need more than the default 5 GB.
export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$ROOT}
export CCACHE_NOHASHDIR=${CCACHE_NOHASHDIR:-1}
export CCACHE_MAXSIZE=${CCACHE_MAXSIZE:-25G}

# Every dependency is a Debian 12 package (see README.md "Dependencies").
PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config git
  libeigen3-dev libpcl-dev libcgal-dev libassimp-dev libtbb-dev libembree-dev
  nlohmann-json3-dev libpugixml-dev libcli11-dev libproj-dev libceres-dev libifcplusplus-dev
  libopen3d-dev
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev qt6-svg-dev libvtk9-dev
  libgtest-dev libgmock-dev
  clang libclang-rt-14-dev
  xvfb xauth libgl1-mesa-dri desktop-file-utils strace chromium poppler-utils
)

deps() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if ((${#missing[@]})); then
    echo "== installing: ${missing[*]}"
    local SUDO=""
    [[ $(id -u) -ne 0 ]] && SUDO=sudo
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
  fi
}

build() {
  # The desktop app and its GUI tests are part of every build, and the whole suite runs under
  # the sanitizers too (a cached OFF of an older tree must not drop them).
  cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=Release -DPLUMB_BUILD_UI=ON \
    -DPLUMB_SANITIZE_SUITE=ON
  cmake --build "$BUILD" -j "$JOBS"
}

have_display() { [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; }

demo() {
  deps
  build
  local out="$BUILD/demo-output"
  # Simulated survey of the "house" preset: indoor TLS (perturbed), outdoor MMS, the BIM model.
  "$BUILD/app/plumb-cli" simulate --demo -o "$out" "$@"
  # A project with the three layers (the model hidden; the indoor scans register onto the
  # outdoor MMS through the windows and doors, 2023 §III).
  cat > "$out/demo.plumb.json" <<'JSON'
{"plumb-project": 1,
 "layers": [{"file": "indoor.e57"}, {"file": "outdoor.e57"},
            {"file": "model.ply", "visible": false}],
 "registration": {"source": 0, "target": 1, "params": {"method": "auto"}}}
JSON
  if have_display && [[ -x "$BUILD/app/plumb" ]]; then
    exec "$BUILD/app/plumb" --project "$out/demo.plumb.json" --register 0,1
  fi
  # Exit 0 usable, 3 check visually (results written, warnings on stderr), 2 failed.
  local status=0
  "$BUILD/app/plumb-cli" register "$out/indoor.e57" "$out/outdoor.e57" \
    --transform "$out/indoor_to_outdoor.json" --report "$out/report.json" \
    -o "$out/indoor_registered.e57" || status=$?
  if [[ $status -eq 3 ]]; then
    echo "demo: the registration is written but asks for a visual check (exit 3)" >&2
  elif [[ $status -ne 0 ]]; then
    return "$status"
  fi
}

run_tests() {
  deps
  build
  cd "$BUILD"
  # GUI tests need a display: CI has none, so every test runs under a virtual X server.
  local runner=()
  have_display || runner=(xvfb-run -a -s "-screen 0 1280x1024x24")
  "${runner[@]}" ctest --output-on-failure -j "$JOBS" --timeout 900 "$@"
}

case "${1:-}" in
  deps) deps ;;
  build) deps; build ;;
  demo) shift; demo "$@" ;;
  test) shift; run_tests "$@" ;;
  package) deps; build; cmake --build "$BUILD" --target package ;;
  *) sed -n '2,7p' "$0"; exit 2 ;;
esac
