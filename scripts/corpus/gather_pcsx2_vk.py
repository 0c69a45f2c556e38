#!/usr/bin/env python3
"""PCSX2/pcsx2 Vulkan GS backend (pcsx2/GS/Renderers/Vulkan/GSDeviceVK.cpp) through the TJnotJT/pcsx2
mirror (upstream is over the snapshot limit): the programs built from
bin/resources/shaders/vulkan/*.glsl (gather_pcsx2.py covers the OpenGL backend only), at most six
per shader file.

Stage text as GSDeviceVK builds it: AddShaderHeader (`#version 460 core`,
GL_EXT_samplerless_texture_functions; for a device with texture barriers and
VK_EXT_attachment_feedback_loop_layout, RADV-like: `#define HAS_FEEDBACK_LOOP_LAYOUT 1`; no ROV),
AddShaderStageMacro (`#define VERTEX_SHADER 1` / `FRAGMENT_SHADER 1`), `#define <entry> main` when
an entry point replaces main, then the file (ReadShaderSource, verbatim). VKShaderCache compiles
with shaderc for `shaderc_target_env_vulkan` version 0 (Vulkan 1.0): FLAGS `-V -l`.

- convert.<entry>: convert.glsl vs_main + the first six `#ifdef ps_*` entries of the file, with
  the six HAS_* lines of CompileConvertPipelines before the source (all 0 but HAS_DEPTH_OUTPUT for
  entries whose name says depth, and HAS_FLOAT32_INPUT for the float32 ones);
- present.<entry>: present.glsl vertex + its first six `#ifdef ps_*` entries (PresentShader);
- interlace<i>, merge<i>: `ps_main<i>` for the slots the file defines (<= 6);
- shadeboost (entry main), fxaa (convert.glsl vertex + `#define FXAA_GLSL_VK 1` +
  shaders/common/fxaa.fx with entry ps_main), imgui (vs_main / ps_main);
- cas (compute): cas.glsl with GSDevice::GetCASShaderSource's ffx_a.h / ffx_cas.h replacement,
  no header (GetComputeShader of the text itself);
- tfx.<what>: GetTFXVertexShader / GetTFXFragmentShader for six selector combinations (fields not
  named are 0; provoking_vertex_last 1); the VS_* / PS_* macro order is read from the two functions.
Usage: gather_pcsx2_vk.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, strip_cpp_comments, write_program  # noqa: E402

VKD = "pcsx2/GS/Renderers/Vulkan/GSDeviceVK.cpp"
SH = "bin/resources/shaders/"
FEAT = dict(texture_barrier=True, feedback_loop_layout=True, rov=False, provoking_vertex_last=True)
TFX = [
    ("flat_untextured", {}, dict(tfx=4)),
    ("modulate_tcc", dict(iip=1, tme=1), dict(tfx=0, tcc=1, iip=1)),
    ("modulate_bilinear", dict(iip=1, tme=1), dict(tfx=0, tcc=1, iip=1, ltf=1)),
    ("sprite_fst_region_clamp", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1, wms=2, wmt=2)),
    ("alpha_test_gequal", dict(tme=1, iip=1), dict(tfx=0, tcc=1, iip=1, atst=2, afail=0)),
    ("fog", dict(iip=1, tme=1), dict(tfx=0, tcc=1, iip=1, fog=1)),
]


def body_of(src, head):
    i = src.index(head)
    i = src.index("{", i)
    depth, j = 0, i
    while True:
        if src[j] == "{":
            depth += 1
        elif src[j] == "}":
            depth -= 1
            if depth == 0:
                return src[i + 1:j]
        j += 1


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    vk = strip_cpp_comments(m.text(VKD))
    hdr_body = body_of(vk, "static void AddShaderHeader(")
    header = re.search(r'ss\s*<<\s*"(#version[^"]*)\\n"', hdr_body).group(1) + "\n"
    for ext in re.findall(r'ss\s*<<\s*"(#extension[^"]*)\\n";', hdr_body.split("if (")[0]):
        header += ext + "\n"  # the unconditional ones (the ROV lines come under `if (features.rov)`)
    if FEAT["texture_barrier"] and FEAT["feedback_loop_layout"]:
        header += "#define HAS_FEEDBACK_LOOP_LAYOUT 1\n"
    assert "HAS_FEEDBACK_LOOP_LAYOUT" in hdr_body

    def stage(kind, source, entry=None, pre=""):
        t = header + ("#define VERTEX_SHADER 1\n" if kind == "vertex" else "#define FRAGMENT_SHADER 1\n")
        if entry:
            t += f"#define {entry} main\n"
        return t + pre + source

    progs = []  # (name, [(stage, stem, text)])
    conv = m.text(SH + "vulkan/convert.glsl")
    conv_vs = ("vertex", "convert_vs", stage("vertex", conv))
    cbody = body_of(vk, "bool GSDeviceVK::CompileConvertPipelines(")
    has = re.findall(r'"#define (HAS_\w+) \{\}\\n"', cbody)
    for e in re.findall(r"^#ifdef (ps_\w+)", conv, re.M)[:6]:
        vals = {h: 0 for h in has}
        if "depth" in e:
            vals["HAS_DEPTH_OUTPUT"] = 1
        if "float32" in e:
            vals["HAS_FLOAT32_INPUT"] = 1
        macro = "".join(f"#define {h} {v}\n" for h, v in vals.items())
        progs.append((f"convert.{e}", [conv_vs, ("fragment", "convert_fs", stage("fragment", conv, e, macro))]))
    pres = m.text(SH + "vulkan/present.glsl")
    for e in re.findall(r"^#ifdef (ps_\w+)", pres, re.M)[:6]:
        progs.append((f"present.{e}", [("vertex", "present_vs", stage("vertex", pres)),
                                        ("fragment", "present_fs", stage("fragment", pres, e))]))
    for f in ("interlace", "merge"):
        t = m.text(SH + f"vulkan/{f}.glsl")
        for i in sorted(set(int(x) for x in re.findall(r"^(?:#ifdef ps_main|void ps_main)(\d+)", t, re.M)))[:6]:
            progs.append((f"{f}{i}", [("vertex", f + "_vs", stage("vertex", t)),
                                      ("fragment", f + "_fs", stage("fragment", t, f"ps_main{i}"))]))
    sb = m.text(SH + "vulkan/shadeboost.glsl")
    progs.append(("shadeboost", [("vertex", "shadeboost_vs", stage("vertex", sb)),
                                 ("fragment", "shadeboost_fs", stage("fragment", sb))]))
    fxaa_pre = re.search(r'"(#define FXAA_GLSL_VK 1)\\n"\s*\+\s*\*pshader', vk).group(1) + "\n"
    progs.append(("fxaa", [conv_vs, ("fragment", "fxaa_fs",
                                     stage("fragment", fxaa_pre + m.text(SH + "common/fxaa.fx"), "ps_main"))]))
    im = m.text(SH + "vulkan/imgui.glsl")
    progs.append(("imgui", [("vertex", "imgui_vs", stage("vertex", im, "vs_main")),
                            ("fragment", "imgui_fs", stage("fragment", im, "ps_main"))]))
    cas = m.text(SH + "vulkan/cas.glsl")
    for inc in ("ffx_a.h", "ffx_cas.h"):
        cas = cas.replace(f'#include "{inc}"', m.text(SH + "common/" + inc))
    progs.append(("cas", [("compute", "cas", cas)]))

    tfx = m.text(SH + "vulkan/tfx.glsl")
    vbody = body_of(vk, "VkShaderModule GSDeviceVK::GetTFXVertexShader(")
    pbody = body_of(vk, "VkShaderModule GSDeviceVK::GetTFXFragmentShader(")

    def macros(body, sel):
        s = ""
        for name, expr in re.findall(r'AddMacro\(\s*ss\s*,\s*"(\w+)"\s*,\s*(.*?)\)\s*;', body):
            fm = re.search(r"m_features\.(\w+)", expr)
            if fm:
                v = int(FEAT.get(fm.group(1), False))
            else:
                v = sel.get(re.search(r"sel\.(\w+)", expr).group(1), 0)
            s += f"#define {name} {v}\n"
        return s
    for what, vsel, psel in TFX:
        v = header + "#define VERTEX_SHADER 1\n" + macros(vbody, vsel) + tfx
        p = header + "#define FRAGMENT_SHADER 1\n" + macros(pbody, psel) + tfx
        progs.append((f"tfx.{what}", [("vertex", "tfx_vs", v), ("fragment", "tfx_fs", p)]))
    for name, stages in progs:
        d = write_program(out, "pcsx2vk", name, stages)
        with open(os.path.join(d, "FLAGS"), "w") as fh:
            fh.write("-V -l\n")
    print(len(progs), "programs")


main()
