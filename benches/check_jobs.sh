#!/usr/bin/env bash
# Benchmark: `effectc check` of many programs in ONE call on two threads against one
# (`--jobs 1`), in the same run. The issue's bound: two threads at least 1.7x faster.
#
# Usage: benches/check_jobs.sh [COPIES] [RUNS]   (default 4 copies of every program under
#        effects/ and tests/rewrite/: ~250 programs; 3 alternating runs of each)
# Needs: ./setup.sh (release build). Prints each run, the medians and the ratio; exits 1
# when the ratio is under 1.7 (a machine with fewer than 2 cores cannot show it).
set -euo pipefail
cd "$(dirname "$0")/.."
copies=${1:-4}
runs=${2:-3}
bin=target/release/effectc
[ -x "$bin" ] || cargo build --release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for c in $(seq 1 "$copies"); do
    # Whole trees, so manifests that reuse a sibling effect still find it.
    mkdir -p "$work/copy$c"
    cp -r effects tests/rewrite "$work/copy$c/"
done
programs=$("$bin" check --color never --jobs 1 "$work" | tail -1 || true)
echo "$programs ($copies copies of effects/ and tests/rewrite/)"
now() { date +%s%N; }
one=(); two=()
for r in $(seq 1 "$runs"); do
    for jobs in 1 2; do
        t0=$(now)
        "$bin" check --color never --jobs "$jobs" "$work" > "$work/out.$jobs" || true
        ms=$(( ($(now) - t0) / 1000000 ))
        if [ "$jobs" = 1 ]; then one+=("$ms"); else two+=("$ms"); fi
        echo "run $r --jobs $jobs: $ms ms"
    done
    cmp -s "$work/out.1" "$work/out.2" || { echo "reports differ between --jobs 1 and --jobs 2" >&2; exit 1; }
done
median() { printf '%s\n' "$@" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
m1=$(median "${one[@]}"); m2=$(median "${two[@]}")
awk -v a="$m1" -v b="$m2" 'BEGIN {
    r = a / b
    printf "median --jobs 1: %d ms, --jobs 2: %d ms, ratio %.2fx (bound >= 1.7x)\n", a, b, r
    exit (r >= 1.7 ? 0 : 1)
}'
