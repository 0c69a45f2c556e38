#!/usr/bin/env bash
# Acceptance on a corpus of real-world programs, side by side with glslangValidator.
# A corpus is a directory of program directories, each holding its stage files (.vert .tesc
# .tese .geom .frag .comp).
# For each program: does glslangValidator link it (-l), does effectc check it without
# errors? Prints the programs where the two disagree and the totals.
#
# With `vulkan` as second argument the reference is `glslangValidator -V -l` (Vulkan GLSL:
# set/binding, push constants, interfaces matched by location).
#
# Program directories named `<source>__<program>` (as scripts/corpus/gather_*.py write them)
# are also counted per source.
#
# Usage: scripts/corpus_accept.sh CORPUS_DIR [opengl|vulkan]
set -uo pipefail
cd "$(dirname "$0")/.."
corpus=${1:?usage: scripts/corpus_accept.sh CORPUS_DIR [opengl|vulkan]}
env=${2:-opengl}
spv=$(mktemp -d)
trap 'rm -rf "$spv"' EXIT
bin=target/release/effectc
[ -x "$bin" ] || cargo build --release
both=0; only_glslang=0; only_effectc=0; neither=0
declare -A src_total src_linked src_ok
for d in "$corpus"/*/; do
    files=$(ls "$d" | grep -E '\.(vert|tesc|tese|geom|frag|comp)$' | sed "s|^|$d|")
    [ -n "$files" ] || continue
    if [ "$env" = vulkan ]; then
        (cd "$spv" && glslangValidator -V -l $(for f in $files; do realpath "$f"; done) >/dev/null 2>&1); g=$?
    else
        glslangValidator -l $files >/dev/null 2>&1; g=$?
    fi
    "$bin" check --color never $files > "$spv/effectc.out" 2>&1; e=$?
    src=$(basename "$d"); src=${src%%__*}
    src_total[$src]=$(( ${src_total[$src]:-0} + 1 ))
    [ $g -eq 0 ] && src_linked[$src]=$(( ${src_linked[$src]:-0} + 1 ))
    [ $g -eq 0 ] && [ $e -eq 0 ] && src_ok[$src]=$(( ${src_ok[$src]:-0} + 1 ))
    if [ $g -eq 0 ] && [ $e -eq 0 ]; then both=$((both + 1))
    elif [ $g -eq 0 ]; then only_glslang=$((only_glslang + 1)); echo "glslang only: $d  $(grep -m1 -E '^error' "$spv/effectc.out")"
    elif [ $e -eq 0 ]; then only_effectc=$((only_effectc + 1)); echo "effectc only: $d"
    else neither=$((neither + 1)); fi
done
echo "per source: programs, glslang links, effectc accepts of those"
for src in $(printf '%s\n' "${!src_total[@]}" | sort); do
    printf '  %-20s %5d %5d %5d\n' "$src" "${src_total[$src]}" "${src_linked[$src]:-0}" "${src_ok[$src]:-0}"
done
total=$((both + only_glslang))
echo "glslang accepts $total; effectc accepts $both of those ($(( total ? 100 * both / total : 0 ))%); effectc-only $only_effectc; both reject $neither"
