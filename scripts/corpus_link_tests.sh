#!/usr/bin/env bash
# glslang's own link tests, effectc's verdict against glslang's expected one.
# The corpus comes from scripts/corpus/gather_glslang_link.py: one directory per link group
# holding the stage files (original names), EXPECTED (accept|reject, from glslang's
# Test/baseResults), ENV (opengl|vulkan), MULTIUNIT (yes|no), FLAGS (glslangValidator options
# that reproduce the test's semantics) and FILES (the order the test links them in).
#
# For each group: `effectc check --color never <files>` (exit 0 accept, 1 reject, anything
# else or a panic = crash) compared with EXPECTED. Prints the disagreements, then totals
# overall and per subset; the acceptance figure is the OpenGL, single-unit-per-stage subset.
# Then checks EXPECTED against the installed glslangValidator run with the group's FLAGS
# (it may be older than the glslang the expectations come from): exit 0 accept, 2/3 reject,
# 1 usage error (an option it does not know), a signal = crash.
#
# Where effectc disagrees with an OpenGL group's expectation, Mesa's verdict on the same files
# (scripts/corpus/gl_verdict.c, one program of every file) says which side a real driver
# takes; the totals count those groups apart ("effectc sides with Mesa").
#
# Groups with a file effectc reads as no stage are skipped and listed.
# In multi-unit groups effectc sees two files of one stage and checks them as separate
# programs (grouped by file stem), not as one linked stage: those figures are indicative.
#
# Usage: scripts/corpus_link_tests.sh [CORPUS_DIR]   (default /work/corpus/glslang-link)
set -uo pipefail
corpus=$(realpath "${1:-/work/corpus/glslang-link}")
cd "$(dirname "$0")/.."
bin=target/release/effectc
glslang=${GLSLANG:-glslangValidator}
[ -x "$bin" ] || { echo "no $bin: build it first (cargo build --release)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mesa_verdict=""
if gcc -O2 -o "$tmp/gl_verdict" scripts/corpus/gl_verdict.c -lEGL -lGL 2>/dev/null; then mesa_verdict="$tmp/gl_verdict"; fi
declare -A with_mesa

declare -A groups agree disagree crash
subsets="all opengl-single opengl-multi vulkan-single vulkan-multi"
for s in $subsets; do groups[$s]=0; agree[$s]=0; disagree[$s]=0; crash[$s]=0; done
skipped=0; g_total=0; g_agree=0; g_mismatch=""

echo "== disagreements (expected vs effectc)"
for d in "$corpus"/*/; do
    d=${d%/}; name=$(basename "$d")
    [ -f "$d/EXPECTED" ] || continue
    expected=$(cat "$d/EXPECTED"); env=$(cat "$d/ENV"); multi=$(cat "$d/MULTIUNIT")
    if [ -f "$d/FILES" ]; then names=$(cat "$d/FILES"); else names=$(ls "$d" | grep -E '\.[a-z]+$'); fi
    files=""; unreadable=""
    for f in $names; do
        files="$files $d/$f"
        case "${f##*.}" in vert|frag|geom|tesc|tese|comp|task|mesh|rgen|rint|rahit|rchit|rmiss|rcall) ;; *) unreadable="$unreadable .${f##*.}" ;; esac
    done
    if [ -n "$unreadable" ]; then
        skipped=$((skipped + 1)); echo "SKIP      $name: effectc cannot read$unreadable files"; continue
    fi

    [ "$multi" = yes ] && sub="$env-multi" || sub="$env-single"
    timeout 120 "$bin" check --color never $files > "$tmp/out" 2>&1; e=$?
    if grep -q 'panicked' "$tmp/out"; then got=crash
    elif [ $e -eq 0 ]; then got=accept
    elif [ $e -eq 1 ]; then got=reject
    else got=crash; fi
    for s in all "$sub"; do
        groups[$s]=$((groups[$s] + 1))
        if [ "$got" = crash ]; then crash[$s]=$((crash[$s] + 1))
        elif [ "$got" = "$expected" ]; then agree[$s]=$((agree[$s] + 1))
        else disagree[$s]=$((disagree[$s] + 1)); fi
    done
    if [ "$got" != "$expected" ]; then
        first=$(grep -m1 -E '^(error|thread .* panicked)' "$tmp/out")
        [ "$got" = crash ] && first="exit $e: $(grep -m1 -E 'panicked|error' "$tmp/out")"
        reason=$(grep -v -E 'node is still EOpNull|compilation errors' "$d/REASON" 2>/dev/null | head -1)
        echo "${got^^}$(printf '%*s' $((10 - ${#got})) '')$name [$sub] expected $expected, effectc $got"
        echo "          files:$(for f in $names; do printf ' %s' "$f"; done)"
        [ -n "$first" ] && echo "          effectc: $first"
        [ -n "$reason" ] && echo "          glslang: $reason"
        if [ -n "$mesa_verdict" ] && [ "$env" = opengl ] && [ "$got" != crash ]; then
            rm -rf "$tmp/mesa"; mkdir "$tmp/mesa"
            for f in $names; do cp "$d/$f" "$tmp/mesa/"; done
            mesa=$("$mesa_verdict" "$tmp/mesa" 2>/dev/null | cut -f2-)
            case "$mesa" in ok*) mv=accept ;; fail*) mv=reject ;; *) mv=unknown ;; esac
            echo "          mesa: $mv ($(echo "$mesa" | cut -f2 | cut -c1-120))"
            if [ "$mv" = "$got" ]; then
                for s in all "$sub"; do with_mesa[$s]=$(( ${with_mesa[$s]:-0} + 1 )); done
            fi
        fi
    fi

    # The reference: does the installed glslangValidator give the expected verdict?
    abs=$(for f in $names; do printf '%s ' "$(realpath "$d/$f")"; done)
    flags=$(cat "$d/FLAGS")
    (cd "$tmp" && $glslang $flags $abs > "$tmp/glslang.out" 2>&1) 2>/dev/null; g=$?
    case $g in 0) gv=accept ;; 1) gv=usage-error ;; 2|3) gv=reject ;; *) gv=crash ;; esac
    g_total=$((g_total + 1))
    if [ "$gv" = "$expected" ]; then g_agree=$((g_agree + 1))
    else g_mismatch="$g_mismatch  $name [$sub] expected $expected, $glslang $gv (exit $g): $(grep -m1 -E 'ERROR|rror' "$tmp/glslang.out" | cut -c1-150)
"; fi
done

echo
echo "== effectc vs glslang's expected verdicts ($skipped groups skipped)"
for s in $subsets; do
    n=${groups[$s]}
    printf '%-14s groups %3d  agree %3d (%3d%%)  disagree %3d (effectc sides with Mesa in %d)  crashes %3d\n' "$s" "$n" "${agree[$s]}" \
        $(( n ? 100 * agree[$s] / n : 0 )) "${disagree[$s]}" "${with_mesa[$s]:-0}" "${crash[$s]}"
done
echo "acceptance figure (opengl-single): ${agree[opengl-single]}/${groups[opengl-single]} agree"
echo
echo "== $($glslang --version 2>/dev/null | head -1) vs the expected verdicts: $g_agree/$g_total agree"
printf '%s' "$g_mismatch"
