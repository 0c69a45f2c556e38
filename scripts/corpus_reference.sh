#!/usr/bin/env bash
# Acceptance against both references on a gathered corpus: for every program directory
# whose GLSLANG and MESA verdict files (written by scripts/corpus_verdicts.sh) say both
# references link it (Vulkan corpora: GLSLANG alone, MESA is `na`), does `effectc check`
# of its stage files exit 0? Prints every legal program effectc refuses with its first
# error, every program effectc accepts that a reference refuses, and a table per source
# (`<source>__<program>` directory names).
#
# Usage: scripts/corpus_reference.sh CORPUS_DIR [opengl|vulkan] [EFFECTC_BINARY]
set -uo pipefail
cd "$(dirname "$0")/.."
corpus=${1:?usage: scripts/corpus_reference.sh CORPUS_DIR [opengl|vulkan] [EFFECTC_BINARY]}
env=${2:-opengl}
bin=${3:-target/release/effectc}
[ -x "$bin" ] || cargo build --release
out=$(mktemp)
trap 'rm -f "$out"' EXIT
declare -A total legal ok lenient
for d in "$corpus"/*/; do
    files=$(ls "$d" | grep -E '\.(vert|frag|geom|tesc|tese|comp)$' | sed "s|^|$d|")
    [ -n "$files" ] || continue
    [ -f "$d/GLSLANG" ] || continue
    g=$(head -c 2 "$d/GLSLANG"); m=$(head -c 2 "$d/MESA" 2>/dev/null || echo na)
    src=$(basename "$d"); src=${src%%__*}
    total[$src]=$(( ${total[$src]:-0} + 1 ))
    if [ "$env" = vulkan ]; then
        flags="--target-env vulkan"; is_legal=$([ "$g" = ok ] && echo 1 || echo 0)
        # The Vulkan version the project compiles for, as glslang's verdict used it (a
        # FLAGS file's `--target-env vulkan1.2`; `spirv1.3` means Vulkan 1.1).
        if [ -f "$d/FLAGS" ]; then
            v=$(grep -oE -- '--target-env[ =]vulkan1\.[0-9]' "$d/FLAGS" | grep -oE 'vulkan1\.[0-9]' | head -1)
            grep -qE -- '--target-env[ =]spirv1\.[3-9]' "$d/FLAGS" && v=${v:-vulkan1.1}
            [ -n "$v" ] && flags="--target-env $v"
        fi
    else
        flags="--target-env opengl"; is_legal=$([ "$g" = ok ] && [ "$m" = ok ] && echo 1 || echo 0)
    fi
    # shellcheck disable=SC2086
    "$bin" check --color never $flags $files > "$out" 2>&1; e=$?
    if [ "$is_legal" = 1 ]; then
        legal[$src]=$(( ${legal[$src]:-0} + 1 ))
        if [ $e -eq 0 ]; then ok[$src]=$(( ${ok[$src]:-0} + 1 ))
        else echo "refused: $d  $(grep -m1 -E '^error' "$out")"; fi
    elif [ $e -eq 0 ] && [ "$g" != ok ]; then
        lenient[$src]=$(( ${lenient[$src]:-0} + 1 ))
        echo "accepted, glslang refuses: $d  ($(head -c 150 "$d/GLSLANG" | tr '\n' ' '))"
    fi
done
printf '%-20s %8s %8s %8s %8s %10s\n' source programs legal accepts percent "lenient"
T=0; L=0; O=0; N=0
for s in $(printf '%s\n' "${!total[@]}" | sort); do
    t=${total[$s]}; l=${legal[$s]:-0}; o=${ok[$s]:-0}; n=${lenient[$s]:-0}
    T=$((T + t)); L=$((L + l)); O=$((O + o)); N=$((N + n))
    printf '%-20s %8d %8d %8d %7s%% %10d\n' "$s" "$t" "$l" "$o" "$(awk -v a="$o" -v b="$l" 'BEGIN{printf "%.1f", b ? 100*a/b : 0}')" "$n"
done
printf '%-20s %8d %8d %8d %7s%% %10d\n' TOTAL "$T" "$L" "$O" "$(awk -v a="$O" -v b="$L" 'BEGIN{printf "%.1f", b ? 100*a/b : 0}')" "$N"
