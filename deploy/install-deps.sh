#!/usr/bin/env bash
# Installs every Debian 12 package Kontakt needs to build, test and compare against ccx.
# Idempotent: does nothing when all packages are present. Needs root (or sudo).
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libsuitesparse-dev libopenblas-dev
  libboost-dev nlohmann-json3-dev
  libhdf5-dev hdf5-tools
  libsqlite3-dev sqlite3
  libzip-dev libssl-dev
  libgtest-dev
  clang-14 libclang-rt-14-dev llvm-14
  python3 python3-numpy python3-h5py python3-yaml python3-jsonschema python3-matplotlib
  wrk curl
  time
  systemd
  slurm-wlm slurmctld slurmd slurm-client munge
  chromium
  calculix-ccx calculix-ccx-test calculix-ccx-doc calculix-cgx
)

# The dashboard's npm packages (uPlot, playwright-core) need node and npm. A machine that has
# them from elsewhere (e.g. NodeSource, which bundles npm) keeps them: Debian's npm package
# would conflict with that nodejs.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then PACKAGES+=(nodejs npm); fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
