#!/usr/bin/env bash
# Installs towdb's build and test dependencies from Debian packages (Debian 12).
# Idempotent: packages already present are left alone; apt-get is skipped
# entirely when nothing is missing. Needs root (or sudo) only when something
# must be installed.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev        # linear algebra
  libsqlite3-dev sqlite3
  libssl-dev           # SHA-256 content hashes (libcrypto)
  libfftw3-dev         # FFTs for the sea records
  libcli11-dev         # command-line parsing
  libtomlplusplus-dev  # ship and sweep files
  nlohmann-json3-dev   # JSON output
  libgtest-dev libgmock-dev
  libbenchmark-dev
  libopenmpi-dev openmpi-bin   # distributed builds (TOWDB_MPI)
  gnuplot-nox          # PNG plots (towdb simulate --plot, towdb plan)
  libcpp-httplib-dev   # towdb serve
  libjs-chart.js       # the charts of towdb serve's page, served locally
  python3-dev pybind11-dev   # the Python module (TOWDB_PYTHON)
  python3-pytest python3-pandas   # its tests (and the DataFrame it returns)
  chromium chromium-driver python3-selenium   # the page's test in headless Chromium
  xz-utils             # scripts/pack-db.sh: the bundled database's archive (db/README.md)
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
