#!/usr/bin/env bash
# Benchmark: `effectc check` over many programs in ONE call, against a baseline run in the
# same script: glslangValidator linking each program (`glslangValidator -l a.vert a.frag`),
# the reference GL front end. Reports ms/program for both and the ratio.
#
# Usage: benches/check_speed.sh [COPIES]   (default 20 copies of every program in
#        effects/ and tests/rewrite/, i.e. several hundred programs)
# Needs: ./setup.sh (release build, glslang-tools).
set -euo pipefail
cd "$(dirname "$0")/.."
copies=${1:-20}
bin=target/release/effectc
[ -x "$bin" ] || cargo build --release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0
for c in $(seq 1 "$copies"); do
    for d in effects/*/ tests/rewrite/*/; do
        [ -d "$d" ] || continue
        vert=$(ls "$d" | grep -E '\.(vert|vs)$' | head -1 || true)
        frag=$(ls "$d" | grep -E '\.(frag|fs)$' | head -1 || true)
        [ -n "$vert" ] && [ -n "$frag" ] || continue
        n=$((n + 1))
        cp "$d/$vert" "$work/p$n.vert"
        cp "$d/$frag" "$work/p$n.frag"
    done
done
now() { date +%s%N; }
t0=$(now)
"$bin" check --color never "$work" > "$work.out" || true
t1=$(now)
tail -1 "$work.out"
if command -v glslangValidator >/dev/null; then
    t2=$(now)
    for i in $(seq 1 "$n"); do glslangValidator -l "$work/p$i.vert" "$work/p$i.frag" >/dev/null 2>&1 || true; done
    t3=$(now)
fi
rm -f "$work.out"
awk -v n="$n" -v e="$(( (t1 - t0) / 1000 ))" -v g="$(( ${t3:-0} - ${t2:-0} ))" 'BEGIN {
    eff = e / 1000.0 / n
    printf "programs: %d\neffectc check (one call): %.2f ms/program (%.0f ms total)\n", n, eff, e / 1000.0
    if (g > 0) {
        gl = g / 1e6 / n
        printf "glslangValidator -l (one process per program): %.2f ms/program\n", gl
        printf "ratio effectc / glslangValidator: %.2f\n", eff / gl
    }
}'
