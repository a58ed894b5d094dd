#!/usr/bin/env bash
# The campaign's parallel runs give the results of serial ones: `rsi
# campaign --jobs 1` and `--jobs 2` on the same case must write the same
# e2 and e_inf in convergence.csv (method, modes, e2, e_inf; wall_s and
# speedup are timings) and byte-identical runs/*/history.csv. A short case
# (5 ms) with a small campaign (cb 0 and 10, ccm 0) keeps it quick. The
# parallel campaign also writes its report (reports/make_campaign_report.py),
# which must produce report.md and every figure it links.
# Usage: campaign_parallel_equals_serial.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/short.json" \
  time.duration=0.005 'campaign=[{"method": "cb", "modes": [0, 10]}, {"method": "ccm", "modes": [0]}]'
for jobs in 1 2; do
  report=--no-report
  [ $jobs -eq 2 ] && report=
  if ! "$rsi" campaign "$work/short.json" --jobs $jobs $report --out "$work/jobs-$jobs" >"$work/log" 2>&1; then
    echo "FAIL rsi campaign --jobs $jobs failed:"
    cat "$work/log"
    exit 1
  fi
done
failures=0
cut -d, -f1-4 "$work/jobs-1/convergence.csv" >"$work/serial.csv"
cut -d, -f1-4 "$work/jobs-2/convergence.csv" >"$work/parallel.csv"
if cmp -s "$work/serial.csv" "$work/parallel.csv" && [ "$(wc -l <"$work/serial.csv")" -eq 5 ]; then
  echo "ok   convergence.csv method,modes,e2,e_inf identical with --jobs 1 and --jobs 2:"
  sed 's/^/       /' "$work/serial.csv"
else
  echo "FAIL convergence.csv (method,modes,e2,e_inf) differs between --jobs 1 and --jobs 2 or lacks a run:"
  diff "$work/serial.csv" "$work/parallel.csv"
  failures=$((failures + 1))
fi
for run in full-0 cb-0 cb-10 ccm-0; do
  if cmp "$work/jobs-1/runs/$run/history.csv" "$work/jobs-2/runs/$run/history.csv"; then
    echo "ok   runs/$run/history.csv byte-identical"
  else
    echo "FAIL runs/$run/history.csv differs between --jobs 1 and --jobs 2"
    failures=$((failures + 1))
  fi
done
# The report links only figures that exist.
links=$(grep -o '([a-z0-9_]*\.png)' "$work/jobs-2/report.md" | tr -d '()')
if [ -n "$links" ] && grep -q "Mode-count guidance" "$work/jobs-2/report.md"; then
  for png in $links; do
    [ -s "$work/jobs-2/$png" ] || { echo "FAIL report.md links $png, which was not written"; failures=$((failures + 1)); }
  done
  echo "ok   report.md written with $(echo "$links" | wc -w) figures"
else
  echo "FAIL report.md missing or without figures"
  failures=$((failures + 1))
fi
[ "$failures" -eq 0 ]
