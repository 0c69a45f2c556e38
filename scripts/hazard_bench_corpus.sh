#!/usr/bin/env bash
# Assembles the 600-program set `benches/hazard_speed.rs` times the hazard analysis on:
# links to program directories of the gathered corpora (no shader code is copied), every
# Nth legal program (its GLSLANG verdict starts with `ok`) of the desktop GL corpus (300),
# the Vulkan GLSL corpus (200) and the fresh GL corpus (100), topped up from the GL corpus.
#
#   scripts/hazard_bench_corpus.sh OUT_DIR [CORPUS_ROOT]   (CORPUS_ROOT: /work/corpus)
#   cargo bench --bench hazard_speed -- --corpus OUT_DIR --limit 600 --rounds 3
set -euo pipefail
out=$1
root=${2:-/work/corpus}
mkdir -p "$out"
legal() { grep -q '^ok' "$root/$1/$2/GLSLANG" 2>/dev/null; }
for spec in opengl:300 vulkan:200 fresh-gl:100; do
    corpus=${spec%%:*}
    want=${spec##*:}
    n=$(ls "$root/$corpus" | wc -l)
    step=$(( n / want > 0 ? n / want : 1 ))
    ls "$root/$corpus" | awk -v s="$step" 'NR % s == 0' | head -"$want" | while read -r p; do
        if legal "$corpus" "$p"; then ln -sfn "$root/$corpus/$p" "$out/${corpus}__$p"; fi
    done
done
ls "$root/opengl" | awk 'NR % 7 == 3' | while read -r p; do
    [ "$(ls "$out" | wc -l)" -ge 600 ] && break
    if legal opengl "$p" && [ ! -e "$out/opengl__$p" ]; then ln -sfn "$root/opengl/$p" "$out/opengl__$p"; fi
done
echo "$(ls "$out" | wc -l) programs in $out"
