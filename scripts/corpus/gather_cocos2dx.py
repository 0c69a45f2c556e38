#!/usr/bin/env python3
"""cocos2d-x 3.x built-in programs as GLProgramCache::loadDefaultGLProgram makes them on desktop
Linux (GL 2.x context, GLSL without #version: 1.10).

Stage texts: the `const char* ccX_vert = R"(...)";` literals of the renderer/ccShader_* files
that renderer/ccShaders.cpp #includes. Pairs: every `case kShaderType_*:` of
GLProgramCache::loadDefaultGLProgram(p, type) (loadDefaultGLPrograms loads each type), its
`p->initWithByteArrays(vert, frag)` arguments evaluated: a shader variable, or
`(def [+ normalMapDef] + std::string(var)).c_str()` where def = getShaderMacrosForLight()
(MAX_DIRECTIONAL/POINT/SPOT_LIGHT_NUM from Configuration's defaults, read from CCConfiguration.cpp's
constructor initializers) and other std::string locals are the case's own literals.

Text per stage as GLProgram::compileShader(shader, type, source, compileTimeHeaders="",
convertedDefines) gives glShaderSource four strings: headersDef (empty on LINUX/WIN32/MAC: the
precision headers are for WinRT, Android and the other mobile targets), COCOS2D_SHADER_UNIFORMS
(CCGLProgram.cpp), the converted compile-time defines (none for the default programs), source.

The copy of the engine used is cocos2d-x 3.17.2 as vendored by a game project
(frameworks/cocos2d-x, one import commit), because cocos2d/cocos2d-x is over the snapshot limit.
Usage: gather_cocos2dx.py MIRROR_GIT_DIR OUT_DIR [ENGINE_PREFIX]
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, c_string, call_args, c_string_vars, strip_cpp_comments, write_program  # noqa: E402


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    eng = sys.argv[3] if len(sys.argv) > 3 else "frameworks/cocos2d-x/"
    rend = eng + "cocos/renderer/"
    # Shader variables.
    shaders = {}
    for inc in re.findall(r'#include\s+"renderer/(ccShader_[^"]+)"', m.text(rend + "ccShaders.cpp")):
        src = strip_cpp_comments(m.text(rend + inc))
        if "STRINGIFY" in src:
            raise SystemExit(f"{inc}: STRINGIFY sources are not handled")
        for name, vals in c_string_vars(src).items():
            shaders[name] = vals[0]
    # compileShader's glShaderSource strings.
    glp = strip_cpp_comments(m.text(rend + "CCGLProgram.cpp"))
    uniforms = c_string_vars(glp)["COCOS2D_SHADER_UNIFORMS"][0]
    fn = glp[glp.index("bool GLProgram::compileShader(GLuint * shader, GLenum type, const GLchar* source, const std::string& compileTimeHeaders"):]
    if not re.search(r"sources\[\]\s*=\s*\{\s*headersDef\.c_str\(\),\s*COCOS2D_SHADER_UNIFORMS,\s*convertedDefines\.c_str\(\),\s*source\s*\}", fn):
        raise SystemExit("GLProgram::compileShader's sources[] changed")
    if not re.search(r"#elif\s*\(CC_TARGET_PLATFORM != CC_PLATFORM_WIN32 && CC_TARGET_PLATFORM != CC_PLATFORM_LINUX", fn):
        raise SystemExit("GLProgram::compileShader's desktop header branch changed")
    header = "" + uniforms + ""
    # Light macros.
    conf = m.text(eng + "cocos/base/CCConfiguration.cpp")
    lights = {k: int(v) for k, v in re.findall(r"_max(Dir|Point|Spot)LightInShader\((\d+)\)", conf)}
    cache = strip_cpp_comments(m.text(rend + "CCGLProgramCache.cpp"))
    mac = cache[cache.index("std::string GLProgramCache::getShaderMacrosForLight"):]
    fmt = c_string(mac[mac.index("snprintf("):mac.index("conf->")])
    light_def = fmt % (lights["Dir"], lights["Point"], lights["Spot"])
    body = cache[cache.index("void GLProgramCache::loadDefaultGLProgram(GLProgram *p, int type)"):]
    body = body[:body.index("p->link();")]
    n = 0
    for case in re.finditer(r"case\s+kShaderType_(\w+)\s*:(.*?)break;", body, re.S):
        name, code = case.group(1), case.group(2)
        local = {"def": light_def} if "getShaderMacrosForLight()" in code else {}
        for v, lit in re.findall(r'std::string\s+(\w+)\s*=\s*("(?:\\.|[^"\\])*")\s*;', code):
            local[v] = c_string(lit)
        call = re.search(r"initWithByteArrays\(", code)
        args = call_args(code, call.end() - 1)
        texts = []
        for a in args:
            a = re.sub(r"\.c_str\(\)$", "", a).strip()
            a = a[1:-1] if a.startswith("(") and a.endswith(")") else a
            t = ""
            for part in a.split("+"):
                part = part.strip()
                sm = re.fullmatch(r"std::string\((\w+)\)", part)
                t += shaders[sm.group(1)] if sm else (local[part] if part in local else shaders[part])
            texts.append(header + t)
        vname, fname = [re.search(r"(?:std::string\()?(\w+)\)?\s*\)?$", re.sub(r"\.c_str\(\)$", "", x)).group(1) for x in args]
        write_program(out, "cocos2dx", name, [("vertex", vname, texts[0]), ("fragment", fname, texts[1])])
        n += 1
    print(n, "programs")


main()
