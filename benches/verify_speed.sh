#!/usr/bin/env bash
# Cost of `effectc verify` against `effectc render` of the same effect, frames and size,
# in the same script (both check, translate and draw with wgpu; verify also compiles the
# original with the OpenGL driver, draws every frame again there, compares and writes
# three pictures a frame where render writes one). Target: verify ≤ 1.5 × render.
# Runs are paired (farm-bench --vs): the ratio is taken run by run; the median is quoted.
#
#   benches/verify_speed.sh [effects/<name> ...]     (default: phong, bloom, explode, planet)
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --locked --quiet
bin=$PWD/target/release/effectc
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
effects=("$@")
[ ${#effects[@]} -eq 0 ] && effects=(effects/phong effects/bloom effects/explode effects/planet)
for e in "${effects[@]}"; do
    name=$(basename "$e")
    echo "== $name: verify (A) against render (B), 4 frames at 256x256"
    farm-bench -n 5 --timeout 600 \
        --vs "$bin render $e --frames 4 --size 256x256 --out $out/r" \
        -- "$bin" verify "$e" --frames 4 --size 256x256 --out "$out/v" | grep -E "wall|ratio|A/B" || true
done
echo "date: $(date -u +%F), machine: $(nproc) cores, load: $(cut -d' ' -f1-3 /proc/loadavg)"
