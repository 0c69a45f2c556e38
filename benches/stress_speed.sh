#!/usr/bin/env bash
# Wall time of `effectc stress` (default: 8 samples, 128x128) per effect, against a
# baseline in the same script: `effectc render --frames 1` of the same effect at the same
# size (device start, check, translate, one frame). Prints seconds and the ratio.
#
#   benches/stress_speed.sh [effects/<name> ...]     (default: every effect)
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --locked --quiet
bin=target/release/effectc
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
effects=("$@")
[ ${#effects[@]} -eq 0 ] && effects=(effects/*/)
now() { date +%s.%N; }
printf '%-14s %9s %9s %7s\n' effect stress_s render_s ratio
for e in "${effects[@]}"; do
    name=$(basename "$e")
    t0=$(now); "$bin" render "$e" --frames 1 --size 128x128 --out "$out/r" >/dev/null; t1=$(now)
    "$bin" stress "$e" --out "$out/s" >/dev/null; t2=$(now)
    awk -v n="$name" -v a="$t0" -v b="$t1" -v c="$t2" \
        'BEGIN { r = b - a; s = c - b; printf "%-14s %9.2f %9.2f %7.1f\n", n, s, r, s / r }'
done
echo "date: $(date -u +%F), machine: $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"
