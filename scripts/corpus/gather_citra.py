#!/usr/bin/env python3
"""Citra's host shaders (src/video_core/host_shaders), OpenGL and Vulkan, paired as the renderers
load them. Read from the PabloMK7/citra mirror: its master is now a single "Azahar Notice" commit,
so the newest tag whose tree still has the host shaders is used (r608383e, 2024-09-28; a COMMIT
argument overrides).

Embedding (host_shaders/CMakeLists.txt + StringShaderHeader.cmake): each SHADER_FILES file becomes
`HostShaders::<NAME>` (file name upper-cased, `.` -> `_`) through CMake: `"` -> `'`, `;` masked,
lines split at `\\n` into a CMake list and re-joined as `"<line>\\n"` literals. A line ending in a
backslash makes `\\;`, which the list expansion keeps in the element as `;` and the unquoted
`${line}` argument then splits away: backslash-newline continuations are joined (no text between
the two lines). Empty lines are kept (`foreach(IN LISTS)`), so the text ends with one extra `\\n`.

OpenGL (desktop branch; GLES's `#version 320 es` preamble not gathered), written to GL_OUT_DIR:
OpenGL::LoadShader (gl_shader_util.cpp) compiles `"#version 430 core\\n"` + source as two strings.
gl_blit_helper.cpp's `CreateProgram(HostShaders::F)` links F with CreateProgram's
`program.Create(HostShaders::FULL_SCREEN_TRIANGLE_VERT, frag)`; RendererOpenGL::ReloadShader links
OPENGL_PRESENT_VERT with `fragment_shader_precision_OES` (glsl_shader_gen.h) + each built-in
`shader_data += HostShaders::F` (default, anaglyph dubois, interlaced; user post-processing
shaders are files in the user's directory, none ship with the source).

Vulkan, written to VK_OUT_DIR: Vulkan::Compile (vk_shader_util.cpp) parses one string with
glslang, Vulkan rules, `setEnvTarget(SPIR-V 1.3)` (client left at Vulkan 1.0), defaultVersion 450
core for a text without #version (full_screen_triangle.vert: written with `#version 450 core`
prepended, its `#ifdef VULKAN` branch taken as glslang predefines VULKAN), and the call's preamble
(before the text; written after the #version line). RendererVulkan::CompileShaders: present
vertex shader + each `present_shaders[i]` fragment compiled with preamble `"#define
ARRAY_DYNAMIC_INDEX"` when the device supports it, else "" (both written, `.ARRAY_DYNAMIC_INDEX`);
vk_blit_helper.cpp: `MakeStages(vert, frag)` graphics pipelines and `MakeComputePipeline(comp, ..)`
compute pipelines of the member modules `x{Compile(HostShaders::Y, eStage, device)}`.
Vulkan programs get FLAGS `-V --target-env spirv1.3 -l` (glslang's Vulkan 1.0 client, SPIR-V 1.3).
Usage: gather_citra.py MIRROR_GIT_DIR VK_OUT_DIR GL_OUT_DIR [COMMIT]
"""
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from granite_common import GitTree  # noqa: E402
from mirror import write_program, strip_cpp_comments, c_string  # noqa: E402

HS = "src/video_core/host_shaders/"
EXT_STAGE = {"vert": "vertex", "frag": "fragment", "comp": "compute", "geom": "geometry"}


def pick_commit(git_dir):
    """HEAD when it has the host shaders, else the newest tag that does."""
    def has(c):
        return subprocess.run(["git", f"--git-dir={git_dir}", "cat-file", "-e", f"{c}:{HS}CMakeLists.txt"],
                              capture_output=True).returncode == 0
    if has("HEAD"):
        return "HEAD"
    tags = subprocess.run(["git", f"--git-dir={git_dir}", "for-each-ref", "--sort=-committerdate",
                           "--format=%(objectname)", "refs/tags"], capture_output=True, text=True).stdout.split()
    for c in tags:
        if has(c):
            return c
    sys.exit("no commit with " + HS)


def cmake_list_split(value, keep_empty):
    """cmExpandList: split at `;` outside [], `\\;` is a literal `;`."""
    out, cur, nest, i = [], "", 0, 0
    while i < len(value):
        c = value[i]
        if c == "\\" and value[i + 1:i + 2] == ";":
            cur += ";"
            i += 2
            continue
        if c == "[":
            nest += 1
        elif c == "]":
            nest -= 1
        if c == ";" and nest == 0:
            if cur or keep_empty:
                out.append(cur)
            cur = ""
        else:
            cur += c
        i += 1
    if cur or keep_empty:
        out.append(cur)
    return out


def embedded(text):
    """The string HostShaders::X holds for a source file (StringShaderHeader.cmake)."""
    text = text.replace('"', "'").replace(";", "{{SEMICOLON}}").replace("\n", ";")
    contents = ""
    for line in cmake_list_split(text, keep_empty=True):
        # string(CONCAT CONTENTS "${CONTENTS}" \"${line}\\n\"): the unquoted argument is split at
        # the `;` that remain in ${line}, CONCAT joins the pieces
        contents += "".join(cmake_list_split('"' + line + '\\n"', keep_empty=False))
    contents = contents.replace("{{SEMICOLON}}", ";")
    return c_string(contents)


def after_version(text, pre):
    v = re.search(r"^[ \t]*#[ \t]*version[^\n]*\n", text, re.M)
    return text[:v.end()] + pre + text[v.end():] if v else pre + text


def main():
    git_dir, vk_out, gl_out = sys.argv[1:4]
    commit = sys.argv[4] if len(sys.argv) > 4 else pick_commit(git_dir)
    tree = GitTree(git_dir, commit)
    cm = re.sub(r"#[^\n]*", "", tree.text(HS + "CMakeLists.txt"))
    files = re.search(r"set\(\s*SHADER_FILES\s+([^)]*)\)", cm).group(1).split()
    shaders = {}  # HostShaders name -> (stem, stage, text)
    for f in files:
        name = os.path.basename(f).replace(".", "_").upper()
        stem, ext = os.path.basename(f).rsplit(".", 1)
        shaders[name] = (stem, EXT_STAGE[ext], embedded(tree.text(HS + f)))

    def src(path):
        return strip_cpp_comments(tree.text(path))

    # OpenGL
    util = src("src/video_core/renderer_opengl/gl_shader_util.cpp")
    gl_pre = c_string(re.search(r"\}\s*else\s*\{\s*preamble\s*=\s*([^;]*);", util).group(1))
    precision = c_string(re.search(r"fragment_shader_precision_OES\[\]\s*=\s*(R\"[^(]*\((?:.|\n)*?\)[^\"]*\")",
                                   tree.text("src/video_core/shader/generator/glsl_shader_gen.h")).group(1))
    gl_programs = []
    blit = src("src/video_core/renderer_opengl/gl_blit_helper.cpp")
    cp = re.search(r"OGLProgram\s+CreateProgram\s*\([^)]*\)\s*\{(.*?)\n\}", blit, re.S).group(1)
    vert = re.search(r"\.Create\(\s*HostShaders::(\w+)\s*,", cp).group(1)
    for frag in dict.fromkeys(re.findall(r"\bCreateProgram\(\s*HostShaders::(\w+)\s*\)", blit)):
        gl_programs.append([(vert, ""), (frag, "")])
    ren = src("src/video_core/renderer_opengl/renderer_opengl.cpp")
    body = re.search(r"void\s+RendererOpenGL::ReloadShader\(\)\s*\{(.*?)\n\}", ren, re.S).group(1)
    assert re.search(r"std::string\s+shader_data\s*=\s*fragment_shader_precision_OES\s*;", body)
    vert = re.search(r"shader\.Create\(\s*HostShaders::(\w+)\s*,\s*shader_data\s*\)", body).group(1)
    for frag in dict.fromkeys(re.findall(r"shader_data\s*\+=\s*HostShaders::(\w+)", body)):
        gl_programs.append([(vert, ""), (frag, precision)])
    for prog in gl_programs:
        stages = [(shaders[n][1], shaders[n][0], gl_pre + pre + shaders[n][2]) for n, pre in prog]
        write_program(gl_out, "citra", "+".join(shaders[n][0] for n, _ in prog), stages)

    # Vulkan
    def vk_text(name, preamble):
        text = shaders[name][2]
        if not re.search(r"^[ \t]*#[ \t]*version", text, re.M):
            text = "#version 450 core\n" + text
        return after_version(text, preamble + "\n") if preamble else text

    vk_programs = []  # (name, [(HostShaders name, preamble)])
    rv = src("src/video_core/renderer_vulkan/renderer_vulkan.cpp")
    body = re.search(r"void\s+RendererVulkan::CompileShaders\(\)\s*\{(.*?)\n\}", rv, re.S).group(1)
    pm = re.search(r"preamble\s*=\s*[^;?]*\?\s*(\"[^\"]*\")\s*:\s*(\"[^\"]*\")\s*;", body)
    preambles = list(dict.fromkeys(c_string(x) for x in pm.groups())) if pm else [""]
    vert = re.search(r"present_vertex_shader\s*=\s*Compile\(\s*HostShaders::(\w+)", body).group(1)
    for m in re.finditer(r"present_shaders\[\d+\]\s*=\s*Compile\(\s*HostShaders::(\w+)[^;]*?(\bpreamble)?\s*\)\s*;", body):
        for pre in (preambles if m.group(2) else [""]):
            vk_programs.append([(vert, ""), (m.group(1), pre)])
    bh = src("src/video_core/renderer_vulkan/vk_blit_helper.cpp")
    modules = {m.group(1): m.group(2) for m in re.finditer(r"(\w+)\{Compile\(\s*HostShaders::(\w+)\s*,", bh)}
    for m in re.finditer(r"MakeStages\(\s*(\w+)\s*,\s*(\w+)\s*\)", bh):
        vk_programs.append([(modules[m.group(1)], ""), (modules[m.group(2)], "")])
    for m in re.finditer(r"\{\s*MakeComputePipeline\(\s*(\w+)\s*,", bh):
        vk_programs.append([(modules[m.group(1)], "")])
    for prog in vk_programs:
        name = "+".join(shaders[n][0] for n, _ in prog) + "".join(
            "." + re.sub(r"#define\s+", "", p) for p in dict.fromkeys(p for _, p in prog if p))
        d = write_program(vk_out, "citra", name, [(shaders[n][1], shaders[n][0], vk_text(n, p)) for n, p in prog])
        with open(os.path.join(d, "FLAGS"), "w") as fh:
            fh.write("-V --target-env spirv1.3 -l\n")
    print(len(gl_programs), "OpenGL programs,", len(vk_programs), "Vulkan programs (commit", commit + ")")


if __name__ == "__main__":
    main()
