#!/usr/bin/env bash
# Rendering on a corpus of real-world programs given as bare stage files (no manifest):
# `effectc render <stage files> --frames 1 --size 128x128`. Attributes, uniforms, mesh and
# textures are guessed (and reported as warnings); a program counts when it exits 0 and
# writes its frame. Failures are split into check/translate errors (the program is not
# legal GLSL, or translation cannot express it) and wgpu errors at render time
# (E0402/E0407: a validation error — the number the render acceptance bounds).
#
# Usage: scripts/corpus_render.sh CORPUS_DIR   (prints failures, then the totals)
set -uo pipefail
cd "$(dirname "$0")/.."
corpus=${1:?usage: scripts/corpus_render.sh CORPUS_DIR}
bin=$PWD/target/release/effectc
[ -x "$bin" ] || cargo build --release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
total=0; rendered=0; wgpu_errors=0; legal=0; rendered_legal=0; legal_wgpu=0
start=$(date +%s.%N)
for d in "$corpus"/*/; do
    files=$(ls "$d" | grep -E '\.(vert|frag)$' | sed "s|^|$d|")
    [ -n "$files" ] || continue
    ls "$d" | grep -qE '\.(geom|tesc|tese)$' && continue   # no geometry/tessellation in WebGPU
    total=$((total + 1))
    rm -rf "$work"/out
    is_legal=0
    glslangValidator -l $files > /dev/null 2>&1 && { is_legal=1; legal=$((legal + 1)); }
    if "$bin" render --color never --frames 1 --size 128x128 --timeout 10 --out "$work"/out $files > "$work"/log 2>&1 \
        && ls "$work"/out/*_0000.png > /dev/null 2>&1; then
        rendered=$((rendered + 1)); [ $is_legal = 1 ] && rendered_legal=$((rendered_legal + 1))
    else
        reason=$(grep -m1 -E '^error' "$work"/log)
        if grep -qE '^error\[E04(02|07)\]' "$work"/log; then
            wgpu_errors=$((wgpu_errors + 1)); [ $is_legal = 1 ] && legal_wgpu=$((legal_wgpu + 1))
            reason="$reason $(grep -m1 -A3 'note' "$work"/log | tr '\n' ' ' | head -c 300)"
        fi
        echo "fails: $d $reason"
    fi
done
end=$(date +%s.%N)
pct() { echo $(( $2 ? 1000 * $1 / $2 : 0 )) | sed 's/\(.\)$/.\1/'; }
echo "programs (vertex+fragment): $total"
echo "rendered a frame: $rendered ($(pct $rendered $total)%)"
echo "without a wgpu validation error: $((total - wgpu_errors)) ($(pct $((total - wgpu_errors)) $total)%)"
echo "of the $legal legal programs (glslangValidator -l links them): rendered $rendered_legal ($(pct $rendered_legal $legal)%), wgpu errors $legal_wgpu"
echo "time: $(echo "$end - $start" | bc) s"
