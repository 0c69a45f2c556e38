//! Stages WebGPU has no counterpart of (ray tracing, mesh shading) checked by the reference
//! compiler alone; Vulkan GLSL compiled for the Vulkan version its constructs need without
//! `--target-env`, and what `auto` reads as Vulkan's; NV passthrough geometry stages.

use crate::common::{code, effectc, scratch, stdout};

/// Writes `files` (name, text) into a fresh scratch directory; their paths.
fn write(name: &str, files: &[(&str, &str)]) -> Vec<String> {
    let dir = scratch("vulkan-stages", name);
    files
        .iter()
        .map(|(file, text)| {
            let path = dir.join(file);
            std::fs::write(&path, text).unwrap();
            path.to_str().unwrap().to_string()
        })
        .collect()
}

fn run(args: &[&str], files: &[String]) -> std::process::Output {
    let mut all: Vec<&str> = args.to_vec();
    all.extend(files.iter().map(String::as_str));
    effectc(&all)
}

const RAYGEN: &str = "#version 460\n#extension GL_EXT_ray_tracing : require\n\
    layout(set = 0, binding = 0) uniform accelerationStructureEXT tlas;\n\
    layout(set = 0, binding = 1, rgba8) uniform image2D image;\n\
    layout(location = 0) rayPayloadEXT vec3 payload;\n\
    void main() {\n\
    \x20   traceRayEXT(tlas, gl_RayFlagsOpaqueEXT, 0xff, 0, 0, 0, vec3(0.0), 0.001, vec3(0.0, 0.0, 1.0), 100.0, 0);\n\
    \x20   imageStore(image, ivec2(gl_LaunchIDEXT.xy), vec4(payload, 1.0));\n}\n";

#[test]
fn a_ray_tracing_stage_is_judged_by_the_reference_compiler_for_the_vulkan_it_needs() {
    // GL_EXT_ray_tracing needs SPIR-V 1.4: glslang refuses it for Vulkan 1.0, and `auto`
    // compiles it for Vulkan 1.2 as the project's `--target-env vulkan1.2` would.
    let files = write("raygen", &[("trace.rgen", RAYGEN)]);
    let out = run(&["check", "--color", "never"], &files);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let text = stdout(&out);
    assert!(text.contains("N0106") && text.contains("WebGPU has no ray generation stage"), "{text}");
    assert!(!text.contains("N0002"), "a ray-tracing stage has no stage interface to pair: {text}");
    // Under Vulkan 1.0 as asked, glslang's refusal with the option that fixes it.
    let out = run(&["check", "--color", "never", "--target-env", "vulkan"], &files);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0105") && stdout(&out).contains("--target-env vulkan1.1"), "{}", stdout(&out));
    // An error in such a stage is glslang's, at its line.
    let broken = write("raygen-broken", &[("trace.rgen", &RAYGEN.replace("vec4(payload, 1.0)", "vec4(payload)"))]);
    let out = run(&["check", "--color", "never"], &broken);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0105") && stdout(&out).contains("trace.rgen:8:"), "{}", stdout(&out));
    // translate names why it stops.
    let dir = scratch("vulkan-stages", "raygen-out");
    let out = run(&["translate", "--color", "never", "--to", "wgsl", "--out", dir.to_str().unwrap()], &files);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0306") && stdout(&out).contains("WebGPU has no ray generation stage"), "{}", stdout(&out));
}

#[test]
fn a_mesh_stage_forms_a_program_with_its_fragment_stage() {
    let mesh = "#version 450\n#extension GL_EXT_mesh_shader : require\nlayout(local_size_x = 1) in;\n\
        layout(triangles, max_vertices = 3, max_primitives = 1) out;\nlayout(location = 0) out vec3 color[];\n\
        void main() {\n    SetMeshOutputsEXT(3, 1);\n    gl_MeshVerticesEXT[0].gl_Position = vec4(-1.0, -1.0, 0.0, 1.0);\n\
        \x20   gl_MeshVerticesEXT[1].gl_Position = vec4(1.0, -1.0, 0.0, 1.0);\n    gl_MeshVerticesEXT[2].gl_Position = vec4(0.0, 1.0, 0.0, 1.0);\n\
        \x20   color[0] = vec3(1.0, 0.0, 0.0); color[1] = vec3(0.0, 1.0, 0.0); color[2] = vec3(0.0, 0.0, 1.0);\n\
        \x20   gl_PrimitiveTriangleIndicesEXT[0] = uvec3(0, 1, 2);\n}\n";
    let frag =
        "#version 450\nlayout(location = 0) in vec3 color;\nlayout(location = 0) out vec4 o;\nvoid main() { o = vec4(color, 1.0); }\n";
    let files = write("mesh", &[("tri.mesh", mesh), ("tri.frag", frag)]);
    let dir = files[0].rsplit_once('/').unwrap().0.to_string();
    let out = effectc(&["check", "--color", "never", "--format", "json", &dir]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let json: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    let stages: Vec<&str> = json["formed"][0]["stages"].as_array().unwrap().iter().map(|s| s["stage"].as_str().unwrap()).collect();
    assert_eq!(stages, ["mesh", "fragment"], "{json}");
    let codes: Vec<&str> = json["diagnostics"].as_array().unwrap().iter().map(|d| d["code"].as_str().unwrap()).collect();
    assert_eq!(codes, ["N0106"], "{json}");
}

#[test]
fn vulkan_glsl_found_by_auto_is_compiled_for_the_oldest_vulkan_that_has_its_constructs() {
    // Subgroup arithmetic needs SPIR-V 1.3 (Vulkan 1.1): without `--target-env` the program
    // is checked and translated for Vulkan 1.1 (its subgroups computed as subgroups of one).
    let comp = "#version 450\n#extension GL_KHR_shader_subgroup_arithmetic : require\nlayout(local_size_x = 64) in;\n\
        layout(set = 0, binding = 0) buffer Values { float v[]; };\n\
        void main() { v[gl_GlobalInvocationID.x] = subgroupAdd(v[gl_GlobalInvocationID.x]); }\n";
    let files = write("subgroups", &[("sum.comp", comp)]);
    let out = run(&["check", "--color", "never"], &files);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains("N0115") && !stdout(&out).contains("E0105"), "{}", stdout(&out));
    let dir = scratch("vulkan-stages", "subgroups-out");
    let out = run(&["translate", "--color", "never", "--to", "wgsl", "--out", dir.to_str().unwrap()], &files);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let wgsl = std::fs::read_to_string(dir.join("sum.wgsl")).unwrap();
    assert!(wgsl.contains("@compute @workgroup_size(64"), "{wgsl}");
    // A genuine error in the same program is still glslang's, not hidden by the retries.
    let broken = write("subgroups-broken", &[("sum.comp", &comp.replace("subgroupAdd(", "subgroupAdd(1, "))]);
    let out = run(&["check", "--color", "never"], &broken);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("E0105") && stdout(&out).contains("subgroupAdd"), "{}", stdout(&out));
}

#[test]
fn atomic_counter_bindings_are_the_drivers_not_the_minimum() {
    // glslang's default limits allow one atomic counter buffer binding (GL's minimum); Mesa
    // offers 16, and a program using binding 1 links there.
    let frag = "#version 450\nlayout(binding = 1) uniform atomic_uint hits;\nout vec4 color;\n\
        void main() { color = vec4(float(atomicCounterIncrement(hits))); }\n";
    let files = write("atomic-binding", &[("count.frag", frag)]);
    let out = run(&["check", "--color", "never"], &files);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    let over = write("atomic-binding-over", &[("count.frag", &frag.replace("binding = 1", "binding = 16"))]);
    let out = run(&["check", "--color", "never"], &over);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(stdout(&out).contains("gl_MaxAtomicCounterBindings"), "{}", stdout(&out));
}

#[test]
fn a_stage_is_named_by_option_or_by_shadercs_pragma() {
    let hit = "#version 460\n#extension GL_EXT_ray_tracing : require\n\
        layout(location = 0) rayPayloadInEXT vec3 payload;\nhitAttributeEXT vec2 barycentrics;\n\
        void main() { payload = vec3(1.0 - barycentrics.x - barycentrics.y, barycentrics); }\n";
    let files = write("named-by-option", &[("hit.glsl", hit)]);
    let out = run(&["check", "--color", "never", "--stage", "closest-hit"], &files);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains("WebGPU has no closest-hit stage"), "{}", stdout(&out));
    // Every stage has its `--stage` name.
    for name in ["vertex", "tess-control", "tess-eval", "task", "mesh", "ray-generation", "any-hit", "miss", "callable"] {
        let out = run(&["check", "--color", "never", "--stage", name], &files);
        assert_ne!(code(&out), 2, "--stage {name}: {}", stdout(&out));
    }
    let pragma = hit.replacen("\n", "\n#pragma shader_stage(closesthit)\n", 1);
    let files = write("named-by-pragma", &[("hit.glsl", &pragma)]);
    let dir = files[0].rsplit_once('/').unwrap().0.to_string();
    let out = effectc(&["check", "--color", "never", &dir]);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(stdout(&out).contains("WebGPU has no closest-hit stage"), "{}", stdout(&out));
}

#[test]
fn auto_reads_what_only_vulkan_allows_and_names_the_option_where_only_vulkan_accepts() {
    // `layout(scalar)` is Vulkan GLSL's only: the stage is read as Vulkan GLSL.
    let scalar = "#version 450\n#extension GL_EXT_scalar_block_layout : require\nlayout(local_size_x = 1) in;\n\
        layout(binding = 0, scalar) buffer Data { vec3 a; float b; } data;\nvoid main() { data.b = data.a.x; }\n";
    let files = write("scalar", &[("pack.comp", scalar)]);
    let out = run(&["check", "--color", "never"], &files);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    // Offsets out of order: OpenGL GLSL refuses them, Vulkan GLSL takes them. Read as GL
    // (nothing Vulkan-only shows), the error stands with the option that says otherwise.
    let offsets = "#version 450\nlayout(location = 0) out vec4 color;\nlayout(std140, binding = 0) uniform UBO {\n\
        \x20   layout(offset = 16) mat4 m;\n    layout(offset = 0) vec4 v;\n};\nlayout(location = 0) in vec4 tint;\n\
        void main() { color = m * tint + v; }\n";
    let files = write("offsets", &[("ubo.frag", offsets)]);
    let out = run(&["check", "--color", "never"], &files);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(
        stdout(&out).contains("cannot lie in previous members") && stdout(&out).contains("pass `--target-env vulkan`"),
        "{}",
        stdout(&out)
    );
    let out = run(&["check", "--color", "never", "--target-env", "vulkan"], &files);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    // A GL error Vulkan GLSL has too gets no such help.
    let files = write("offsets-wrong", &[("ubo.frag", &offsets.replace("m * tint + v", "m * tint + v.xyz"))]);
    let out = run(&["check", "--color", "never"], &files);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
    assert!(!stdout(&out).contains("--target-env vulkan"), "{}", stdout(&out));
}

#[test]
fn a_passthrough_geometry_stage_declares_no_output_primitive() {
    // GL_NV_geometry_shader_passthrough: the input primitive is emitted as it is.
    let geom = "#version 450\n#extension GL_NV_geometry_shader_passthrough : require\nlayout(triangles) in;\n\
        layout(passthrough) in gl_PerVertex { vec4 gl_Position; } gl_in[];\n\
        layout(passthrough, location = 0) in vec4 color[];\nvoid main() { gl_Layer = 1; }\n";
    let files = write("passthrough", &[("pass.geom", geom)]);
    let out = run(&["check", "--color", "never"], &files);
    assert_eq!(code(&out), 0, "{}", stdout(&out));
    assert!(!stdout(&out).contains("E0214"), "{}", stdout(&out));
    let files = write("no-output", &[("pass.geom", &geom.replace("layout(passthrough)", "").replace("passthrough, ", ""))]);
    let out = run(&["check", "--color", "never"], &files);
    assert_eq!(code(&out), 1, "{}", stdout(&out));
}
