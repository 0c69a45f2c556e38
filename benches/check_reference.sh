#!/usr/bin/env bash
# Benchmark: `effectc check` against the two references on real programs, in one run.
#
#   effectc      `effectc check` of N programs in ONE call (every core), the way a CI lint
#                runs it;
#   glslang      `glslangValidator -d -l <stages>`, one process per program (glslang links
#                one program per call), fanned out over every core with xargs -P;
#   mesa         Mesa's GL driver compiling and linking the same programs in one process
#                (scripts/corpus/gl_verdict.c, EGL surfaceless);
#   big          one generated 6,000-line stage (helpers and a long main, no third-party
#                code): `effectc check` against `glslangValidator` on it.
#
# Bounds (issue "Front on the reference compiler"): effectc <= 0.10 x glslang, effectc
# <= mesa, big <= 1.5 x glslangValidator. Each side runs RUNS times, alternating; medians.
#
# Programs: the first N program directories of CORPUS_DIR (as scripts/corpus/gather_*.py
# write them) with one file per stage that both references link (GLSLANG and MESA files from
# scripts/corpus_verdicts.sh); each is copied as p<i>/prog.<stage> so a directory walk
# forms exactly that program.
#
# Usage: benches/check_reference.sh CORPUS_DIR [N] [RUNS]   (default 500 programs, 3 runs)
# Needs: ./setup.sh (release build, glslang-tools), gcc and Mesa's EGL/GL (libegl-dev,
#        libgl-dev) for the Mesa side (skipped when missing).
set -euo pipefail
cd "$(dirname "$0")/.."
corpus=${1:?usage: benches/check_reference.sh CORPUS_DIR [N] [RUNS]}
want=${2:-500}
runs=${3:-3}
bin=$PWD/target/release/effectc
[ -x "$bin" ] || cargo build --release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=0
for d in "$corpus"/*/; do
    [ "$n" -lt "$want" ] || break
    [ "$(head -c 2 "$d/GLSLANG" 2>/dev/null)" = ok ] && [ "$(head -c 2 "$d/MESA" 2>/dev/null)" = ok ] || continue
    # One file per stage (a stage of several shader objects would lose all but one of them).
    exts=$(for f in "$d"/*.vert "$d"/*.frag "$d"/*.geom "$d"/*.tesc "$d"/*.tese "$d"/*.comp; do if [ -e "$f" ]; then echo "${f##*.}"; fi; done)
    [ "$(echo "$exts" | sort | uniq -d)" = "" ] || continue
    n=$((n + 1))
    mkdir -p "$work/progs/p$n"
    for f in "$d"/*; do
        case "$f" in *.vert|*.frag|*.geom|*.tesc|*.tese|*.comp) cp "$f" "$work/progs/p$n/prog.${f##*.}" ;; esac
    done
done
echo "programs: $n (from $corpus)"
export EGL_PLATFORM=surfaceless MESA_GL_VERSION_OVERRIDE=4.6COMPAT MESA_GLSL_VERSION_OVERRIDE=460 MESA_SHADER_CACHE_DISABLE=true
gv=""
if gcc -O2 -o "$work/gl_verdict" scripts/corpus/gl_verdict.c -lEGL -lGL 2>/dev/null; then gv="$work/gl_verdict"; fi
now() { date +%s%N; }
ms() { echo $(( ($(now) - $1) / 1000000 )); }
e=(); g=(); m=()
for r in $(seq 1 "$runs"); do
    t=$(now); "$bin" check --color never "$work/progs" > "$work/effectc.out" 2>&1 || true; e+=("$(ms "$t")")
    t=$(now)
    ls -d "$work"/progs/p*/ | xargs -P "$(nproc)" -I{} sh -c 'glslangValidator -d -l {}prog.* > /dev/null 2>&1 || true'
    g+=("$(ms "$t")")
    if [ -n "$gv" ]; then t=$(now); ls -d "$work"/progs/p*/ | "$gv" > /dev/null 2>&1 || true; m+=("$(ms "$t")"); fi
    echo "run $r: effectc ${e[-1]} ms, glslangValidator (all cores) ${g[-1]} ms${gv:+, mesa ${m[-1]} ms}"
done
tail -1 "$work/effectc.out"
# The 6,000-line stage: 300 helpers of ~15 lines and a main calling each.
big="$work/big.frag"
{
    echo "#version 330 core"
    echo "in vec2 uv;"
    echo "out vec4 color;"
    echo "uniform float time;"
    for i in $(seq 1 300); do
        cat <<GLSL
vec3 helper$i(vec3 p, float k)
{
    vec3 q = p * (1.0 + 0.$i * k);
    float s = sin(q.x * $i.0 + time) * cos(q.y - $i.0);
    if (s > 0.5) {
        q = q.yzx * s;
    } else {
        q += vec3(s, -s, s * 0.5);
    }
    for (int j = 0; j < 3; j++) {
        q = abs(q) / max(dot(q, q), 0.001) - vec3(0.$i);
    }
    return clamp(q, 0.0, 1.0);
}
GLSL
    done
    echo "void main()"
    echo "{"
    echo "    vec3 p = vec3(uv, 0.5);"
    for i in $(seq 1 300); do echo "    p = mix(p, helper$i(p, $i.0), 0.01);"; done
    echo "    color = vec4(p, 1.0);"
    echo "}"
} > "$big"
bigE=(); bigG=()
for r in $(seq 1 "$runs"); do
    t=$(now); "$bin" check --color never "$big" > /dev/null 2>&1 || true; bigE+=("$(ms "$t")")
    t=$(now); glslangValidator "$big" > /dev/null 2>&1 || true; bigG+=("$(ms "$t")")
done
median() { printf '%s\n' "$@" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
me=$(median "${e[@]}"); mg=$(median "${g[@]}"); mm=$( [ -n "$gv" ] && median "${m[@]}" || echo 0)
be=$(median "${bigE[@]}"); bg=$(median "${bigG[@]}")
awk -v n="$n" -v e="$me" -v g="$mg" -v m="$mm" -v be="$be" -v bg="$bg" -v lines="$(wc -l < "$big")" 'BEGIN {
    ok = 1
    printf "median effectc check (one call): %d ms (%.2f ms/program)\n", e, e / n
    printf "median glslangValidator per program, all cores: %d ms; ratio effectc/glslang %.3f (bound <= 0.10)\n", g, e / g
    if (e / g > 0.10) ok = 0
    if (m > 0) { printf "median Mesa compile+link in one process: %d ms; ratio effectc/mesa %.2f (bound <= 1.0)\n", m, e / m; if (e > m) ok = 0 }
    printf "%d-line stage: effectc %d ms, glslangValidator %d ms, ratio %.2f (bound <= 1.5)\n", lines, be, bg, be / bg
    if (be / bg > 1.5) ok = 0
    exit ok ? 0 : 1
}'
