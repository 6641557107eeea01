#!/usr/bin/env bash
# Quick start 1: install dependencies, build, start kontaktd on localhost (SQLite store and job
# folders in out/kontaktd-data), submit the bundled example to it, fetch its results into
# out/example, and keep the daemon running until Ctrl-C.
set -euo pipefail
cd "$(dirname "$0")/.."
bash deploy/install-deps.sh
bash deploy/build.sh
port="${KONTAKTD_PORT:-8080}"
server="http://127.0.0.1:${port}"
mkdir -p out/example out/kontaktd-data
./build/server/kontaktd --port "$port" --data-dir out/kontaktd-data &
daemon=$!
trap 'kill -TERM "$daemon" 2>/dev/null; wait "$daemon"' INT TERM EXIT
for _ in $(seq 50); do
  curl -fsS "$server/healthz" >/dev/null 2>&1 && break
  kill -0 "$daemon" 2>/dev/null || { echo "kontaktd did not start (port $port in use? set KONTAKTD_PORT)"; exit 1; }
  sleep 0.2
done
export KONTAKT_SERVER="$server"
job=$(./build/solver/app/kontakt submit examples/cantilever.inp --name cantilever)
./build/solver/app/kontakt wait "$job"
./build/solver/app/kontakt fetch "$job" -o out/example >/dev/null
cat <<EOT

kontaktd is running at $server (dashboard: $server/). The example job $job succeeded;
its results are in out/example/: cantilever.dat (ccx layout), cantilever.hdf (open in
ParaView), cantilever.xdmf (time series), cantilever.log.jsonl (events).

Submit it again from another shell:
  KONTAKT_SERVER=$server build/solver/app/kontakt submit examples/cantilever.inp --wait
  curl -H 'Content-Type: text/plain' --data-binary @examples/cantilever.inp $server/v1/jobs
Ctrl-C stops the daemon (running jobs are requeued and resume at the next start).
EOT
wait "$daemon"
