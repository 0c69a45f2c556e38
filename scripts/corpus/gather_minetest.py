#!/usr/bin/env python3
"""minetest/minetest (Luanti): client/shaders/<name>/opengl_vertex.glsl + opengl_fragment.glsl as
ShaderSource::generateShader (src/client/shader.cpp) builds them: common header (`#version 150`
for the OpenGL3 driver, `#version 120` + empty precision macros for the legacy OpenGL driver;
node/object constants NDT_*, TILE_MATERIAL_*, MATERIAL_TYPE, DRAW_TYPE, waving and reflection
flags; USE_DISCARD / USE_DISCARD_REF from the material's base material on the OpenGL3 driver;
the settings constants), the driver's vertex header (OpenGL3: precision, mWorldView /
mWorldViewProj / mTexture uniforms, inVertex* attributes and the `.bgra` swizzle; legacy:
gl_ModelViewMatrix / gl_Vertex ... macros), the fragment header (baseTexture / normalTexture /
textureFlags macros), `#line 0`, then the file.

Programs: the getShaderRaw names the client requests (clouds, selection, minimap, stars,
3d_interlaced_merge, the second-stage chain), nodes_shader for every tile material type (with
the drawtype nodedef gives it; DRAW_TYPE is not read by the shaders), object_shader for the
material types entities use; each for both drivers and two settings sets: the defaults of
src/defaultsettings.cpp and a "fancy" set (dynamic shadows, waving, reflections, translucent
foliage, specular, bloom, auto exposure, tone mapping, volumetric light, SSAA).
Usage: gather_minetest.py MIRROR_GIT_DIR OUT_DIR
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program  # noqa: E402

RAW = [("cloud_shader", True), ("selection_shader", True), ("minimap_shader", True), ("stars_shader", True),
       ("3d_interlaced_merge", False), ("extract_bloom", False), ("volumetric_light", False),
       ("bloom_downsample", False), ("bloom_upsample", False), ("update_exposure", False), ("fxaa", False),
       ("second_stage", False)]

DEFAULTS = dict(enable_waving_water=False, water_wave_height="1.0", water_wave_length="20.0",
                water_wave_speed="5.0", enable_waving_leaves=False, enable_waving_plants=False, tone_mapping=False,
                enable_dynamic_shadows=False, shadow_map_color=False, shadow_poisson_filter=True,
                enable_water_reflections=False, enable_translucent_foliage=False, enable_node_specular=False,
                shadow_filters=1, shadow_soft_radius="5.00000", enable_bloom=False, enable_bloom_debug=False,
                enable_auto_exposure=False, antialiasing="none", fsaa=0, debanding=False,
                enable_volumetric_lighting=False)
FANCY = dict(DEFAULTS, enable_waving_water=True, enable_waving_leaves=True, enable_waving_plants=True,
             tone_mapping=True, enable_dynamic_shadows=True, shadow_map_color=True, enable_water_reflections=True,
             enable_translucent_foliage=True, enable_node_specular=True, shadow_filters=2, enable_bloom=True,
             enable_auto_exposure=True, antialiasing="ssaa", fsaa=2, debanding=True, enable_volumetric_lighting=True)


def enum_values(src, name):
    body = re.search(r"enum\s+" + name + r"\b[^{]*\{(.*?)\}", src, re.S).group(1)
    body = re.sub(r"//[^\n]*|/\*.*?\*/", "", body, flags=re.S)
    vals, nxt = {}, 0
    for item in body.split(","):
        m = re.match(r"\s*(\w+)\s*(?:=\s*(\w+))?\s*$", item)
        if not m:
            continue
        if m.group(2):
            nxt = int(m.group(2), 0)
        vals[m.group(1)] = nxt
        nxt += 1
    return vals


def main():
    m, out = Mirror(sys.argv[1]), sys.argv[2]
    NDT = enum_values(m.text("src/nodedef.h"), "NodeDrawType")
    MAT = enum_values(m.text("src/client/tile.h"), "MaterialType")
    provided = re.findall(r"^\s*PROVIDE\((\w+)\);", m.text("src/client/shader.cpp"), re.M)
    base = {}
    for k in ("TILE_MATERIAL_OPAQUE", "TILE_MATERIAL_LIQUID_OPAQUE", "TILE_MATERIAL_WAVING_LIQUID_OPAQUE"):
        base[MAT[k]] = "solid"
    for k in ("TILE_MATERIAL_ALPHA", "TILE_MATERIAL_PLAIN_ALPHA", "TILE_MATERIAL_LIQUID_TRANSPARENT",
              "TILE_MATERIAL_WAVING_LIQUID_TRANSPARENT"):
        base[MAT[k]] = "alpha"
    for k in ("TILE_MATERIAL_BASIC", "TILE_MATERIAL_PLAIN", "TILE_MATERIAL_WAVING_LEAVES", "TILE_MATERIAL_WAVING_PLANTS",
              "TILE_MATERIAL_WAVING_LIQUID_BASIC"):
        base[MAT[k]] = "ref"
    b = lambda v: "1" if v else "0"

    def texts(name, material, drawtype, gl3, s):
        h = "#version 150\n" if gl3 else "\n\t\t\t#version 120\n\t\t\t#define lowp\n\t\t\t#define mediump\n\t\t\t#define highp\n\t\t"
        if gl3:
            vh = ("\n\t\t\tprecision mediump float;\n\n\t\t\tuniform highp mat4 mWorldView;\n\t\t\tuniform highp mat4 mWorldViewProj;\n"
                  "\t\t\tuniform mediump mat4 mTexture;\n\n\t\t\tattribute highp vec4 inVertexPosition;\n"
                  "\t\t\tattribute lowp vec4 inVertexColor;\n\t\t\tattribute mediump vec2 inTexCoord0;\n"
                  "\t\t\tattribute mediump vec3 inVertexNormal;\n\t\t\tattribute mediump vec4 inVertexTangent;\n"
                  "\t\t\tattribute mediump vec4 inVertexBinormal;\n\t\t")
            vh += "#define inVertexColor (inVertexColor.bgra)\n"
            fh = "\n\t\t\tprecision mediump float;\n\t\t"
        else:
            vh = ("\n\t\t\t#define mWorldView gl_ModelViewMatrix\n\t\t\t#define mWorldViewProj gl_ModelViewProjectionMatrix\n"
                  "\t\t\t#define mTexture (gl_TextureMatrix[0])\n\n\t\t\t#define inVertexPosition gl_Vertex\n"
                  "\t\t\t#define inVertexColor gl_Color\n\t\t\t#define inTexCoord0 gl_MultiTexCoord0\n"
                  "\t\t\t#define inVertexNormal gl_Normal\n\t\t\t#define inVertexTangent gl_MultiTexCoord1\n"
                  "\t\t\t#define inVertexBinormal gl_MultiTexCoord2\n\t\t")
            fh = ""
        fh += "\n\t\t#define baseTexture texture0\n\t\t#define normalTexture texture1\n\t\t#define textureFlags texture2\n\t"
        if drawtype is not None:
            if gl3:
                if base[material] == "alpha":
                    h += "#define USE_DISCARD 1\n"
                elif base[material] == "ref":
                    h += "#define USE_DISCARD_REF 1\n"
            for k in provided:  # PROVIDE(constant) lines of generateShader
                h += f"#define {k} {NDT.get(k, MAT.get(k))}\n"
            h += f"#define MATERIAL_TYPE {material}\n#define DRAW_TYPE {drawtype}\n"
            h += f"#define ENABLE_WAVING_WATER {b(s['enable_waving_water'])}\n"
            if s["enable_waving_water"]:
                h += (f"#define WATER_WAVE_HEIGHT {s['water_wave_height']}\n#define WATER_WAVE_LENGTH {s['water_wave_length']}\n"
                      f"#define WATER_WAVE_SPEED {s['water_wave_speed']}\n")
            waving_liquid = material in (MAT["TILE_MATERIAL_WAVING_LIQUID_TRANSPARENT"], MAT["TILE_MATERIAL_WAVING_LIQUID_OPAQUE"],
                                         MAT["TILE_MATERIAL_WAVING_LIQUID_BASIC"])
            h += f"#define MATERIAL_WAVING_LIQUID {b(waving_liquid)}\n"
            h += f"#define MATERIAL_WATER_REFLECTIONS {b(waving_liquid or material == MAT['TILE_MATERIAL_LIQUID_TRANSPARENT'])}\n"
            h += f"#define ENABLE_WAVING_LEAVES {b(s['enable_waving_leaves'])}\n#define ENABLE_WAVING_PLANTS {b(s['enable_waving_plants'])}\n"
        h += f"#define ENABLE_TONE_MAPPING {b(s['tone_mapping'])}\n"
        if s["enable_dynamic_shadows"]:
            h += "#define ENABLE_DYNAMIC_SHADOWS 1\n"
            for k, d in (("shadow_map_color", "COLORED_SHADOWS"), ("shadow_poisson_filter", "POISSON_FILTER"),
                         ("enable_water_reflections", "ENABLE_WATER_REFLECTIONS"),
                         ("enable_translucent_foliage", "ENABLE_TRANSLUCENT_FOLIAGE"), ("enable_node_specular", "ENABLE_NODE_SPECULAR")):
                if s[k]:
                    h += f"#define {d} 1\n"
            h += f"#define SHADOW_FILTER {s['shadow_filters']}\n#define SOFTSHADOWRADIUS {s['shadow_soft_radius']}\n"
        if s["enable_bloom"]:
            h += "#define ENABLE_BLOOM 1\n" + ("#define ENABLE_BLOOM_DEBUG 1\n" if s["enable_bloom_debug"] else "")
        if s["enable_auto_exposure"]:
            h += "#define ENABLE_AUTO_EXPOSURE 1\n"
        if s["antialiasing"] == "ssaa":
            h += f"#define ENABLE_SSAA 1\n#define SSAA_SCALE {max(2, s['fsaa'])}.\n"
        if s["debanding"]:
            h += "#define ENABLE_DITHERING 1\n"
        if s["enable_volumetric_lighting"]:
            h += "#define VOLUMETRIC_LIGHT 1\n"
        vs = m.text(f"client/shaders/{name}/opengl_vertex.glsl")
        fs = m.text(f"client/shaders/{name}/opengl_fragment.glsl")
        gs = m.text(f"client/shaders/{name}/opengl_geometry.glsl")
        stages = [("vertex", "opengl_vertex", h + vh + "#line 0\n" + vs), ("fragment", "opengl_fragment", h + fh + "#line 0\n" + fs)]
        if gs:
            stages.insert(1, ("geometry", "opengl_geometry", h + "#line 0\n" + gs))
        return stages

    n, seen = 0, set()

    def emit(label, stages):
        nonlocal n
        key = tuple(t for _, _, t in stages)
        if key in seen:
            return
        seen.add(key)
        write_program(out, "minetest", label, stages)
        n += 1

    drawtype_for = {"TILE_MATERIAL_LIQUID_TRANSPARENT": "NDT_LIQUID", "TILE_MATERIAL_LIQUID_OPAQUE": "NDT_LIQUID",
                    "TILE_MATERIAL_WAVING_LIQUID_BASIC": "NDT_LIQUID", "TILE_MATERIAL_WAVING_LIQUID_TRANSPARENT": "NDT_LIQUID",
                    "TILE_MATERIAL_WAVING_LIQUID_OPAQUE": "NDT_LIQUID", "TILE_MATERIAL_WAVING_LEAVES": "NDT_ALLFACES",
                    "TILE_MATERIAL_WAVING_PLANTS": "NDT_PLANTLIKE", "TILE_MATERIAL_ALPHA": "NDT_GLASSLIKE"}
    for drv, gl3 in (("gl3", True), ("gl2", False)):
        for sname, s in (("default", DEFAULTS), ("fancy", FANCY)):
            for name, alpha in RAW:
                mat = MAT["TILE_MATERIAL_ALPHA" if alpha else "TILE_MATERIAL_BASIC"]
                emit(f"{name}.{drv}.{sname}", texts(name, mat, None, gl3, s))
            for k, v in MAT.items():
                if k.startswith("TILE_MATERIAL_PLAIN"):
                    continue
                emit(f"nodes_shader.{k[14:].lower()}.{drv}.{sname}", texts("nodes_shader", v, NDT[drawtype_for.get(k, "NDT_NORMAL")], gl3, s))
            for k in ("TILE_MATERIAL_BASIC", "TILE_MATERIAL_ALPHA", "TILE_MATERIAL_PLAIN", "TILE_MATERIAL_PLAIN_ALPHA"):
                emit(f"object_shader.{k[14:].lower()}.{drv}.{sname}", texts("object_shader", MAT[k], NDT["NDT_NORMAL"], gl3, s))
    print(n, "programs")


main()
