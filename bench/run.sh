#!/usr/bin/env bash
# Benchmarks: render plate(N) (bench/plate.lua) at 1024x768 on one and on
# all threads; print a Markdown table of wall time and peak memory, with
# the machine and date, for docs/performance.md. Wall time includes start-up
# and the script, as a user sees it. Compare ratios within one run: the
# machines are shared and noisy.
set -euo pipefail
csgray=${1:-build/cli/csgray}
sizes=${SIZES:-"8 16 32 64"}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(free -g | awk '/Mem:/ {print $2}') GiB; $(date -u +%Y-%m-%d)"
echo
echo "| scene | threads | wall time (s) | peak memory (MB) |"
echo "|---|---:|---:|---:|"
for n in $sizes; do
  for threads in 1 $(nproc); do
    /usr/bin/time -f "%e %M" -o "$out/time" \
      "$csgray" render bench/plate.lua -D n="$n" -o "$out/plate.png" --size 1024x768 \
      --threads "$threads" >/dev/null
    read -r seconds kilobytes <"$out/time"
    printf '| plate(%s) | %s | %s | %d |\n' "$n" "$threads" "$seconds" $((kilobytes / 1024))
  done
done
