#!/usr/bin/env bash
# Translation on a corpus of real-world programs, side by side with glslangValidator's
# OpenGL SPIR-V path. A corpus is a directory of program directories (.vert/.frag files).
#
# effectc: `effectc translate DIR --to wgsl,spv`; a program counts when it exits 0, the WGSL
# passes the independent validators on PATH (naga-cli re-validates it; tint too, when present)
# and every .spv passes `spirv-val --target-env vulkan1.0`.
# glslang: `glslangValidator -G --amb --aml -l` (OpenGL SPIR-V, auto-mapped bindings and
# locations); a program counts when it links and every .spv passes
# `spirv-val --target-env opengl4.5`.
#
# Also counted: programs glslangValidator -l links for OpenGL (legal GLSL programs).
#
# Usage: scripts/corpus_translate.sh CORPUS_DIR   (prints failures, then the totals)
set -uo pipefail
cd "$(dirname "$0")/.."
corpus=${1:?usage: scripts/corpus_translate.sh CORPUS_DIR}
bin=$PWD/target/release/effectc
[ -x "$bin" ] || cargo build --release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
total=0; gl_linked=0; effectc_ok_of_gl=0; effectc_ok=0; glslang_ok=0; glslang_linked=0; effectc_ok_of_linked=0
for d in "$corpus"/*/; do
    files=$(ls "$d" | grep -E '\.(vert|frag)$' | sed "s|^|$d|")
    [ -n "$files" ] || continue
    ls "$d" | grep -qE '\.(geom|tesc|tese)$' && continue   # no geometry/tessellation in WGSL
    total=$((total + 1))
    rm -rf "$work"/e "$work"/g; mkdir -p "$work"/e "$work"/g
    e=ok
    if ! "$bin" translate --color never --to wgsl,spv --out "$work"/e $files > "$work"/e.log 2>&1; then
        e="translate: $(grep -m1 -E '^error' "$work"/e.log)"
    else
        for w in "$work"/e/*.wgsl; do
            naga "$w" > "$work"/naga.log 2>&1 || e="naga-cli rejects the WGSL: $(head -c 200 "$work"/naga.log)"
            if command -v tint >/dev/null; then
                tint "$w" --format wgsl -o "$work"/tint.wgsl > "$work"/tint.log 2>&1 || e="tint rejects the WGSL: $(head -c 200 "$work"/tint.log)"
            fi
        done
        for s in "$work"/e/*.spv; do
            spirv-val --target-env vulkan1.0 "$s" > "$work"/val.log 2>&1 || e="spirv-val: $(head -c 200 "$work"/val.log)"
        done
    fi
    g=ok
    if (cd "$work"/g && glslangValidator -G --amb --aml -l $(for f in $files; do realpath "$f"; done) > log 2>&1); then
        glslang_linked=$((glslang_linked + 1)); linked=1
        for s in "$work"/g/*.spv; do
            spirv-val --target-env opengl4.5 "$s" > "$work"/gval.log 2>&1 || g="spirv-val: $(head -c 120 "$work"/gval.log)"
        done
    else
        g="glslang: $(grep -m1 ERROR "$work"/g/log)"; linked=0
    fi
    if glslangValidator -l $files > /dev/null 2>&1; then
        gl_linked=$((gl_linked + 1)); [ "$e" = ok ] && effectc_ok_of_gl=$((effectc_ok_of_gl + 1))
    fi
    [ "$e" = ok ] && effectc_ok=$((effectc_ok + 1))
    [ "$e" = ok ] && [ $linked = 1 ] && effectc_ok_of_linked=$((effectc_ok_of_linked + 1))
    [ "$g" = ok ] && glslang_ok=$((glslang_ok + 1))
    [ "$e" = ok ] || echo "effectc fails: $d  $e" | tr '\n' ' ' && [ "$e" = ok ] || echo
done
pct() { echo $(( $2 ? 1000 * $1 / $2 : 0 )) | sed 's/\(.\)$/.\1/'; }
echo "programs (vertex+fragment): $total"
echo "effectc: valid WGSL + spirv-val-clean SPIR-V for $effectc_ok ($(pct $effectc_ok $total)%)"
echo "glslangValidator -G: links and spirv-val-clean for $glslang_ok ($(pct $glslang_ok $total)%)"
echo "of the $gl_linked programs glslangValidator -l links (legal OpenGL GLSL), effectc translates $effectc_ok_of_gl ($(pct $effectc_ok_of_gl $gl_linked)%)"
echo "of the $glslang_linked programs glslang links, effectc translates $effectc_ok_of_linked ($(pct $effectc_ok_of_linked $glslang_linked)%)"
