#!/usr/bin/env bash
# Speed against the peers, in one run, on this machine:
#
#   check      `effectc check` over every vertex+fragment program in the repo in ONE process
#              (how users run it: `effectc check effects/ tests/rewrite/`) against
#              `glslangValidator -l a.vert a.frag`, one process per program (how glslang must
#              be run: it links one program per call). Every program counts, accepted or not.
#   translate  `effectc translate --to wgsl` (one process) against naga-cli converting each
#              GLSL stage file to WGSL (one process per stage), on the inputs both accept.
#              naga-cli's GLSL front end takes only `#version 440/450/460` with Vulkan-style
#              separate textures and samplers, so it rejects nearly all of these desktop-GL
#              programs; the script reports how many it accepts and times only that set (the
#              same set for effectc). When no whole program is accepted by both, the unit is
#              the stage file: each stage both accept is its own input to effectc.
#   render     `cargo bench --bench render_speed`: effectc's steady-state ms/frame against a
#              bare wgpu loop drawing the same pipeline (see benches/render_speed.rs).
#
# Programs: the single-pass effects in effects/*/ (effect.toml with a [stages] table; multi-
# pass effects with [[passes]] are left out) and every program directory in tests/rewrite/.
# Each measurement is repeated REPEATS times (render: the bench binary is run REPEATS times),
# both sides back to back in each repeat. The script prints the median of each side and the
# median of the per-repeat ratios effectc / peer (below 1: effectc is faster; pairing within
# a repeat keeps load drift on a shared machine out of the ratio), then a summary table with
# the date, the machine and its load average at the start.
#
# Usage: benches/peers.sh [REPEATS]     (default 5; takes a few minutes)
# Needs: ./setup.sh (release build, glslang-tools, Vulkan/lavapipe). naga-cli is taken from
#        PATH (`naga`); when missing it is installed into target/peers/ with
#        `cargo install --locked naga-cli --version 30.0.1 --root target/peers`.
# Temporary files go under target/peers/.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
repeats=${1:-5}
case "$repeats" in '' | *[!0-9]* | 0) echo "usage: benches/peers.sh [REPEATS]" >&2; exit 2 ;; esac

bin=$root/target/release/effectc
# Build (a no-op when target/release/effectc is current): a stale binary would measure old code.
cargo build --release --locked
command -v glslangValidator >/dev/null || { echo "peers.sh: glslangValidator not found (run ./setup.sh)" >&2; exit 2; }
naga_bin=$(command -v naga || true)
if [ -z "$naga_bin" ]; then
    naga_bin=$root/target/peers/bin/naga
    [ -x "$naga_bin" ] || cargo install --locked naga-cli --version 30.0.1 --root "$root/target/peers"
fi

work=$root/target/peers/run
rm -rf "$work"
mkdir -p "$work"

now() { date +%s%N; }
# median of integers (nanoseconds) given as arguments
median() { printf '%s\n' "$@" | sort -n | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
ms() { awk -v n="$1" -v d="${2:-1}" 'BEGIN { printf "%.1f", n / 1e6 / d }'; }
ms2() { awk -v n="$1" -v d="${2:-1}" 'BEGIN { printf "%.2f", n / 1e6 / d }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.3f", a / b; else printf "n/a" }'; }
# median of decimal numbers, 3 decimals
fmedian() { printf '%s\n' "$@" | sort -g | awk '{ a[NR] = $1 } END { printf "%.3f", (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
load=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo '?')

# ---- programs -------------------------------------------------------------------------------
# stage file named KEY in the [stages] table of manifest $1
stage_of() {
    awk -v k="$2" '
        /^[[:space:]]*\[/ { in_stages = ($0 ~ /^[[:space:]]*\[stages\][[:space:]]*(#.*)?$/) }
        in_stages {
            line = $0; sub(/#.*/, "", line)
            if (match(line, "^[[:space:]]*" k "[[:space:]]*=[[:space:]]*\"[^\"]*\"")) {
                s = substr(line, RSTART, RLENGTH); sub(/^[^"]*"/, "", s); sub(/"$/, "", s); print s; exit
            }
        }' "$1"
}
dirs=(); verts=(); frags=(); skipped=0
for d in effects/*/; do
    m=$d/effect.toml
    [ -f "$m" ] || continue
    if grep -q '^[[:space:]]*\[\[passes\]\]' "$m" || ! grep -q '^[[:space:]]*\[stages\]' "$m"; then
        skipped=$((skipped + 1)); continue
    fi
    v=$(stage_of "$m" vertex); f=$(stage_of "$m" fragment)
    if [ -z "$v" ] || [ -z "$f" ] || [ -n "$(stage_of "$m" geometry)" ]; then skipped=$((skipped + 1)); continue; fi
    dirs+=("${d%/}"); verts+=("${d}$v"); frags+=("${d}$f")
done
for d in tests/rewrite/*/; do
    v=$(ls "$d" | grep -E '\.(vert|vs)$' || true); f=$(ls "$d" | grep -E '\.(frag|fs)$' || true)
    other=$(ls "$d" | grep -E '\.(geom|gs|tesc|tese|comp)$' || true)
    if [ "$(echo "$v" | grep -c .)" != 1 ] || [ "$(echo "$f" | grep -c .)" != 1 ] || [ -n "$other" ]; then
        skipped=$((skipped + 1)); continue
    fi
    dirs+=("${d%/}"); verts+=("$d$v"); frags+=("$d$f")
done
n=${#dirs[@]}
[ "$n" -gt 0 ] || { echo "peers.sh: no programs found" >&2; exit 1; }

# glslangValidator tells the stage by the extension: give it .vert/.frag names
gverts=(); gfrags=()
for i in "${!dirs[@]}"; do
    v=${verts[$i]}; f=${frags[$i]}
    case "$v" in *.vert) ;; *) mkdir -p "$work/glsl/$i"; cp "$v" "$work/glsl/$i/s.vert"; v=$work/glsl/$i/s.vert ;; esac
    case "$f" in *.frag) ;; *) mkdir -p "$work/glsl/$i"; cp "$f" "$work/glsl/$i/s.frag"; f=$work/glsl/$i/s.frag ;; esac
    gverts+=("$v"); gfrags+=("$f")
done

echo "peers.sh: $n vertex+fragment programs ($skipped multi-pass or other programs left out), $repeats repeats"
echo "effectc: $bin"
echo "glslangValidator: $(glslangValidator --version 2>/dev/null | head -1)"
echo "naga-cli: $naga_bin ($("$naga_bin" --version 2>/dev/null || echo '?'))"
echo

# ---- check ----------------------------------------------------------------------------------
# untimed first pass: acceptance counts (and warm caches)
e_rc=0
"$bin" check --color never "${dirs[@]}" > "$work/check.log" 2>&1 || e_rc=$?
e_summary=$(grep -E '^checked ' "$work/check.log" | tail -1 || true)
g_rejected=0
for i in "${!dirs[@]}"; do
    glslangValidator -l "${gverts[$i]}" "${gfrags[$i]}" > /dev/null 2>&1 || g_rejected=$((g_rejected + 1))
done
ce=(); cg=(); cq=()
for r in $(seq 1 "$repeats"); do
    t0=$(now)
    "$bin" check --color never "${dirs[@]}" > /dev/null 2>&1 || true
    t1=$(now)
    for i in "${!dirs[@]}"; do
        glslangValidator -l "${gverts[$i]}" "${gfrags[$i]}" > /dev/null 2>&1 || true
    done
    t2=$(now)
    ce+=($((t1 - t0))); cg+=($((t2 - t1))); cq+=("$(ratio $((t1 - t0)) $((t2 - t1)))")
done
check_e=$(median "${ce[@]}"); check_g=$(median "${cg[@]}")
check_ratio=$(fmedian "${cq[@]}")
echo "== check: $n programs"
echo "effectc check (one process):           median $(ms "$check_e") ms = $(ms2 "$check_e" "$n") ms/program   (exit $e_rc; ${e_summary:-no summary line})"
echo "glslangValidator -l (process/program): median $(ms "$check_g") ms = $(ms2 "$check_g" "$n") ms/program   ($((n - g_rejected)) linked, $g_rejected rejected)"
echo "ratio effectc / glslangValidator: $check_ratio"
echo

# ---- translate ------------------------------------------------------------------------------
naga_to_wgsl() { # stage file out.wgsl
    local st
    case "$1" in *.vert | *.vs) st=vert ;; *) st=frag ;; esac
    "$naga_bin" --input-kind glsl --shader-stage "$st" "$1" "$2"
}
mkdir -p "$work/naga" "$work/accept"
stages_total=0; stages_naga=0; progs_naga=0
t_inputs=(); t_stages=()   # the common set: effectc inputs, and the stage files naga converts
declare -A naga_ok=()
for i in "${!dirs[@]}"; do
    ok=1
    for s in "${verts[$i]}" "${frags[$i]}"; do
        stages_total=$((stages_total + 1))
        if naga_to_wgsl "$s" "$work/naga/x.wgsl" > /dev/null 2>&1; then
            stages_naga=$((stages_naga + 1)); naga_ok[$s]=1
        else
            ok=0
        fi
    done
    if [ $ok = 1 ]; then
        progs_naga=$((progs_naga + 1))
        if "$bin" translate --color never --to wgsl --out "$work/accept/$i" "${dirs[$i]}" > /dev/null 2>&1; then
            t_inputs+=("${dirs[$i]}"); t_stages+=("${verts[$i]}" "${frags[$i]}")
        fi
    fi
done
unit="program(s)"
if [ ${#t_inputs[@]} = 0 ]; then
    # no whole program accepted by both: compare on the stage files both accept, each stage
    # file copied into a directory of its own so effectc translates it as its own input
    unit="stage file(s)"
    k=0
    for s in "${verts[@]}" "${frags[@]}"; do
        [ -n "${naga_ok[$s]:-}" ] || continue
        k=$((k + 1)); mkdir -p "$work/stages/$k"; cp "$s" "$work/stages/$k/"
        if "$bin" translate --color never --to wgsl --out "$work/accept/s$k" "$work/stages/$k" > /dev/null 2>&1; then
            t_inputs+=("$work/stages/$k"); t_stages+=("$s")
        fi
    done
fi
nt=${#t_inputs[@]}
echo "== translate to WGSL"
echo "naga-cli accepts $stages_naga of $stages_total stage files, $progs_naga of $n programs (both stages)"
# effectc over all programs, for scale (one process; naga-cli has no counterpart)
ta=()
for r in $(seq 1 "$repeats"); do
    rm -rf "$work/out-all"
    t0=$(now)
    "$bin" translate --color never --to wgsl --out "$work/out-all" "${dirs[@]}" > /dev/null 2>&1 || true
    ta+=($(($(now) - t0)))
done
trans_all=$(median "${ta[@]}")
echo "effectc translate, all $n programs (one process): median $(ms "$trans_all") ms = $(ms2 "$trans_all" "$n") ms/program"
if [ "$nt" -gt 0 ]; then
    te=(); tn=(); tq=()
    for r in $(seq 1 "$repeats"); do
        rm -rf "$work/out-e"
        t0=$(now)
        "$bin" translate --color never --to wgsl --out "$work/out-e" "${t_inputs[@]}" > /dev/null 2>&1 || true
        t1=$(now)
        j=0
        for s in "${t_stages[@]}"; do
            j=$((j + 1)); naga_to_wgsl "$s" "$work/naga/$j.wgsl" > /dev/null 2>&1 || true
        done
        t2=$(now)
        te+=($((t1 - t0))); tn+=($((t2 - t1))); tq+=("$(ratio $((t1 - t0)) $((t2 - t1)))")
    done
    trans_e=$(median "${te[@]}"); trans_n=$(median "${tn[@]}")
    trans_ratio=$(fmedian "${tq[@]}")
    echo "accepted by both: $nt $unit (${#t_stages[@]} stage file(s) for naga-cli)"
    echo "effectc translate --to wgsl (one process): median $(ms2 "$trans_e") ms"
    echo "naga-cli (process per stage file):         median $(ms2 "$trans_n") ms"
    echo "ratio effectc / naga-cli: $trans_ratio"
else
    echo "no input accepted by both: no translate comparison"
fi
echo

# ---- render ---------------------------------------------------------------------------------
echo "== render: cargo bench --bench render_speed (x$repeats)"
declare -A re=() rb=() rr=()
labels=(); adapter=""; first_png=""; render_ok=0
for r in $(seq 1 "$repeats"); do
    if ! cargo bench --locked --bench render_speed > "$work/render.$r.log" 2> "$work/render.$r.err"; then
        echo "render run $r failed: $(tail -3 "$work/render.$r.err" | tr '\n' ' ')"
        continue
    fi
    render_ok=$((render_ok + 1))
    [ -n "$adapter" ] || adapter=$(sed -n 's/^adapter: //p' "$work/render.$r.log" | head -1)
    p=$(grep -m1 '^time to first PNG' "$work/render.$r.log" || true); [ -z "$p" ] || first_png=$p
    # table rows: label, effectc ms/frame, bare ms/frame, ratio ("1.234x")
    while IFS=$'\t' read -r label e b q; do
        [ -n "${re[$label]:-}" ] || labels+=("$label")
        re[$label]="${re[$label]:-} $e"; rb[$label]="${rb[$label]:-} $b"; rr[$label]="${rr[$label]:-} $q"
        echo "run $r: $label  effectc $e ms/frame, bare $b ms/frame, ${q}x"
    done < <(awk '/^program /{t = 1; next} t && NF >= 4 && $NF ~ /x$/ {
                  l = $1; for (i = 2; i <= NF - 3; i++) l = l " " $i
                  r = $NF; sub(/x$/, "", r); printf "%s\t%s\t%s\t%s\n", l, $(NF - 2), $(NF - 1), r }' "$work/render.$r.log")
done
[ -z "$first_png" ] || echo "$first_png (last run)"
echo

# ---- summary --------------------------------------------------------------------------------
cores=$(nproc); arch=$(uname -m); day=$(date -u +%F)
echo "== summary ($day; $cores cores, $arch, load average $load at the start; adapter: ${adapter:-none}; medians of $repeats runs; ratio = median of per-run effectc / peer)"
echo
echo "| comparison | effectc | peer | ratio |"
echo "|---|---|---|---|"
echo "| check, $n programs: \`effectc check\` (one process) vs \`glslangValidator -l\` (process per program) | $(ms "$check_e") ms ($(ms2 "$check_e" "$n") ms/program) | $(ms "$check_g") ms ($(ms2 "$check_g" "$n") ms/program) | **$check_ratio** |"
if [ "$nt" -gt 0 ]; then
    echo "| translate to WGSL, the $nt $unit naga-cli also accepts: \`effectc translate\` (one process) vs naga-cli (process per stage) | $(ms2 "$trans_e") ms | $(ms2 "$trans_n") ms | **$trans_ratio** |"
else
    echo "| translate to WGSL: naga-cli accepts none of the $n programs | $(ms2 "$trans_all" "$n") ms/program | – | – |"
fi
if [ "$render_ok" -gt 0 ]; then
    for label in "${labels[@]}"; do
        # shellcheck disable=SC2086
        me=$(fmedian ${re[$label]}); mb=$(fmedian ${rb[$label]})
        echo "| render ms/frame, $label: effectc vs bare wgpu loop | $(printf %.2f "$me") | $(printf %.2f "$mb") | **$(fmedian ${rr[$label]})** |"
    done
else
    echo "| render: cargo bench --bench render_speed failed (see $work/render.*.err) | – | – | – |"
fi
echo
echo "naga-cli accepted $stages_naga of $stages_total stage files and $progs_naga of $n programs; glslangValidator linked $((n - g_rejected)) of $n; effectc check: ${e_summary:-?}"
