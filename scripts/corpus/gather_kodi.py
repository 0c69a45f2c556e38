#!/usr/bin/env python3
"""Kodi (xbmc/xbmc) video-player GLSL programs, desktop GL renderer (HAS_GL), paired and
prefixed as the C++ builds them.

Upstream xbmc/xbmc and every recent fork are over the snapshot limit; the newest fork snapshot
that could be fetched is dvdbot/xbmc (master f6cc4f2 of 2017-06-23, Kodi 18.0 ALPHA1 in
development), whose shaders are the flat system/shaders/*.glsl layout (before the GL/1.2,
GL/1.5, GLES/2.0 split). Nothing is prepended but Kodi's own define lines: no `#version`
(GLSL 1.10, compatibility).

Text (xbmc/guilib/Shader.cpp): CShader::LoadSource(file, prefix) reads
system/shaders/<file> and inserts `prefix` before it; AppendSource(file) appends the file;
SetSource(s) takes a C++ string; each stage is one glShaderSource string; CGLSLShaderProgram
attaches vertex + fragment and links.

Programs (LinuxRendererGL.cpp choices):
- YUV2RGBProgressiveShader (YUV2RGBShader.cpp): vertex `yuv2rgb_vertex.glsl`, fragment
  `yuv2rgb_basic.glsl` + `output.glsl`, both with m_defines = GLSLOutput::GetDefines()
  (XBMC_DITHER, XBMC_FULLRANGE, KODI_3DLUT; only in single-pass mode) + XBMC_texture_rectangle
  0/1 + XBMC_texture_rectangle_hack (advancedsetting, default 0) + XBMC_STRETCH 0/1 + the
  format define (XBMC_YV12 / NV12 / YUY2 / UYVY / NV12_RRG); 6 combinations.
  YUV2RGBBobShader is never constructed by the GL renderer and is left out.
- ConvolutionFilterShader (VideoFilterShader.cpp): BaseVideoFilterShader's inline vertex
  string + `convolution-4x4.glsl` / `convolution-6x6.glsl` with HAS_FLOAT_TEXTURE, XBMC_STRETCH,
  GLSLOutput defines and USE1DTEXTURE 1 (HAS_GL), then `output.glsl`; 4 combinations each.
- StretchFilterShader: inline vertex + `stretch.glsl`; DefaultFilterShader: both inline strings.
The GLES renderer's programs (yuv2rgb_*_gles.glsl, guishader_*.glsl) are left out: they carry
no `#version`, which on GLES means GLSL ES 1.00 and on desktop GL (the references here) 1.10.
Usage: gather_kodi.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, strip_cpp_comments, write_program  # noqa: E402

VS = "xbmc/cores/VideoPlayer/VideoRenderers/VideoShaders/"
SH = "system/shaders/"

FORMAT_DEFINE = {"YV12": "#define XBMC_YV12\n", "NV12": "#define XBMC_NV12\n",
                 "YUY2": "#define XBMC_YUY2\n", "UYVY": "#define XBMC_UYVY\n",
                 "NV12_RRG": "#define XBMC_NV12_RRG\n"}
# (texture rectangle, rectangle hack, stretch, format, output defines)
YUV_COMBOS = [
    (0, 0, 0, "YV12", ()),
    (0, 0, 1, "NV12", ("dither",)),
    (1, 0, 0, "YUY2", ()),
    (0, 0, 0, "UYVY", ("dither", "fullrange", "3dlut")),
    (0, 0, 1, "NV12_RRG", ("fullrange",)),
    (1, 1, 1, "YV12", ("dither",)),
]
# (float texture, stretch, output defines)
CONV_COMBOS = [(1, 0, ()), (1, 1, ("dither",)), (0, 0, ("fullrange", "3dlut")),
               (1, 0, ("dither", "fullrange", "3dlut"))]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]

    def shader_file(name):
        return m.text(SH + name)

    # GLSLOutput::GetDefines, HAS_GL branch
    glsl_out = strip_cpp_comments(m.text(VS + "GLSLOutput.cpp"))
    body = re.search(r"GLSLOutput::GetDefines\(\)\s*\{(.*?)\n\}", glsl_out, re.S).group(1)
    out_defs = {}
    for flag, key in (("m_dither", "dither"), ("m_fullRange", "fullrange"), ("m_3DLUT", "3dlut")):
        out_defs[key] = c_string(re.search(r"if\s*\(\s*" + flag + r"\s*\)\s*defines\s*\+=\s*(\"[^\"]*\")", body).group(1))

    def output_defines(keys):
        return "".join(out_defs[k] for k in ("dither", "fullrange", "3dlut") if k in keys)

    yuv = strip_cpp_comments(m.text(VS + "YUV2RGBShader.cpp"))
    for lit in ("#define XBMC_texture_rectangle %d\\n", "#define XBMC_texture_rectangle_hack %d\\n",
                "#define XBMC_STRETCH %d\\n"):
        for v in (0, 1):
            assert '"' + (lit % v) + '"' in yuv, lit
    for d in FORMAT_DEFINE.values():
        assert '"' + d.replace("\n", "\\n") + '"' in yuv, d
    assert 'LoadSource("yuv2rgb_vertex.glsl", m_defines)' in yuv
    assert re.search(r'LoadSource\("yuv2rgb_basic.glsl", m_defines\);\s*PixelShader\(\)->AppendSource\("output.glsl"\)', yuv)
    n = 0
    for rect, hack, stretch, fmt, outs in YUV_COMBOS:
        defines = (output_defines(outs) + f"#define XBMC_texture_rectangle {rect}\n"
                   + f"#define XBMC_texture_rectangle_hack {hack}\n" + f"#define XBMC_STRETCH {stretch}\n"
                   + FORMAT_DEFINE[fmt])
        name = "yuv2rgb_basic." + fmt.lower() + (".rect" if rect else "") + (".hack" if hack else "") + \
            (".stretch" if stretch else "") + "".join("." + o for o in outs)
        write_program(out, "kodi", name, [
            ("vertex", "yuv2rgb_vertex", defines + shader_file("yuv2rgb_vertex.glsl")),
            ("fragment", "yuv2rgb_basic", defines + shader_file("yuv2rgb_basic.glsl") + shader_file("output.glsl"))])
        n += 1

    vf = strip_cpp_comments(m.text(VS + "VideoFilterShader.cpp"))
    base = re.search(r"BaseVideoFilterShader::BaseVideoFilterShader\(\)\s*\{(.*?)\n\}", vf, re.S).group(1)
    inline_v = c_string(re.search(r'std::string\s+shaderv\s*=((?:\s|"(?:\\.|[^"\\])*")*);', base).group(1))
    inline_f = c_string(re.search(r'std::string\s+shaderp\s*=((?:\s|"(?:\\.|[^"\\])*")*);', base).group(1))
    conv = re.search(r"ConvolutionFilterShader::ConvolutionFilterShader\([^)]*\)\s*\{(.*?)\n\}", vf, re.S).group(1)
    files = re.findall(r'shadername\s*=\s*"([^"]+)"', conv)
    assert "USE1DTEXTURE" in vf and '"#define USE1DTEXTURE 1\\n"' in conv
    for f in files:
        for floattex, stretch, outs in CONV_COMBOS:
            defines = (f"#define HAS_FLOAT_TEXTURE {floattex}\n" + f"#define XBMC_STRETCH {stretch}\n"
                       + output_defines(outs) + "#define USE1DTEXTURE 1\n")
            stem = f.rsplit(".", 1)[0]
            name = stem + (".float" if floattex else "") + (".stretch" if stretch else "") + \
                "".join("." + o for o in outs)
            write_program(out, "kodi", name, [
                ("vertex", "videofilter", inline_v),
                ("fragment", stem, defines + shader_file(f) + shader_file("output.glsl"))])
            n += 1
    stretch = re.search(r"StretchFilterShader::StretchFilterShader\(\)\s*\{(.*?)\n\}", vf, re.S).group(1)
    sfile = re.search(r'PixelShader\(\)->LoadSource\("([^"]+)"\)', stretch).group(1)
    write_program(out, "kodi", "stretch", [("vertex", "videofilter", inline_v),
                                          ("fragment", "stretch", shader_file(sfile))])
    write_program(out, "kodi", "default_filter", [("vertex", "videofilter", inline_v),
                                                 ("fragment", "videofilter", inline_f)])
    n += 2
    print(n, "programs")


main()
