#!/usr/bin/env bash
# Both reference verdicts for every program of a corpus (no effectc, no cargo).
#
# For each program directory CORPUS_DIR/<source>__<program>/ holding stage files
# (.vert .frag .geom .tesc .tese .comp) it writes two files into that directory:
#   GLSLANG  `ok` or `fail: <first ERROR line>`  (opengl: glslangValidator -d -l <files>: -d
#            makes a stage without #version GLSL 1.10 as in GL, not ES 1.00, glslangValidator's
#            default;
#            vulkan: glslangValidator -V -l <files>, run in a temp cwd so no .spv lands here)
#   MESA     `ok`, `fail: <first error line>`, `na` (Vulkan GLSL, or a vulkan run) or
#            `crash: ...` (the driver died or hung on it), from scripts/corpus/gl_verdict.c:
#            Mesa's GL driver, EGL surfaceless, one 4.5 compatibility context
#            (MESA_GL_VERSION_OVERRIDE=4.6COMPAT MESA_GLSL_VERSION_OVERRIDE=460).
# A program directory with an ENV file (glslang-link) uses its content (opengl/vulkan) as the
# environment, and a FLAGS file replaces glslangValidator's options.
# Also writes CORPUS_DIR/VERDICTS.tsv (program, GLSLANG, MESA) and prints a per-source table
# (programs, glslang links, Mesa links, both) and the disagreements with both messages.
#
# Usage: scripts/corpus_verdicts.sh CORPUS_DIR [opengl|vulkan]
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
corpus=$(cd "${1:?usage: scripts/corpus_verdicts.sh CORPUS_DIR [opengl|vulkan]}" && pwd)
env=${2:-opengl}
export EGL_PLATFORM=surfaceless MESA_GL_VERSION_OVERRIDE=4.6COMPAT MESA_GLSL_VERSION_OVERRIDE=460
export MESA_SHADER_CACHE_DISABLE=true
gv=/tmp/gl_verdict
if [ ! -x "$gv" ] || [ "$here/corpus/gl_verdict.c" -nt "$gv" ]; then
    gcc -O2 -o "$gv" "$here/corpus/gl_verdict.c" -lEGL -lGL || exit 1
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
first_error() { # first ERROR line of glslang's output (program dir $2 cut from paths), else its first non-empty line
    local l
    l=$(grep -a -m1 -E '^ERROR:' "$1" | grep -a -v 'compilation terminated' || true)
    [ -n "$l" ] || l=$(grep -a -m1 -v -E '^\s*$|^/' "$1" || true)
    [ -n "$l" ] || l="glslangValidator exit status $3"
    printf '%s' "${l//$2\//}" | tr '\t\r' '  ' | cut -c1-400
}
fresh() { # GLSLANG and MESA of program dir $1 newer than its stage files (REUSE=1)
    [ "${REUSE:-0}" = 1 ] && [ -f "$1/GLSLANG" ] && [ -f "$1/MESA" ] || return 1
    [ -z "$(find "$1" -maxdepth 1 -regex '.*\.\(vert\|frag\|geom\|tesc\|tese\|comp\)' -newer "$1/MESA")" ] &&
    [ -z "$(find "$1" -maxdepth 1 -regex '.*\.\(vert\|frag\|geom\|tesc\|tese\|comp\)' -newer "$1/GLSLANG")" ]
}

# 1. glslang
: > "$tmp/gl_list"
for d in "$corpus"/*/; do
    d=${d%/}
    files=$(ls "$d" | grep -E '\.(vert|frag|geom|tesc|tese|comp)$' | sed "s|^|$d/|")
    [ -n "$files" ] || continue
    fresh "$d" && continue
    penv=$env
    [ -f "$d/ENV" ] && penv=$(head -n1 "$d/ENV")
    if [ -f "$d/FLAGS" ]; then read -r -a opts < "$d/FLAGS" || true
    elif [ "$penv" = vulkan ]; then opts=(-V -l)
    else opts=(-d -l); fi
    [ ${#opts[@]} -gt 0 ] || opts=(-l)
    (cd "$tmp" && rm -f ./*.spv && timeout 120 glslangValidator "${opts[@]}" $files) > "$tmp/g.out" 2>&1; st=$?
    if [ $st -eq 0 ]; then echo ok > "$d/GLSLANG"; else echo "fail: $(first_error "$tmp/g.out" "$d" $st)" > "$d/GLSLANG"; fi
    if [ "$penv" = vulkan ]; then echo na > "$d/MESA"; else echo "$d" >> "$tmp/gl_list"; fi
done

# 2. Mesa, resuming after a program that kills the driver
cp "$tmp/gl_list" "$tmp/todo"
while [ -s "$tmp/todo" ]; do
    "$gv" < "$tmp/todo" > "$tmp/mesa.out" 2> "$tmp/mesa.err"; st=$?
    while IFS=$'\t' read -r d v m; do
        if [ "$v" = ok ] || [ "$v" = na ]; then echo "$v" > "$d/MESA"; else echo "$v: $m" > "$d/MESA"; fi
    done < "$tmp/mesa.out"
    done_n=$(wc -l < "$tmp/mesa.out")
    total_n=$(wc -l < "$tmp/todo")
    [ "$done_n" -lt "$total_n" ] || break
    [ $st -eq 2 ] && [ "$done_n" -eq 0 ] && { echo "gl_verdict could not start: $(cat "$tmp/mesa.err")" >&2; exit 1; }
    bad=$(sed -n "$((done_n + 1))p" "$tmp/todo")
    echo "crash: gl_verdict died on it (exit status $st$([ $st -eq 142 ] && echo ', 120 s timeout'))" > "$bad/MESA"
    tail -n +"$((done_n + 2))" "$tmp/todo" > "$tmp/todo2"; mv "$tmp/todo2" "$tmp/todo"
done

# 3. Table
: > "$corpus/VERDICTS.tsv"
declare -A n_all n_g n_m n_both n_na
dis=""
for d in "$corpus"/*/; do
    d=${d%/}
    [ -f "$d/GLSLANG" ] || continue
    g=$(cat "$d/GLSLANG"); m=$(cat "$d/MESA" 2>/dev/null || echo missing)
    name=$(basename "$d"); src=${name%%__*}
    printf '%s\t%s\t%s\n' "$name" "$g" "$m" >> "$corpus/VERDICTS.tsv"
    n_all[$src]=$(( ${n_all[$src]:-0} + 1 ))
    [ "$g" = ok ] && n_g[$src]=$(( ${n_g[$src]:-0} + 1 ))
    [ "$m" = ok ] && n_m[$src]=$(( ${n_m[$src]:-0} + 1 ))
    [ "$m" = na ] && n_na[$src]=$(( ${n_na[$src]:-0} + 1 ))
    [ "$g" = ok ] && [ "$m" = ok ] && n_both[$src]=$(( ${n_both[$src]:-0} + 1 ))
    if [ "$m" != na ] && { [ "$g" = ok ] || [ "$m" = ok ]; } && [ "$g" != "$m" ]; then
        dis+="  $name"$'\n'"    glslang: $g"$'\n'"    mesa:    $m"$'\n'
    fi
done
printf '%-24s %8s %8s %8s %8s %8s\n' source programs glslang mesa both mesa-na
T=(0 0 0 0 0)
for src in $(printf '%s\n' "${!n_all[@]}" | sort); do
    r=("${n_all[$src]}" "${n_g[$src]:-0}" "${n_m[$src]:-0}" "${n_both[$src]:-0}" "${n_na[$src]:-0}")
    printf '%-24s %8d %8d %8d %8d %8d\n' "$src" "${r[@]}"
    for i in 0 1 2 3 4; do T[$i]=$(( T[i] + r[i] )); done
done
printf '%-24s %8d %8d %8d %8d %8d\n' TOTAL "${T[@]}"
if [ -n "$dis" ]; then echo "disagreements (one reference links, the other does not):"; printf '%s' "$dis"; fi
