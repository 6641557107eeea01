#!/bin/sh
# Stand-in for `kontakt solve MODEL.inp -o DIR [--quiet] [--threads N] [--scheme NAME]` that runs
# ccx 2.20 and copies its MODEL.dat, MODEL.sta and MODEL.frd to DIR: a self-test of run_peer.py
# (every deck must PASS) and of the contact scripts, e.g.
#   /usr/bin/python3 tests/peer/run_peer.py --kontakt tests/peer/fake_kontakt_ccx.sh
# Like the reference, it uses ccx's direct solver (SOLVER=ITERATIVE... is removed from *STATIC).
# --scheme is accepted and ignored: ccx uses the deck's *CONTACT PAIR TYPE.
# Exit codes follow kontakt's: 2 input error (bad command line), 3 not converged (ccx: too many
# cutbacks / increment below the minimum), 4 ccx failed otherwise.
set -u
[ "${1:-}" = solve ] || { echo "usage: $0 solve MODEL.inp -o DIR" >&2; exit 2; }
shift
deck="" out="."
while [ $# -gt 0 ]; do
  case "$1" in
    -o) out="$2"; shift 2 ;;
    --threads|--scheme) shift 2 ;;
    --quiet|-q) shift ;;
    *) deck="$1"; shift ;;
  esac
done
[ -f "$deck" ] || { echo "fake kontakt: no deck '$deck'" >&2; exit 2; }
name=$(basename "$deck" .inp)
dir=$(dirname "$deck")
mkdir -p "$out"
stage=".fake_${name}_$$"  # one per call: callers may solve one deck with several "schemes" at once
tmp="$dir/$stage"
sed -E 's/^(\*[Ss][Tt][Aa][Tt][Ii][Cc][^,]*(,[^,]*)*),[ ]*[Ss][Oo][Ll][Vv][Ee][Rr][ ]*=[ ]*[Ii][Tt][Ee][Rr][Aa][Tt][Ii][Vv][Ee][^,]*/\1/' \
  "$deck" > "$tmp.inp"
(cd "$dir" && OMP_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 ccx -i "$stage" > "$stage.log" 2>&1)
for ext in dat sta frd; do
  [ -f "$tmp.$ext" ] && cp "$tmp.$ext" "$out/$name.$ext"
done
log="$out/$name.fake.log"
mv "$tmp.log" "$log"
rm -f "$tmp".*
if ! grep -q "Job finished" "$log"; then
  if grep -q -e "too many cutbacks" -e "increment size smaller" "$log"; then
    echo "fake kontakt: ccx did not converge on $deck (see $log)" >&2
    exit 3
  fi
  echo "fake kontakt: ccx failed on $deck (see $log)" >&2
  exit 4
fi
