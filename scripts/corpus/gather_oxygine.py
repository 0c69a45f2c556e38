#!/usr/bin/env python3
"""oxygine/oxygine-framework (2D engine) programs as a desktop SDL build (GL 2.x compatibility
context, not GLES, not Emscripten) compiles them.

ShaderProgramGL::createShader(type, data, prepend = "", append = "") gives glShaderSource the
strings: `#define lowp\\n#define mediump\\n#define highp\\n` (the `!gles` branch), prepend when
non-null, data, append when non-null. No #version: GLSL 1.10.

- The uber shader: STDRenderer::initialize reads system/shader.glsl from the system_data zip
  embedded in core/system_data.cpp (no shader.glsl in an app's data), UberShaderProgramBase::init
  (body, prepend="", append="") puts prepend before and append after the body, and
  UberShaderProgram::getShaderProgram(flags) compiles the fragment stage with the flag defines
  (ALPHA_PREMULTIPLY, SEPARATE_ALPHA, MASK_R_CHANNEL, MASK, ADD_COLOR in that order) +
  `#define program_main_ps main\\n#define PS\\n` and the vertex stage with the flag defines +
  `#define program_main_vs main\\n#define VS\\n`, as prepend (append ""): all 32 flag sets
  (`uber.f<flags>`, the enum values read from UberShaderProgram.h).
- examples/Demo TestUserShader's three UberShaderPrograms (init(uberShaderBody, R"(...)")) at the
  flags a Sprite with a premultiplied-alpha atlas draws with (Material adds ADD_COLOR):
  ALPHA_PREMULTIPLY | ADD_COLOR, and ADD_COLOR alone.
- PostProcess: blur V/H x pp_rast_fs / pp_rast_fs2 (createShader(type, data): prepend "",
  append "") and the blit program, files from the same zip.
- examples' inline programs: Demo TestOpenGL (R"()" literals) and DemoBox2D Box2DDebugDraw
  (createShader(type, data, 0, 0): no prepend/append strings).
Usage: gather_oxygine.py MIRROR_GIT_DIR OUT_DIR
"""
import io
import os
import re
import sys
import zipfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, c_string_vars, strip_cpp_comments, write_program  # noqa: E402

SRC = "oxygine/src/oxygine/"
FLAG_ORDER = ["ALPHA_PREMULTIPLY", "SEPARATE_ALPHA", "MASK_R_CHANNEL", "MASK", "ADD_COLOR"]


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    sgl = strip_cpp_comments(m.text(SRC + "core/gl/ShaderProgramGL.cpp"))
    non_gles = c_string(re.search(r"nonGLES\[\]\s*=([^;]*);", sgl).group(1))
    if not re.search(r"if \(prepend\)\s*\{\s*\*ptr = prepend;.*?\*ptr = data;.*?if \(append\)", sgl, re.S):
        raise SystemExit("ShaderProgramGL::createShader's source order changed")
    blob = m.text(SRC + "core/system_data.cpp").split("system_data[]", 1)[1]
    z = zipfile.ZipFile(io.BytesIO(bytes(int(x, 16) for x in re.findall(r"0x([0-9a-fA-F]{2})", blob))))
    sysfile = lambda name: z.read("system/" + name).decode("utf-8")

    def shader(data, prepend="", append=""):
        return non_gles + (prepend or "") + data + (append or "")

    # UberShaderProgram.
    uh = m.text(SRC + "core/UberShaderProgram.h")
    bits = {k: eval(v) for k, v in re.findall(r"\b(" + "|".join(FLAG_ORDER) + r")\s*=\s*([^,\n]+)", uh)}
    uc = strip_cpp_comments(m.text(SRC + "core/UberShaderProgram.cpp"))
    order = re.findall(r'if \(flags & (\w+)\)\s*strcat\(prepend, "#define (\w+)\\n"\);', uc)
    if [a for a, _ in order] != FLAG_ORDER or any(a != b for a, b in order):
        raise SystemExit("UberShaderProgram::getShaderProgram's defines changed")
    body = sysfile("shader.glsl")

    def uber(name, data, flags):
        pre = "".join(f"#define {f}\n" for f in FLAG_ORDER if flags & bits[f])
        write_program(out, "oxygine", name, [
            ("vertex", "shader", shader(data, pre + "#define program_main_vs main\n#define VS\n", "")),
            ("fragment", "shader", shader(data, pre + "#define program_main_ps main\n#define PS\n", ""))])

    n = 0
    for flags in range(1 << len(FLAG_ORDER)):
        uber(f"uber.f{flags:02d}", body, flags)
        n += 1
    tus = strip_cpp_comments(m.text("examples/Demo/src/TestUserShader.h"))
    for var, lit in re.findall(r'(_shader\w+)->init\(STDRenderer::uberShaderBody,\s*(R"\((?:.|\n)*?\)")\s*\)', tus):
        user = c_string_vars(f"x = {lit};")["x"][0]
        for flags in (bits["ALPHA_PREMULTIPLY"] | bits["ADD_COLOR"], bits["ADD_COLOR"]):
            uber(f"user{var}.f{flags:02d}", user + body, flags)
            n += 1
    # PostProcess.
    for vs in ("pp_vblur_vs", "pp_hblur_vs"):
        for fs in ("pp_rast_fs", "pp_rast_fs2"):
            write_program(out, "oxygine", f"postprocess.{vs}.{fs}", [
                ("vertex", vs, shader(sysfile(vs + ".glsl"))), ("fragment", fs, shader(sysfile(fs + ".glsl")))])
            n += 1
    write_program(out, "oxygine", "postprocess.blit", [
        ("vertex", "pp_blit_vs", shader(sysfile("pp_blit_vs.glsl"))),
        ("fragment", "pp_blit_fs", shader(sysfile("pp_blit_fs.glsl")))])
    n += 1
    # Example inline programs.
    for path, name, pre in (("examples/Demo/src/TestOpenGL.h", "demo.opengl_sprite", ""),
                            ("examples/DemoBox2D/src/Box2DDebugDraw.cpp", "box2d.debugdraw", None)):
        s = c_string_vars(strip_cpp_comments(m.text(path)))
        write_program(out, "oxygine", name, [
            ("vertex", "vertex", shader(s["vertexShaderData"][0], pre, pre)),
            ("fragment", "fragment", shader(s["fragmentShaderData"][0], pre, pre))])
        n += 1
    print(n, "programs")


main()
