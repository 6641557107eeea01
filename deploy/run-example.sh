#!/usr/bin/env bash
# Quick start 1: install dependencies, build, and solve the bundled example deck.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh
bash deploy/build.sh
mkdir -p out/example
./build/solver/app/kontakt solve examples/cantilever.inp -o out/example
echo
echo "Results are in out/example/: cantilever.dat (ccx layout), cantilever.hdf (open in ParaView),"
echo "cantilever.xdmf (time series), cantilever.log.jsonl (events)."
