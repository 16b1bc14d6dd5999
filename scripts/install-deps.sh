#!/usr/bin/env bash
# Installs the Debian 12 packages that collide's build, tests and reports need, then the npm
# packages of the engines in engines/ (`npm ci`: the versions of engines/package-lock.json; the
# one place npm packages enter the project, docs/engines.md).
# Idempotent: packages already present are skipped and `apt-get update` runs at most once.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"

packages=(
  build-essential cmake git pkg-config
  libeigen3-dev libbox2d-dev libchipmunk-dev libgsl-dev libgtest-dev libhdf5-dev hdf5-tools
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
  ocl-icd-opencl-dev opencl-c-headers opencl-clhpp-headers pocl-opencl-icd clinfo
  clang libclang-rt-14-dev libomp-dev
  python3 python3-matplotlib python3-numpy python3-scipy python3-mpmath python3-h5py python3-jinja2
  python3-dev pybind11-dev python3-pybind11 python3-pytest
  chromium chromium-driver python3-selenium
  libopenmpi-dev openmpi-bin
  libsdl2-dev libpng-dev libgif-dev python3-pil
  python3-gsd python3-meshio python3-ase
)

# Node and npm for the engines: Debian's, unless a node and npm are already on PATH (NodeSource's
# nodejs package brings its own npm and conflicts with Debian's).
if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  packages+=(nodejs npm)
fi

# The engines' npm packages, as pinned; skipped when node_modules was installed from this lock.
install_engines() {
  local lock="$here/engines/package-lock.json" installed="$here/engines/node_modules/.package-lock.json"
  if [ -f "$installed" ] && [ "$installed" -nt "$lock" ]; then
    echo "install-deps: engines/node_modules is up to date"
    return
  fi
  echo "install-deps: npm ci in engines/"
  (cd "$here/engines" && npm ci --no-audit --no-fund)
}

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  install_engines
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages: ${missing[*]}" >&2
  echo "install-deps: run as root (or with sudo) to install them" >&2
  exit 1
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
install_engines
