#!/usr/bin/env bash
# Seed 000's own exploding-mesh trio (res/shaderGeoText.{vert,geom,frag}: a vert_vars →
# geom_vars chain, GLSL 420) as bare stage files: check, translate (WGSL checked by naga-cli
# and tint, SPIR-V by spirv-val) and render 8 frames. The shaders are the student's and are
# not kept in this repository: they are read from a mirror of the project
# (`fetch github:AidenD1799/AidenDonkinGraphicProject2023`).
#
# Usage: scripts/seed_geometry.sh MIRROR_GIT_DIR   (e.g. /work/.mirror/AidenD1799+AidenDonkinGraphicProject2023/repo)
set -euo pipefail
cd "$(dirname "$0")/.."
git_dir=${1:?usage: scripts/seed_geometry.sh MIRROR_GIT_DIR}
bin=$PWD/target/release/effectc
[ -x "$bin" ] || cargo build --release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for stage in vert geom frag; do
    git --git-dir="$git_dir" show "HEAD:res/shaderGeoText.$stage" > "$work/shaderGeoText.$stage"
done
files=("$work"/shaderGeoText.vert "$work"/shaderGeoText.geom "$work"/shaderGeoText.frag)
"$bin" check --color never "${files[@]}" | tail -1
"$bin" translate --color never --to wgsl,spv,reflect --out "$work/out" "${files[@]}" | head -1
naga "$work/out/shaderGeoText.wgsl" > /dev/null && echo "naga-cli: WGSL valid"
tint "$work/out/shaderGeoText.wgsl" --format wgsl -o "$work/tint.wgsl" && echo "tint: WGSL valid"
for spv in "$work"/out/*.spv; do spirv-val --target-env vulkan1.0 "$spv" && echo "spirv-val: $(basename "$spv") valid"; done
# Time 4.0–5.4 s: around 3π/2, where the pieces are back together.
"$bin" render --color never --frames 8 --start 4.0 --time-step 0.2 --size 128x128 --out "$work/frames" "${files[@]}" | head -1
ls "$work"/frames/*.png | wc -l | sed 's/$/ frames written/'
