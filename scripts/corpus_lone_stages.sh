#!/usr/bin/env bash
# Every stage file of a repository checked on its own: glslangValidator's verdict against
# effectc's, file by file. The unit for stages that form no raster program (ray tracing,
# compute) and a quick sweep of a Vulkan repository's other stages.
#
# A file is legal when glslangValidator `-V` compiles it for some Vulkan version (1.0, then
# `--target-env vulkan1.1` … `vulkan1.3`, as the project would name the one it needs);
# effectc runs with no target environment (`auto`), so the figure says whether it finds the
# dialect and version itself.
#
# Usage: [EFFECTC=binary] scripts/corpus_lone_stages.sh MIRROR_GIT_DIR SUBDIR
#   e.g. scripts/corpus_lone_stages.sh /work/.mirror/SaschaWillems+Vulkan/repo shaders/glsl
# Prints one line per legal file effectc refuses, then the totals per stage extension.
set -uo pipefail
git_dir=$1; subdir=$2
cd "$(dirname "$0")/.."
bin=$(realpath "${EFFECTC:-target/release/effectc}")
[ -x "$bin" ] || { echo "no $bin: build it first (cargo build --release)" >&2; exit 2; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
git --git-dir="$git_dir" archive HEAD "$subdir" | tar -x -C "$tmp"
# The checkout's root, as effectc finds it (the project root: includes resolve inside it).
mkdir -p "$tmp/.git"
declare -A legal accepted
cd "$tmp"
while IFS= read -r f; do
    ext=${f%.glsl}; ext=${ext##*.}
    g=fail
    for env in vulkan1.0 vulkan1.1 vulkan1.2 vulkan1.3; do
        if glslangValidator -V --target-env $env -o /dev/null "$f" > /dev/null 2>&1; then g=ok; break; fi
    done
    if "$bin" check --color never "$f" > out.txt 2>&1; then e=ok; else e=fail; fi
    [ "$g" = ok ] || continue
    legal[$ext]=$(( ${legal[$ext]:-0} + 1 ))
    if [ "$e" = ok ]; then accepted[$ext]=$(( ${accepted[$ext]:-0} + 1 ));
    else echo "REFUSED $f: $(grep -m1 -E '^(error|warning)' out.txt)"; fi
done < <(find "$subdir" -type f | grep -E '\.(vert|frag|geom|tesc|tese|comp|task|mesh|rgen|rint|rahit|rchit|rmiss|rcall)(\.glsl)?$' | sort)
for ext in "${!legal[@]}"; do
    printf '%-6s legal %4d  effectc accepts %4d\n' "$ext" "${legal[$ext]}" "${accepted[$ext]:-0}"
done | sort
total=0; ok=0
for ext in "${!legal[@]}"; do total=$((total + legal[$ext])); ok=$((ok + ${accepted[$ext]:-0})); done
echo "all    legal $total  effectc accepts $ok"
