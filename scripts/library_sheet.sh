#!/usr/bin/env bash
# The README's contact sheet of the effects library: 4 frames of every effect under
# effects/, one row per effect with its name, written to docs/effects.png.
# Needs: the release binary (./setup.sh) and Python 3 with Pillow (`pip install pillow`).
# Usage: scripts/library_sheet.sh [SIZE]   (default 128: 128x128 frames)
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-128}
bin=target/release/effectc
[ -x "$bin" ] || cargo build --release
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for dir in effects/*/; do
    name=$(basename "$dir")
    "$bin" render --color never "$dir/effect.toml" --frames 4 --size "${size}x${size}" --out "$work/$name" > /dev/null
done
mkdir -p docs
python3 - "$work" "$size" <<'PY'
import os, sys
from PIL import Image, ImageDraw
work, size = sys.argv[1], int(sys.argv[2])
names = sorted(n for n in os.listdir(work) if os.path.isdir(os.path.join(work, n)))
gap, label = 2, 16
sheet = Image.new("RGB", (4 * size + 3 * gap, len(names) * (size + label + gap)), (30, 30, 30))
draw = ImageDraw.Draw(sheet)
for row, name in enumerate(names):
    y = row * (size + label + gap)
    draw.text((4, y + 2), name, fill=(235, 235, 235))
    for i in range(4):
        frame = Image.open(os.path.join(work, name, f"{name}_{i:04d}.png")).convert("RGB")
        sheet.paste(frame, (i * (size + gap), y + label))
sheet.save("docs/effects.png", optimize=True)
print(f"wrote docs/effects.png ({len(names)} effects)")
PY
