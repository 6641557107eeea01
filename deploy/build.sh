#!/usr/bin/env bash
# Configures and builds Kontakt (Release) into ./build; used by both quick-start commands.
set -euo pipefail
cd "$(dirname "$0")/.."
# Unity build: eight sources per compiler run, so the Eigen templates the solver's headers
# instantiate are compiled once per batch, not once per file (README.md, "Building").
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON \
  ${KONTAKT_CMAKE_ARGS:-} >/dev/null
cmake --build build -j"$(nproc)"
