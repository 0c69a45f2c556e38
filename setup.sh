#!/usr/bin/env bash
# Installs what effectc needs on a fresh Debian machine, then builds it (release).
# System packages: glslang-tools and spirv-tools (peer tools for the benchmark and corpus
# scripts), mesa-vulkan-drivers + libvulkan1 (lavapipe, the CPU Vulkan used for rendering),
# ffmpeg (ffmpeg and ffprobe: the test that pipes `effectc render --out -` into ffmpeg),
# g++ (the `glslang-sys` crate builds the Khronos reference compiler from its C++ source),
# libegl1 + libegl-mesa0 + libgl1-mesa-dri (Mesa's OpenGL driver, headless through EGL:
# what `effectc verify` compares every translation with).
set -euo pipefail
cd "$(dirname "$0")"
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
if command -v apt-get >/dev/null; then
    missing=""
    for pkg in glslang-tools spirv-tools mesa-vulkan-drivers libvulkan1 ffmpeg g++ libegl1 libegl-mesa0 libgl1-mesa-dri; do
        dpkg -s "$pkg" >/dev/null 2>&1 || missing="$missing $pkg"
    done
    if [ -n "$missing" ]; then
        $SUDO apt-get update -qq
        DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq $missing
    fi
fi
command -v cargo >/dev/null || { echo "setup.sh: cargo not found; install Rust (rustup) first" >&2; exit 2; }
# rustfmt and clippy for .ci/run's habits (already there on most rustup installs).
if command -v rustup >/dev/null; then rustup component add rustfmt clippy >/dev/null 2>&1 || true; fi
cargo build --release
