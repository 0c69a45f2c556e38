#!/usr/bin/env python3
"""PCSX2/pcsx2 OpenGL GS backend (pcsx2/GS/Renderers/OpenGL/GSDeviceOGL.cpp): the programs
GSDeviceOGL::Create, CompileShadeBoostProgram, CompileFXAAProgram, CreateCASPrograms,
CreateImGuiProgram and SetupPipeline build from bin/resources/shaders/opengl/*.glsl and
shaders/common/ (files read verbatim by ReadShaderSource).

Every graphics stage is GetShaderSource(entry, type, file, macro) = GenGlslHeader(entry, type, macro)
+ file, with GenGlslHeader's lines for a typical desktop GL 4.6 core driver without
EXT_shader_framebuffer_fetch (Mesa radeonsi / NVIDIA): vs_expand (ARB_shader_storage_buffer_object
with vertex SSBOs, ARB_gpu_shader5, DisableVertexShaderExpand off) so `#version 430 core`;
HAS_FRAMEBUFFER_FETCH 0; ARB_conservative_depth (`#extension ... : enable`,
PS_HAS_CONSERVATIVE_DEPTH 1); ARB_texture_barrier with the default DepthFeedbackMode Auto, so
DEPTH_FEEDBACK_SUPPORT 2; ARB_clip_control, HAS_CLIP_CONTROL 1; then `#define VERTEX_SHADER 1` /
`FRAGMENT_SHADER 1`, `#define <entry> main` unless the entry is `main`, and the macro block.

Programs (all fragment programs but present/imgui/tfx use convert.glsl's `vs_main`):
- convert.<ShaderConvert>[.depth][.biln]: ShaderConvertSelector::Get(i) for every i <
  NUM_TOTAL_SHADERS (the valid (shader, depth_out, filter) remaps of GSDevice.cpp, then COPY and
  RTA_CORRECTION with the 16 write masks), entry ShaderEntryPoint(shader), the six HAS_* macros;
  the write masks and the shaders sharing an entry and flags give the same text, kept once.
- date.primid<i>: `ps_primid_image_init_<i>` of convert.glsl for each m_date.primid_ps slot.
- present.<entry>: present.glsl vs_main with each PresentShader entry point.
- merge<i>, interlace<i>: `ps_main<i>` of merge.glsl / interlace.glsl for each m_merge_obj.ps /
  NUM_INTERLACE_SHADERS slot; shadeboost (`ps_main`); fxaa (shaders/common/fxaa.fx, entry `main`,
  `#define FXAA_GLSL_130 1`); imgui (imgui.glsl vs_main + ps_main).
- cas.upscale / cas.sharpen (compute): `#version 420` + GL_ARB_compute_shader +
  `#define CAS_SHARPEN_ONLY false|true` + cas.glsl with GetCASShaderSource's
  `#include "ffx_a.h"` / `"ffx_cas.h"` string replacement.
- tfx.NN.<what>: SetupPipeline's GetVSSource(VSSelector) + GetPSSource(PSSelector) for a fixed
  sample of selector combinations the hardware renderer uses (list below; every field not named is
  0, as a value-initialized selector; HWAA1 off so no AA1). The VS_* / PS_* macro lists and their
  order are read from GetVSSource / GetPSSource.
Usage: gather_pcsx2.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, strip_cpp_comments, write_program  # noqa: E402

OGL = "pcsx2/GS/Renderers/OpenGL/GSDeviceOGL.cpp"
OGL_H = "pcsx2/GS/Renderers/OpenGL/GSDeviceOGL.h"
DEV_H = "pcsx2/GS/Renderers/Common/GSDevice.h"
DEV = "pcsx2/GS/Renderers/Common/GSDevice.cpp"
SH = "bin/resources/shaders/"

# GenGlslHeader's inputs on the assumed driver (see the docstring).
FEAT = dict(vs_expand=True, gl43=True, gpu_shader5=True, framebuffer_fetch=False, ext_fbfetch=False,
            conservative_depth=True, texture_barrier=True, multidraw_fb_copy=False, depth_feedback=False,
            clip_control=True)

# (name, VSSelector fields, PSSelector fields): draws of GSRendererHW on that driver.
TFX = [
    ("flat_untextured", {}, dict(tfx=4)),
    ("gouraud_untextured", dict(iip=1), dict(tfx=4, iip=1)),
    ("modulate_tcc", dict(iip=1, tme=1), dict(tfx=0, tcc=1, iip=1)),
    ("modulate_bilinear", dict(iip=1, tme=1), dict(tfx=0, tcc=1, iip=1, ltf=1)),
    ("decal", dict(tme=1), dict(tfx=1, tcc=1)),
    ("highlight", dict(iip=1, tme=1), dict(tfx=2, tcc=1, iip=1)),
    ("highlight2_rgb", dict(iip=1, tme=1), dict(tfx=3, tcc=0, iip=1)),
    ("sprite_fst", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1)),
    ("sprite_fst_region_clamp", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1, wms=2, wmt=2)),
    ("region_repeat", dict(tme=1, iip=1), dict(tfx=0, tcc=1, iip=1, wms=3, wmt=3, ltf=1)),
    ("region_rect", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1, region_rect=1, wms=1, wmt=1)),
    ("lines", dict(iip=1, expand=2), dict(tfx=4, iip=1)),
    ("points_vs_expand", dict(expand=1), dict(tfx=4)),
    ("points_hw_size", dict(point_size=1), dict(tfx=4)),
    ("alpha_test_gequal", dict(tme=1, iip=1), dict(tfx=0, tcc=1, iip=1, atst=2, afail=0)),
    ("alpha_test_fb_only", dict(tme=1), dict(tfx=0, tcc=1, atst=1, afail=1)),
    ("alpha_test_rgb_only", dict(tme=1), dict(tfx=0, tcc=1, atst=3, afail=3)),
    ("alpha_test_notequal_zb_only", dict(tme=1), dict(tfx=0, tcc=1, atst=4, afail=2)),
    ("fog", dict(iip=1, tme=1), dict(tfx=0, tcc=1, iip=1, fog=1)),
    ("pal8_aem", dict(tme=1), dict(tfx=0, tcc=1, pal_fmt=1, aem_fmt=0, aem=1)),
    ("pal4", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1, pal_fmt=2)),
    ("aem_fmt24", dict(tme=1), dict(tfx=0, tcc=1, aem_fmt=1, aem=1)),
    ("aem_fmt16_ltf", dict(tme=1), dict(tfx=0, tcc=1, aem_fmt=2, ltf=1)),
    ("date_primid_init", dict(iip=1), dict(tfx=4, iip=1, date=1)),
    ("date_primid_tracking", dict(iip=1), dict(tfx=4, iip=1, date=3)),
    ("date_barrier", dict(tme=1), dict(tfx=0, tcc=1, date=5)),
    ("sw_blend_mix", dict(iip=1, tme=1), dict(tfx=0, tcc=1, iip=1, blend_a=0, blend_b=1, blend_c=0, blend_d=1,
                                               blend_mix=1, no_color1=0)),
    ("sw_blend_full_colclip", dict(tme=1), dict(tfx=0, tcc=1, blend_a=1, blend_b=0, blend_c=2, blend_d=0,
                                                colclip=1, fixed_one_a=1)),
    ("hw_blend_accu", dict(tme=1), dict(tfx=0, tcc=1, blend_a=0, blend_b=2, blend_c=0, blend_d=1, blend_hw=2)),
    ("colclip_hw_round_inv", dict(iip=1), dict(tfx=4, iip=1, colclip_hw=1, blend_a=1, blend_b=0, blend_c=1,
                                               blend_d=2, round_inv=1, a_masked=1)),
    ("fbmask_dither_16bit", dict(tme=1), dict(tfx=0, tcc=1, fbmask=1, dst_fmt=2, dither=1)),
    ("dither_adjust_pabe", dict(iip=1), dict(tfx=4, iip=1, dst_fmt=2, dither=2, dither_adjust=1, pabe=1,
                                              blend_a=0, blend_b=1, blend_c=0, blend_d=1)),
    ("channel_red", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1, channel=1, depth_fmt=0)),
    ("channel_gxby_depth", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1, channel=5, depth_fmt=1)),
    ("depth_as_texture16", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1, depth_fmt=2, ltf=0)),
    ("shuffle_read16", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1, shuffle=1, real16src=1,
                                                           dst_fmt=2, process_ba=3, process_rg=3)),
    ("shuffle_across_write_rg", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1, shuffle=1,
                                                                    shuffle_across=1, write_rg=1, process_rg=1)),
    ("tex_is_fb_sw_ztest", dict(fst=1, tme=1, expand=3), dict(fst=1, tfx=0, tcc=1, tex_is_fb=1, ztst=2)),
    ("zclamp_zfloor_lod", dict(tme=1, iip=1), dict(tfx=0, tcc=1, iip=1, zclamp=1, zfloor=1, automatic_lod=1,
                                                   ltf=1, rta_correction=1)),
    ("aniso_manual_lod_scanmsk", dict(tme=1), dict(tfx=0, tcc=1, ltf=1, sw_aniso=4, manual_lod=1, scanmsk=2,
                                                   rta_source_correction=1)),
]


def body_of(src, head):
    """The brace-balanced body following the first match of the regex `head`."""
    m = re.search(head, src)
    i = src.index("{", m.end())
    depth, j = 0, i
    while True:
        depth += {"{": 1, "}": -1}.get(src[j], 0)
        j += 1
        if depth == 0:
            return src[i:j]


def switch_table(src, func, enum):
    """{enumerator: returned value} and the default of a `switch` over `enum` in function `func`."""
    body = body_of(src, rf"\b{func}\s*\(\s*{enum}\s+\w+\s*\)\s*(?:const\s*)?(?=\{{)")
    table, labels, default = {}, [], None
    for t in re.finditer(rf"case\s+{enum}::(\w+)\s*:|default\s*:|return\s+([^;]+);", body):
        if t.group(1):
            labels.append(t.group(1))
        elif t.group(0).startswith("default"):
            labels.append(None)
        else:
            val = t.group(2).strip()
            val = c_string(val) if val.startswith('"') else {"true": 1, "false": 0}.get(val, val)
            val = int(val) if isinstance(val, str) and val.isdigit() else val
            for lab in labels:
                if lab is None:
                    default = val
                else:
                    table[lab] = val
            labels = []
    return table, default


def enumerators(src, enum):
    body = body_of(src, rf"enum\s+class\s+{enum}\b[^{{]*")
    return [x for x in re.findall(r"^\s*(\w+)", body.strip("{}"), re.M) if x != "Count"]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    ogl = strip_cpp_comments(m.text(OGL))
    dev_h = strip_cpp_comments(m.text(DEV_H))
    dev = strip_cpp_comments(m.text(DEV))
    ogl_h = strip_cpp_comments(m.text(OGL_H))
    read = lambda p: m.text(SH + p)

    # GenGlslHeader, checked against the strings of the C++ code.
    gen = body_of(ogl, r"std::string\s+GSDeviceOGL::GenGlslHeader\([^)]*\)")
    lits = set(re.findall(r'"(?:\\.|[^"\\])*"', gen))
    q = lambda s: '"' + s.replace("\n", "\\n") + '"'

    def need(s):
        if q(s) not in lits:
            raise SystemExit(f"GenGlslHeader no longer has {s!r}")
        return s

    def header(entry, stage, macro=""):
        f = FEAT
        if f["vs_expand"] and f["gl43"]:
            h = need("#version 430 core\n")
        else:
            h = need("#version 330 core\n") + need("#extension GL_ARB_shading_language_420pack : require\n")
            h += need("#extension GL_ARB_gpu_shader5 : require\n") if f["gpu_shader5"] else ""
            h += need("#extension GL_ARB_shader_storage_buffer_object: require\n") if f["vs_expand"] else ""
        if f["framebuffer_fetch"] and f["ext_fbfetch"]:
            h += need("#extension GL_EXT_shader_framebuffer_fetch : require\n")
        h += need("#define HAS_FRAMEBUFFER_FETCH 1\n" if f["framebuffer_fetch"] else "#define HAS_FRAMEBUFFER_FETCH 0\n")
        if f["conservative_depth"]:
            h += need("#extension GL_ARB_conservative_depth : enable\n") + need("#define PS_HAS_CONSERVATIVE_DEPTH 1\n")
        else:
            h += need("#define PS_HAS_CONSERVATIVE_DEPTH 0\n")
        if not f["texture_barrier"] and not f["multidraw_fb_copy"]:
            h += need("#define DEPTH_FEEDBACK_SUPPORT 0\n")
        elif f["depth_feedback"]:
            h += need("#define DEPTH_FEEDBACK_SUPPORT 1\n")
        else:
            h += need("#define DEPTH_FEEDBACK_SUPPORT 2\n")
        h += need("#define HAS_CLIP_CONTROL 1\n" if f["clip_control"] else "#define HAS_CLIP_CONTROL 0\n")
        h += need({"vertex": "#define VERTEX_SHADER 1\n", "fragment": "#define FRAGMENT_SHADER 1\n"}[stage])
        if entry != "main":
            h += f"#define {entry} main\n"
        return h + macro

    src_of = lambda entry, stage, glsl, macro="": header(entry, stage, macro) + glsl
    n, seen = 0, {}

    def program(name, stages):
        nonlocal n
        key = tuple(t for _, _, t in stages)
        if key in seen:
            return
        seen[key] = name
        write_program(out, "pcsx2", name, stages)
        n += 1

    # convert.glsl
    convert = read("opengl/convert.glsl")
    conv_vs = ("vertex", "convert_vs_main", src_of("vs_main", "vertex", convert))
    shaders = enumerators(dev_h, "ShaderConvert")
    tab = lambda f: (lambda t: (lambda s: t[0].get(s, t[1])))(switch_table(dev_h, f, "ShaderConvert"))
    variable_mask, color_out = tab("HasVariableWriteMask"), tab("HasColorOutput")
    f32out, f32in, datm = tab("HasFloat32Output"), tab("HasFloat32Input"), tab("IsDATMConvertShader")
    int_bpp, biln_ok = tab("IntegerOutputBpp"), tab("SupportsBilinear")
    entry_of = (lambda t: lambda s: t[0].get(s, t[1]))(switch_table(dev, "ShaderEntryPoint", "ShaderConvert"))
    sels = []
    for idx in range(len(shaders) * 4):  # GetPackedShaders: the RemapIndexIsValid indices, in order
        s, depth_out, biln = shaders[idx >> 2], idx & 1, (idx >> 1) & 1
        if variable_mask(s) and not depth_out and not biln:
            continue
        if (depth_out and not f32out(s)) or (biln and not biln_ok(s)):
            continue
        sels.append((s, depth_out, biln))
    sels += [(s, 0, 0) for s in shaders if variable_mask(s) for _mask in range(16)]
    loop = body_of(ogl, r"for\s*\(u32 i = 0; i < ShaderConvertSelector::NUM_TOTAL_SHADERS; i\+\+\)")
    conv_macros = re.findall(r'fmt::format\("#define (\w+) \{\}\\n",\s*static_cast<int>\(shader\.(\w+)\(\)(\s*!=\s*0)?\)\)', loop)
    for s, depth_out, biln in sels:
        vals = {"Biln": biln, "StencilOutput": datm(s), "IntegerOutputBpp": int_bpp(s), "DepthOutput": depth_out,
                "Float32Input": f32in(s), "Float32Output": f32out(s)}
        macro = "".join(f"#define {name} {int(bool(vals[meth])) if nz or meth != 'IntegerOutputBpp' else vals[meth]}\n"
                        for name, meth, nz in conv_macros)
        name = "convert." + s + (".depth" if depth_out else "") + (".biln" if biln else "")
        program(name, [conv_vs, ("fragment", entry_of(s), src_of(entry_of(s), "fragment", convert, macro))])
    del color_out

    # DATE primitive-ID init
    slots = int(re.search(r"primid_ps\[(\d+)\]", ogl_h).group(1))
    for i in range(slots):
        e = f"ps_primid_image_init_{i}"
        program(f"date.primid{i}", [conv_vs, ("fragment", e, src_of(e, "fragment", convert))])

    # present.glsl
    present = read("opengl/present.glsl")
    pvs = ("vertex", "present_vs_main", src_of("vs_main", "vertex", present))
    ptab, _ = switch_table(dev, "ShaderEntryPoint", "PresentShader")
    for p in enumerators(dev_h, "PresentShader"):
        program(f"present.{ptab[p]}", [pvs, ("fragment", ptab[p], src_of(ptab[p], "fragment", present))])

    # merge / interlace
    merge_n = int(re.search(r"GLProgram\s+ps\[(\d+)\];[^}]*\}\s*m_merge_obj", ogl_h).group(1))
    inter_n = int(re.search(r"NUM_INTERLACE_SHADERS\s*=\s*(\d+)", dev_h).group(1))
    for file, count in (("merge", merge_n), ("interlace", inter_n)):
        text = read(f"opengl/{file}.glsl")
        for i in range(count):
            program(f"{file}{i}", [conv_vs, ("fragment", f"{file}_ps_main{i}", src_of(f"ps_main{i}", "fragment", text))])

    # shadeboost, fxaa, imgui
    program("shadeboost", [conv_vs, ("fragment", "shadeboost", src_of("ps_main", "fragment", read("opengl/shadeboost.glsl")))])
    fx = body_of(ogl, r"bool\s+GSDeviceOGL::CompileFXAAProgram\(\)")
    fxaa_macro = c_string(re.search(r"fxaa_macro\s*=\s*(\"[^;]*);", fx).group(1))
    fxaa_entry = c_string(re.search(r'GetShaderSource\(\s*("\w+")', fx).group(1))
    program("fxaa", [conv_vs, ("fragment", "fxaa", src_of(fxaa_entry, "fragment", read("common/fxaa.fx"), fxaa_macro))])
    imgui = read("opengl/imgui.glsl")
    program("imgui", [("vertex", "imgui", src_of("vs_main", "vertex", imgui)),
                      ("fragment", "imgui", src_of("ps_main", "fragment", imgui))])

    # CAS compute programs
    cas_fn = body_of(ogl, r"bool\s+GSDeviceOGL::CreateCASPrograms\(\)")
    cas_head = c_string(re.search(r"const char\*\s*header\s*=\s*([^;]*);", cas_fn).group(1))
    params = [c_string(x) for x in re.findall(r'"(?:\\.|[^"\\])*"', re.search(r"sharpen_params\[2\]\s*=\s*\{([^}]*)\}", cas_fn).group(1))]
    cas = read("opengl/cas.glsl")
    for inc in ("ffx_a.h", "ffx_cas.h"):
        cas = cas.replace(f'#include "{inc}"', read(f"common/{inc}"))
    for tag, p in zip(("upscale", "sharpen"), params):
        program(f"cas.{tag}", [("compute", "cas", cas_head + p + cas)])

    # tfx: SetupPipeline(GetVSSource(vs), GetPSSource(ps))
    vgs, fs = read("opengl/tfx_vgs.glsl"), read("opengl/tfx_fs.glsl")
    fmt = r'fmt::format\("#define (\w+) \{\}\\n",\s*(?:static_cast<\w+>\()?(sel\.\w+|\d+)\)?\)'
    vs_list = re.findall(fmt, body_of(ogl, r"std::string\s+GSDeviceOGL::GetVSSource\([^)]*\)"))
    ps_list = re.findall(fmt, body_of(ogl, r"std::string\s+GSDeviceOGL::GetPSSource\([^)]*\)"))
    ps_fields = set(re.findall(r"u32\s+(\w+)\s*:", body_of(dev_h, r"struct\s+PSSelector\b"))) | \
        set(re.findall(r"PS_\w+\s+(\w+)\s*:", body_of(dev_h, r"struct\s+PSSelector\b")))
    for k, (what, vsel, psel) in enumerate(TFX):
        bad = set(psel) - ps_fields
        if bad:
            raise SystemExit(f"PSSelector has no {bad}")
        mac = lambda lst, sel: "".join(f"#define {name} {sel.get(v[4:], 0) if v.startswith('sel.') else v}\n" for name, v in lst)
        program(f"tfx.{k:02d}.{what}", [("vertex", "tfx_vgs", header("vs_main", "vertex", mac(vs_list, vsel)) + vgs),
                                        ("fragment", "tfx_fs", header("ps_main", "fragment", mac(ps_list, psel)) + fs)])
    print(n, "programs")


main()
