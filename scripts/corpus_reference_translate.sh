#!/usr/bin/env bash
# Translation and rendering of the programs both references accept, per source. For every
# STEP-th program directory (deterministic sample; 1 = all) whose GLSLANG and MESA verdict
# files (scripts/corpus_verdicts.sh) say both references link it (Vulkan: GLSLANG alone):
#   translate  `effectc translate --to wgsl,spv` exits 0, naga-cli and tint accept the WGSL
#              and every .spv passes `spirv-val --target-env vulkan1.0`;
#   render     `effectc render --frames 1` writes a frame (bare stage files: mesh, uniforms
#              and textures guessed).
# Prints each failure with effectc's first error (the construct it names), then a table.
# A Vulkan program's FLAGS file (`-V --target-env vulkan1.2 -l`, from the gatherer) gives the
# Vulkan version effectc is told, as glslang's verdict used it.
#
# Usage: scripts/corpus_reference_translate.sh CORPUS_DIR [opengl|vulkan] [STEP]
set -uo pipefail
cd "$(dirname "$0")/.."
corpus=${1:?usage: scripts/corpus_reference_translate.sh CORPUS_DIR [opengl|vulkan] [STEP]}
env=${2:-opengl}
step=${3:-1}
bin=${EFFECTC:-$PWD/target/release/effectc}
[ -x "$bin" ] || cargo build --release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_RUNTIME_DIR=${XDG_RUNTIME_DIR:-$work}
declare -A legal translated rendered
i=0
for d in "$corpus"/*/; do
    files=$(ls "$d" | grep -E '\.(vert|frag|geom|tesc|tese|comp)$' | sed "s|^|$d|")
    [ -n "$files" ] && [ -f "$d/GLSLANG" ] || continue
    g=$(head -c 2 "$d/GLSLANG"); m=$(head -c 2 "$d/MESA" 2>/dev/null || echo na)
    if [ "$env" = vulkan ]; then [ "$g" = ok ] || continue; else [ "$g" = ok ] && [ "$m" = ok ] || continue; fi
    i=$((i + 1)); [ $(( i % step )) = 0 ] || continue
    src=$(basename "$d"); src=${src%%__*}
    legal[$src]=$(( ${legal[$src]:-0} + 1 ))
    rm -rf "$work/out" "$work/frames"
    # The Vulkan version the project compiles for (a FLAGS file's `--target-env vulkan1.2`),
    # as glslang's verdict was taken.
    penv=$env
    if [ "$env" = vulkan ] && [ -f "$d/FLAGS" ]; then
        v=$(grep -oE -- '--target-env[ =]vulkan1\.[0-9]' "$d/FLAGS" | grep -oE 'vulkan1\.[0-9]' | head -1)
        grep -qE -- '--target-env[ =]spirv1\.[3-9]' "$d/FLAGS" && v=${v:-vulkan1.1}
        [ -n "$v" ] && penv=$v
    fi
    # shellcheck disable=SC2086
    if "$bin" translate --color never --target-env "$penv" --to wgsl,spv --out "$work/out" $files > "$work/log" 2>&1; then
        ok=1
        for w in "$work"/out/*.wgsl; do
            naga "$w" > "$work/val" 2>&1 && tint "$w" --format wgsl -o "$work/tint.wgsl" > "$work/val" 2>&1 || ok=0
        done
        for s in "$work"/out/*.spv; do spirv-val --target-env vulkan1.0 "$s" > "$work/val" 2>&1 || ok=0; done
        if [ $ok = 1 ]; then translated[$src]=$(( ${translated[$src]:-0} + 1 ))
        else echo "invalid output: $d $(head -c 200 "$work/val" | tr '\n' ' ')"; fi
    else
        echo "translate fails: $d $(grep -m1 -E '^error' "$work/log")"
    fi
    # shellcheck disable=SC2086
    if "$bin" render --color never --target-env "$penv" --frames 1 --size 64x64 --timeout 10 --out "$work/frames" $files > "$work/rlog" 2>&1 \
        && ls "$work"/frames/*.png > /dev/null 2>&1; then
        rendered[$src]=$(( ${rendered[$src]:-0} + 1 ))
    else
        echo "render fails: $d $(grep -m1 -E '^error' "$work/rlog")"
    fi
done
pct() { awk -v a="$1" -v b="$2" 'BEGIN{printf "%.1f", b ? 100*a/b : 0}'; }
printf '%-20s %8s %12s %10s\n' source legal translated rendered
L=0; T=0; R=0
for s in $(printf '%s\n' "${!legal[@]}" | sort); do
    l=${legal[$s]}; t=${translated[$s]:-0}; r=${rendered[$s]:-0}; L=$((L + l)); T=$((T + t)); R=$((R + r))
    printf '%-20s %8d %6d %4s%% %5d %4s%%\n' "$s" "$l" "$t" "$(pct "$t" "$l")" "$r" "$(pct "$r" "$l")"
done
printf '%-20s %8d %6d %4s%% %5d %4s%%\n' TOTAL "$L" "$T" "$(pct "$T" "$L")" "$R" "$(pct "$R" "$L")"
