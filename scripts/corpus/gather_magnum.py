#!/usr/bin/env python3
"""mosra/magnum builtin shaders (src/Magnum/Shaders/*GL.cpp), as their compile() builds them
on desktop GL: GL::Shader{GL320} puts "#version 150\\n" first, then every non-empty
addSource() is preceded by "#line 0 N\\n" (GL::Shader::addSourceInternal, GLSL < 330).
The addSource() sequences below mirror FlatGL, VertexColorGL, VectorGL,
DistanceFieldVectorGL, PhongGL and MeshVisualizerGL2D (`"X"` = `flags & X ? "#define X\\n" : ""`,
`"@f"` = rs.getString(f)); a handful of flag configurations per shader.
Usage: gather_magnum.py MIRROR_GIT_DIR OUT_DIR
"""
import os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program

m, out = Mirror(sys.argv[1]), sys.argv[2]
D = "src/Magnum/Shaders/"


def dims(c):
    return "#define TWO_DIMENSIONS\n" if c.get("dims", 3) == 2 else "#define THREE_DIMENSIONS\n"


def ubo(*extra):
    def f(c):
        if "UNIFORM_BUFFERS" not in c["flags"]:
            return ""
        return "#define UNIFORM_BUFFERS\n#define DRAW_COUNT 1\n" + "".join(f"#define {e} 1\n" for e in extra)
    return f


def multidraw(c):
    return "#define MULTI_DRAW\n" if "UNIFORM_BUFFERS" in c["flags"] and "MULTI_DRAW" in c["flags"] else ""


def phong_lights(c):
    if "UNIFORM_BUFFERS" in c["flags"]:
        n = c["lights"]
        return (f"#define UNIFORM_BUFFERS\n#define DRAW_COUNT 1\n#define MATERIAL_COUNT 1\n"
                f"#define LIGHT_COUNT {n}\n#define PER_DRAW_LIGHT_COUNT {n}\n")
    n = c["lights"]
    s = (f"#define LIGHT_COUNT {n}\n#define PER_DRAW_LIGHT_COUNT {n}\n#define LIGHT_COLORS_LOCATION {12 + n}\n"
         f"#define LIGHT_SPECULAR_COLORS_LOCATION {12 + 2 * n}\n#define LIGHT_RANGES_LOCATION {12 + 3 * n}\n")
    return s


def phong_light_init(c):
    n = c["lights"]
    if "UNIFORM_BUFFERS" in c["flags"] or not n:
        return ""
    return ("#define LIGHT_POSITION_INITIALIZER " + ", ".join(["vec4(0.0, 0.0, 1.0, 0.0)"] * n) + "\n"
            "#define LIGHT_COLOR_INITIALIZER " + ", ".join(["vec3(1.0)"] * n) + "\n"
            "#define LIGHT_RANGE_INITIALIZER " + ", ".join(["1.0/0.000000000000000000000001"] * n) + "\n")


def no_geom(c):
    return "#define NO_GEOMETRY_SHADER\n" if "WIREFRAME_RENDERING" not in c["flags"] or "NO_GEOMETRY_SHADER" in c["flags"] else ""


SHADERS = {
    "Flat": {
        "vertex": ["@compatibility.glsl", "TEXTURED", "VERTEX_COLOR", "TEXTURE_TRANSFORMATION", "TEXTURE_ARRAYS", dims,
                   "INSTANCED_OBJECT_ID", "INSTANCED_TRANSFORMATION", "INSTANCED_TEXTURE_OFFSET", ubo(), multidraw,
                   "@generic.glsl", "@Flat.vert"],
        "fragment": ["@compatibility.glsl", "TEXTURED", "TEXTURE_ARRAYS", "ALPHA_MASK", "VERTEX_COLOR", "OBJECT_ID",
                     "INSTANCED_OBJECT_ID", "OBJECT_ID_TEXTURE", ubo("MATERIAL_COUNT"), multidraw,
                     "@generic.glsl", "@Flat.frag"],
        "configs": [set(), {"TEXTURED"}, {"TEXTURED", "ALPHA_MASK"}, {"VERTEX_COLOR"}, {"TEXTURED", "TEXTURE_TRANSFORMATION"},
                    {"TEXTURED", "TEXTURE_ARRAYS"}, {"INSTANCED_TRANSFORMATION"}, {"OBJECT_ID"},
                    {"OBJECT_ID", "INSTANCED_OBJECT_ID"}, {"UNIFORM_BUFFERS"}, {"UNIFORM_BUFFERS", "MULTI_DRAW", "TEXTURED"}],
        "dims": (2, 3),
    },
    "VertexColor": {
        "vertex": ["@compatibility.glsl", dims, ubo(), multidraw, "@generic.glsl", "@VertexColor.vert"],
        "fragment": ["@compatibility.glsl", "@generic.glsl", "@VertexColor.frag"],
        "configs": [set(), {"UNIFORM_BUFFERS"}], "dims": (2, 3),
    },
    "Vector": {
        "vertex": ["@compatibility.glsl", "TEXTURE_TRANSFORMATION", "TEXTURE_ARRAYS", dims, ubo(), multidraw,
                   "@generic.glsl", "@Vector.vert"],
        "fragment": ["@compatibility.glsl", "TEXTURE_ARRAYS", ubo("MATERIAL_COUNT"), multidraw, "@generic.glsl", "@Vector.frag"],
        "configs": [set(), {"TEXTURE_TRANSFORMATION"}, {"TEXTURE_ARRAYS"}, {"UNIFORM_BUFFERS"}], "dims": (2, 3),
    },
    "DistanceFieldVector": {
        "vertex": ["@compatibility.glsl", "TEXTURE_TRANSFORMATION", "TEXTURE_ARRAYS", dims, ubo(), multidraw,
                   "@generic.glsl", "@Vector.vert"],
        "fragment": ["@compatibility.glsl", "TEXTURE_ARRAYS", ubo("MATERIAL_COUNT"), multidraw, "@generic.glsl",
                     "@DistanceFieldVector.frag"],
        "configs": [set(), {"TEXTURE_TRANSFORMATION"}, {"TEXTURE_ARRAYS"}, {"UNIFORM_BUFFERS"}], "dims": (2, 3),
    },
    "Phong": {
        "vertex": ["@compatibility.glsl", "TEXTURED", "NORMAL_TEXTURE", "BITANGENT", "VERTEX_COLOR", "TEXTURE_TRANSFORMATION",
                   "TEXTURE_ARRAYS", lambda c: "#define HAS_LIGHTS\n" if c["lights"] else "", "INSTANCED_OBJECT_ID",
                   "INSTANCED_TRANSFORMATION", "INSTANCED_TEXTURE_OFFSET", ubo(), multidraw, "@generic.glsl", "@Phong.vert"],
        "fragment": ["@compatibility.glsl", "AMBIENT_TEXTURE", "DIFFUSE_TEXTURE", "SPECULAR_TEXTURE", "NORMAL_TEXTURE",
                     "TEXTURE_ARRAYS", "BITANGENT", "VERTEX_COLOR", "DOUBLE_SIDED", "ALPHA_MASK", "OBJECT_ID",
                     "INSTANCED_OBJECT_ID", "OBJECT_ID_TEXTURE", "NO_SPECULAR", phong_lights, multidraw,
                     phong_light_init, "@generic.glsl", "@Phong.frag"],
        "configs": [set(), {"TEXTURED", "DIFFUSE_TEXTURE"}, {"TEXTURED", "AMBIENT_TEXTURE", "DIFFUSE_TEXTURE", "SPECULAR_TEXTURE"},
                    {"TEXTURED", "NORMAL_TEXTURE"}, {"TEXTURED", "NORMAL_TEXTURE", "BITANGENT"}, {"VERTEX_COLOR"},
                    {"TEXTURED", "DIFFUSE_TEXTURE", "ALPHA_MASK"}, {"DOUBLE_SIDED"}, {"NO_SPECULAR"}, {"OBJECT_ID"},
                    {"INSTANCED_TRANSFORMATION"}, {"TEXTURED", "DIFFUSE_TEXTURE", "TEXTURE_ARRAYS", "TEXTURE_TRANSFORMATION"},
                    {"UNIFORM_BUFFERS"}, {"UNIFORM_BUFFERS", "MULTI_DRAW", "TEXTURED", "DIFFUSE_TEXTURE"}],
        "lights": (0, 1, 3),
    },
    "MeshVisualizer2D": {
        "vertex": ["@compatibility.glsl", "WIREFRAME_RENDERING", "TEXTURED", "TEXTURE_TRANSFORMATION", "TEXTURE_ARRAYS",
                   "INSTANCED_OBJECT_ID", "INSTANCED_TRANSFORMATION", "INSTANCED_TEXTURE_OFFSET", "VERTEX_ID",
                   "PRIMITIVE_ID_FROM_VERTEX_ID", ubo("MATERIAL_COUNT"), multidraw, "#define TWO_DIMENSIONS\n", no_geom,
                   "@generic.glsl", "@MeshVisualizer.vert"],
        "fragment": ["@compatibility.glsl", "WIREFRAME_RENDERING", "OBJECT_ID", "OBJECT_ID_TEXTURE", "TEXTURE_ARRAYS",
                     "INSTANCED_OBJECT_ID", "VERTEX_ID", "PRIMITIVE_ID", "PRIMITIVE_ID_FROM_VERTEX_ID",
                     ubo("MATERIAL_COUNT"), multidraw, no_geom,
                     lambda c: "#define TWO_DIMENSIONS\n" if "UNIFORM_BUFFERS" in c["flags"] else "",
                     "@generic.glsl", "@MeshVisualizer.frag"],
        "geometry": ["@compatibility.glsl", "#define WIREFRAME_RENDERING\n#define MAX_VERTICES 3\n", "TEXTURED",
                     "TEXTURE_ARRAYS", "OBJECT_ID", "INSTANCED_OBJECT_ID", "VERTEX_ID", "PRIMITIVE_ID",
                     lambda c: ("#define TWO_DIMENSIONS\n#define UNIFORM_BUFFERS\n#define DRAW_COUNT 1\n#define MATERIAL_COUNT 1\n"
                                if "UNIFORM_BUFFERS" in c["flags"] else ""), multidraw, "@MeshVisualizer.geom"],
        "configs": [{"WIREFRAME_RENDERING"}, {"WIREFRAME_RENDERING", "NO_GEOMETRY_SHADER"}, {"VERTEX_ID"},
                    {"OBJECT_ID", "INSTANCED_OBJECT_ID"}, {"WIREFRAME_RENDERING", "PRIMITIVE_ID"},
                    {"WIREFRAME_RENDERING", "UNIFORM_BUFFERS"}],
    },
}


def build(recipe, cfg):
    sources = ["#version 150\n"]
    for item in recipe:
        if callable(item):
            s = item(cfg)
        elif item.startswith("@"):
            s = m.text(D + item[1:])
        elif item.startswith("#"):
            s = item
        else:
            s = f"#define {item}\n" if item in cfg["flags"] else ""
        if s:  # addSource() ignores empty strings
            sources += [f"#line 0 {(len(sources) + 1) // 2}\n", s]
    return "".join(sources)


n = 0
for shader, spec in SHADERS.items():
    for flags in spec["configs"]:
        for d in spec.get("dims", (3,)):
            for lights in spec.get("lights", (0,)):
                cfg = {"flags": flags, "dims": d, "lights": lights}
                stages = [("vertex", shader, build(spec["vertex"], cfg))]
                if "geometry" in spec and "WIREFRAME_RENDERING" in flags and "NO_GEOMETRY_SHADER" not in flags:
                    stages.append(("geometry", shader, build(spec["geometry"], cfg)))
                stages.append(("fragment", shader, build(spec["fragment"], cfg)))
                name = shader + ("%dD" % d if "dims" in spec else "") + ("_L%d" % lights if "lights" in spec else "")
                name += "_" + ("_".join(sorted(flags)) or "default")
                write_program(out, "magnum", name, stages)
                n += 1
print(n, "programs")
