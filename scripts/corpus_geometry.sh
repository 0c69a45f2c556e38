#!/usr/bin/env bash
# Geometry programs of a real-world corpus through translate and render, side by side with
# glslangValidator. For each program directory holding a .geom stage (its tessellation
# stages too): does glslangValidator link it (-l; `vulkan` as second argument: -V -l)? Does
# `effectc check` accept it (no error)? Does `effectc translate --to wgsl,spv`
# exit 0 with WGSL that naga-cli and tint accept and SPIR-V that spirv-val accepts? Does
# `effectc render` (bare stage files: mesh, attributes, uniforms and textures guessed) write
# a frame? Programs that fail print their first error (the construct effectc names).
#
# Usage: scripts/corpus_geometry.sh CORPUS_DIR [opengl|vulkan]
set -uo pipefail
cd "$(dirname "$0")/.."
corpus=${1:?usage: scripts/corpus_geometry.sh CORPUS_DIR [opengl|vulkan]}
env=${2:-opengl}
bin=${EFFECTC:-$PWD/target/release/effectc}
[ -x "$bin" ] || cargo build --release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
total=0; legal=0; checked=0; translated=0; rendered=0; both=0
for d in "$corpus"/*/; do
    ls "$d" | grep -qE '\.geom$' || continue
    files=$(ls "$d" | grep -E '\.(vert|tesc|tese|geom|frag)$' | sed "s|^|$d|")
    total=$((total + 1))
    if [ "$env" = vulkan ]; then
        (cd "$work" && glslangValidator -V -l $(for f in $files; do realpath "$f"; done) > /dev/null 2>&1) && is_legal=1 || is_legal=0
    else
        glslangValidator -l $files > /dev/null 2>&1 && is_legal=1 || is_legal=0
    fi
    [ $is_legal = 1 ] || continue
    legal=$((legal + 1))
    rm -rf "$work"/out "$work"/frames
    if "$bin" check --color never $files > "$work"/clog 2>&1; then
        checked=$((checked + 1))
    else
        echo "check fails: $d $(grep -m1 -E '^error' "$work"/clog)"
    fi
    ok_t=0
    if "$bin" translate --color never --to wgsl,spv --out "$work"/out $files > "$work"/log 2>&1; then
        wgsl=$(ls "$work"/out/*.wgsl)
        if naga "$wgsl" > "$work"/val 2>&1 && tint "$wgsl" --format wgsl -o "$work"/tint.wgsl > "$work"/val 2>&1; then
            ok_t=1
            for spv in "$work"/out/*.spv; do spirv-val --target-env vulkan1.0 "$spv" > "$work"/val 2>&1 || ok_t=0; done
        fi
        [ $ok_t = 1 ] || echo "invalid output: $d $(head -c 300 "$work"/val | tr '\n' ' ')"
    else
        echo "translate fails: $d $(grep -m1 -E '^error' "$work"/log) $(grep -m1 -A3 -E '^error' "$work"/log | grep -m1 '= ' | head -c 250)"
    fi
    ok_r=0
    if "$bin" render --color never --frames 1 --size 128x128 --timeout 10 --out "$work"/frames $files > "$work"/rlog 2>&1 \
        && ls "$work"/frames/*_0000.png > /dev/null 2>&1; then
        ok_r=1
    elif [ $ok_t = 1 ]; then
        echo "render fails: $d $(grep -m1 -E '^error' "$work"/rlog)"
    fi
    translated=$((translated + ok_t)); rendered=$((rendered + ok_r))
    [ $ok_t = 1 ] && [ $ok_r = 1 ] && both=$((both + 1))
done
pct() { echo $(( $2 ? 1000 * $1 / $2 : 0 )) | sed 's/\(.\)$/.\1/'; }
echo "programs with a geometry stage: $total; glslangValidator links: $legal"
echo "of those: check accepts: $checked ($(pct $checked $legal)%)"
echo "of those: valid WGSL + SPIR-V: $translated ($(pct $translated $legal)%), a frame rendered: $rendered ($(pct $rendered $legal)%), both: $both ($(pct $both $legal)%)"
