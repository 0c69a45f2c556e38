#!/usr/bin/env bash
# `effectc verify` on the programs both references accept, per source: for every STEP-th
# program directory whose GLSLANG and MESA verdict files (scripts/corpus_verdicts.sh) say
# both link it, one 64x64 frame of the translation is compared with the original drawn by
# the OpenGL driver (bare stage files: mesh, uniforms and textures guessed, the same on
# both sides). Counts:
#   drawn     verify drew both pictures (what `render` draws);
#   match     every frame within the default tolerance (2/255 on 0.1% of the pixels);
# and lists each mismatch (largest difference, pixels over) and each program drawn by
# one side only (effectc's first error).
#
# Usage: scripts/corpus_verify.sh CORPUS_DIR [STEP]
set -uo pipefail
cd "$(dirname "$0")/.."
corpus=${1:?usage: scripts/corpus_verify.sh CORPUS_DIR [STEP]}
step=${2:-1}
bin=${EFFECTC:-$PWD/target/release/effectc}
[ -x "$bin" ] || cargo build --release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$work}
declare -A legal drawn matched
i=0
for d in "$corpus"/*/; do
    files=$(ls "$d" | grep -E '\.(vert|frag|geom|tesc|tese|comp)$' | sed "s|^|$d|")
    [ -n "$files" ] && [ -f "$d/GLSLANG" ] || continue
    g=$(head -c 2 "$d/GLSLANG"); m=$(head -c 2 "$d/MESA" 2>/dev/null || echo na)
    [ "$g" = ok ] && [ "$m" = ok ] || continue
    i=$((i + 1)); [ $(( i % step )) = 0 ] || continue
    src=$(basename "$d"); src=${src%%__*}
    legal[$src]=$(( ${legal[$src]:-0} + 1 ))
    rm -rf "$work/v"
    # shellcheck disable=SC2086
    "$bin" verify --color never --target-env opengl --frames 1 --size 64x64 --timeout 10 --out "$work/v" $files > "$work/log" 2>&1
    if grep -qE '^  frame' "$work/log"; then
        drawn[$src]=$(( ${drawn[$src]:-0} + 1 ))
        if grep -qE '^verified .*: 1/1 frame match' "$work/log"; then
            matched[$src]=$(( ${matched[$src]:-0} + 1 ))
        else
            echo "differs: $d $(grep -m1 -E '^  frame' "$work/log" | sed 's/^ *//')"
        fi
    else
        echo "not drawn: $d $(grep -m1 -E '^error' "$work/log")"
    fi
done
pct() { awk -v a="$1" -v b="$2" 'BEGIN{printf "%.1f", b ? 100*a/b : 0}'; }
printf '%-20s %8s %8s %12s\n' source legal drawn match
L=0; D=0; M=0
for s in $(printf '%s\n' "${!legal[@]}" | sort); do
    l=${legal[$s]}; dd=${drawn[$s]:-0}; mm=${matched[$s]:-0}; L=$((L + l)); D=$((D + dd)); M=$((M + mm))
    printf '%-20s %8d %8d %6d %4s%%\n' "$s" "$l" "$dd" "$mm" "$(pct "$mm" "$dd")"
done
printf '%-20s %8d %8d %6d %4s%%\n' TOTAL "$L" "$D" "$M" "$(pct "$M" "$D")"
