//! Translation: every effect under `effects/` and every program under `tests/rewrite/` and
//! `tests/through_spirv/`
//! translates to every target. The WGSL re-validates (inside effectc), every SPIR-V stage
//! passes `spirv-val`, and a wgpu render pipeline builds from the WGSL on the machine's
//! adapter (lavapipe in CI). The pruned IR, the WGSL and the SPIR-V disassembly are
//! snapshotted under `snapshots/translate/`, so a review shows what translation changed.
//!
//! In CI (`CI` set) a missing `spirv-val` or Vulkan adapter fails the test; elsewhere those
//! parts are skipped with a message.

use std::path::{Path, PathBuf};
use std::process::Command;

use effectc::back::{self, Target, TranslateOptions};
use effectc::diag::{self, Code};
use effectc::stage::StageKind;

use crate::common;

use crate::common::in_ci;

fn programs() -> Vec<PathBuf> {
    let mut dirs = common::fixtures("effects", 21);
    dirs.extend(common::fixtures("tests/rewrite", common::REWRITE_FIXTURES));
    dirs.extend(common::fixtures("tests/through_spirv", 11));
    dirs
}

fn spirv_val_available() -> bool {
    let ok = Command::new("spirv-val").arg("--version").output().is_ok_and(|o| o.status.success());
    assert!(ok || !in_ci(), "spirv-val is missing (Debian package spirv-tools; ./setup.sh installs it)");
    if !ok {
        eprintln!("spirv-val not found: SPIR-V validation skipped");
    }
    ok
}

fn spirv_val(words: &[u32], path: &Path) -> Result<(), String> {
    std::fs::write(path, words.iter().flat_map(|w| w.to_le_bytes()).collect::<Vec<u8>>()).unwrap();
    let out = Command::new("spirv-val").args(["--target-env", "vulkan1.0"]).arg(path).output().unwrap();
    if out.status.success() {
        Ok(())
    } else {
        Err(String::from_utf8_lossy(&out.stderr).into_owned() + &String::from_utf8_lossy(&out.stdout))
    }
}

#[test]
fn every_program_translates_validates_and_builds_a_pipeline() {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../snapshots/translate");
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    let validate_spirv = spirv_val_available();
    let gpu = match effectc::render::device::Gpu::new() {
        Ok(g) => Some(g),
        Err(e) => {
            assert!(!in_ci(), "no wgpu device in CI: {e}");
            eprintln!("no wgpu device ({e}): pipeline builds skipped");
            None
        }
    };
    let scratch = Path::new(env!("CARGO_TARGET_TMPDIR")).join("translate");
    std::fs::create_dir_all(&scratch).unwrap();
    let mut problems = Vec::new();
    let dirs = programs();
    for dir in &dirs {
        let name = common::name_of(dir);
        let (outcome, checked) = common::check(dir);
        assert!(!diag::has_errors(&outcome.diagnostics), "{name} does not check:\n{}", common::render(&outcome));
        let c = &checked[0];
        // A multi-pass effect translates pass by pass (`<effect>.<pass>`).
        for unit in &c.units {
            let (name, program, effect) = match c.multi_pass() {
                Some(_) => (unit.name.clone(), &unit.program, unit.effect.as_ref()),
                None => (name.clone(), &unit.program, unit.effect.as_ref()),
            };
            let t = match back::translate(&name, program, effect, TranslateOptions::default()) {
                Ok(t) => t,
                Err(d) => {
                    problems.push(format!("{name}: {}", diag::render_human(&d, &outcome.files, false)));
                    continue;
                }
            };
            for target in Target::ALL {
                match back::emit(&t, target) {
                    Ok(outputs) => assert!(!outputs.is_empty() && outputs.iter().all(|o| !o.bytes.is_empty())),
                    // GLSL ES 3.00 has no `noperspective`, no images and no storage buffers (which a
                    // folded geometry stage reads): the things a target may refuse here.
                    Err(e) if target == Target::Glsl && e.contains("NOPERSPECTIVE") => {}
                    // GLSL ES 3.00 has no image load/store (ES 3.10 does).
                    Err(e) if target == Target::Glsl && e.contains("IMAGE_LOAD_STORE") => {}
                    Err(e) if target == Target::Glsl && t.reflection.geometry.is_some() && e.contains("storage buffers") => {}
                    // A program's own storage buffers (`buffer` blocks) have no GLSL ES 3.00 form either.
                    Err(e) if target == Target::Glsl && e.contains("BUFFER_STORAGE") => {}
                    // Nor a texture's level count (`textureQueryLod`'s clamp), which GLSL 4.30 added.
                    Err(e) if target == Target::Glsl && e.contains("TEXTURE_LEVELS") => {}
                    // Nor arrays of arrays (an array of std140 two-row matrices, stored as
                    // `vec4` columns), which GLSL ES 3.10 added.
                    Err(e) if target == Target::Glsl && e.contains("ARRAY_OF_ARRAYS") => {}
                    // Nor cube map arrays, which GLSL ES 3.20 added.
                    Err(e) if target == Target::Glsl && e.contains("CUBE_TEXTURES_ARRAY") => {}
                    // Nor 16-bit floats (`f16vec3`), which WGSL, SPIR-V, MSL and HLSL keep.
                    Err(e) if target == Target::Glsl && e.contains("Scalar { kind: Float, width: 2 }") => {}
                    Err(e) => problems.push(format!("{name}: {}: {e}", target.name())),
                }
            }
            let text = |target| String::from_utf8(back::emit(&t, target).unwrap().remove(0).bytes).unwrap();
            let wgsl = text(Target::Wgsl);
            settings.bind(|| {
                insta::assert_snapshot!(format!("{name}-ir"), text(Target::Ir));
                insta::assert_snapshot!(format!("{name}-wgsl"), wgsl);
            });
            let asm_files = back::emit(&t, Target::Spvasm).unwrap();
            for stage in &t.stages {
                let words = back::spirv_words(&t, *stage).unwrap();
                let file = format!("{name}.{}.spvasm", stage.short_name());
                let asm = asm_files.iter().find(|o| o.file_name == file).expect("one disassembly per stage");
                settings
                    .bind(|| insta::assert_snapshot!(format!("{name}-{}-spvasm", stage.short_name()), String::from_utf8_lossy(&asm.bytes)));
                if validate_spirv {
                    if let Err(e) = spirv_val(&words, &scratch.join(format!("{name}.{}.spv", stage.short_name()))) {
                        problems.push(format!("{name}: spirv-val ({stage}): {e}"));
                    }
                }
            }
            if let Some(gpu) = &gpu {
                if t.stages.contains(&StageKind::Vertex) {
                    if let Err(e) = gpu.build_pipeline(&wgsl, &t.reflection) {
                        problems.push(format!("{name}: wgpu pipeline: {e}"));
                    }
                }
            }
        }
    }
    assert!(problems.is_empty(), "{} problem(s):\n{}", problems.len(), problems.join("\n"));
}

#[test]
fn manifest_defaults_pack_into_the_reflected_bytes() {
    let (outcome, checked) = common::check(Path::new("effects/sun"));
    assert!(!diag::has_errors(&outcome.diagnostics));
    let c = &checked[0];
    let effect = c.effect.as_ref().unwrap();
    let t = back::translate("sun", &c.units[0].program, Some(effect), TranslateOptions::default()).unwrap();
    let bytes = back::reflect::pack_defaults(&t.module, effect).unwrap().expect("sun has a uniform block");
    let block = t.reflection.uniform_block.as_ref().unwrap();
    assert_eq!(bytes.len() as u32, block.size);
    let mut checked_fills = 0;
    for fill in block.fills.iter().filter(|f| f.value.is_some()) {
        let value = fill.value.as_ref().unwrap().as_f64().expect("sun's defaults are numbers");
        let [start, end] = fill.bytes;
        assert_eq!(end - start, 4, "{}", fill.uniform);
        let member = block.members.iter().find(|m| m.name == fill.uniform).unwrap();
        let raw: [u8; 4] = bytes[start as usize..end as usize].try_into().unwrap();
        // `blurEffectRadius` is an int; the other defaults are floats.
        let stored = if member.glsl_type == "int" { f64::from(i32::from_le_bytes(raw)) } else { f64::from(f32::from_le_bytes(raw)) };
        assert_eq!(stored, f64::from(value as f32), "{} at {start}", fill.uniform);
        assert_eq!(member.offset, start, "the fill and the member agree on {}", fill.uniform);
        checked_fills += 1;
    }
    assert!(checked_fills >= 7, "sun sets minBI, maxBI, bFrequency, swirlIntensity, swirlSeed, randomConstant, blurEffectRadius");
    // Semantics are filled by the renderer: zero here, but their bytes are reflected.
    assert!(block.fills.iter().any(|f| f.semantic.as_deref() == Some("time")));
}

const VERT: &str = "#version 330 core\nlayout(location = 0) in vec3 aPos;\nlayout(location = 1) in vec3 aNormal;\n\
uniform mat4 mvp;\nuniform float unusedScale;\nout vec3 normal;\nout vec3 debugPos;\n\
float neverCalled(float x) { return x * unusedScale; }\n\
void main() { normal = aNormal; debugPos = aPos; gl_Position = mvp * vec4(aPos, 1.0); }\n";
const FRAG: &str = "#version 330 core\nin vec3 normal;\nin vec3 debugPos;\nuniform vec3 tint;\nout vec4 color;\n\
void main() { color = vec4(normalize(normal) * 0.5 + 0.5, 1.0) * vec4(tint, 1.0); }\n";

/// effectc with `args`, then `dir/out_name`, `dir/p.vert` and `dir/p.frag`.
/// A fresh directory `<target tmp>/<name>` holding the pair `p.vert`, `p.frag` for [`on_pair`].
fn pair_dir(name: &str, vert: &str, frag: &str) -> std::path::PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("p.vert"), vert).unwrap();
    std::fs::write(dir.join("p.frag"), frag).unwrap();
    dir
}

fn on_pair(dir: &Path, args: &[&str], out_name: &str) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_effectc"))
        .args(args)
        .arg(dir.join(out_name))
        .arg(dir.join("p.vert"))
        .arg(dir.join("p.frag"))
        .env("NO_COLOR", "1")
        .output()
        .unwrap()
}

#[test]
fn unused_varyings_uniforms_and_functions_are_left_out_and_explained() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("translate-prune");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("p.vert"), VERT).unwrap();
    std::fs::write(dir.join("p.frag"), FRAG).unwrap();
    let out = on_pair(&dir, &["translate", "--explain", "--to", "wgsl,reflect", "--out"], "out");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    for expected in ["varying `debugPos`", "uniform `unusedScale`", "function `neverCalled`"] {
        assert!(stdout.contains(expected), "`{expected}` not explained:\n{stdout}");
    }
    assert!(!stdout.contains("`normal`") && !stdout.contains("`tint`"), "used items were left out:\n{stdout}");
    let wgsl = std::fs::read_to_string(dir.join("out/p.wgsl")).unwrap();
    assert!(wgsl.contains("fn vs_main(") && wgsl.contains("fn fs_main("));
    assert!(!wgsl.contains("debugPos") && !wgsl.contains("unusedScale") && !wgsl.contains("neverCalled"), "{wgsl}");
    let reflect: serde_json::Value = serde_json::from_str(&std::fs::read_to_string(dir.join("out/p.reflect.json")).unwrap()).unwrap();
    let members: Vec<&str> = reflect["uniform_block"]["members"].as_array().unwrap().iter().map(|m| m["name"].as_str().unwrap()).collect();
    assert_eq!(members, ["mvp", "tint"]);
    let inputs: Vec<u64> = reflect["vertex_inputs"].as_array().unwrap().iter().map(|v| v["location"].as_u64().unwrap()).collect();
    assert_eq!(inputs, [0, 1]);
}

#[test]
fn translate_refuses_a_program_with_check_errors() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("translate-refuse");
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(env!("CARGO_BIN_EXE_effectc"))
        .args(["translate", "tests/fail/01-vert-out-vs-vert-vars", "--out"])
        .arg(&dir)
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{stdout}");
    assert!(stdout.contains(Code::InputBlockUnmatched.as_str()), "check's diagnostic is the output:\n{stdout}");
    assert!(!dir.exists(), "nothing is written for a refused program");
}

/// 16-bit floats (GL_EXT_shader_explicit_arithmetic_types_float16) translate with WebGPU's
/// optional `shader-f16` feature: the WGSL enables it, N0109 points at the first 16-bit type,
/// and render asks the device for it. They were E0306 "which WebGPU does not have".
#[test]
fn sixteen_bit_floats_translate_with_the_optional_feature() {
    let dir = pair_dir(
        "translate-f16",
        "#version 450\nlayout(location = 0) in vec3 pos;\nlayout(location = 0) out vec4 c;\n\
         void main() { c = vec4(pos * 0.5 + 0.5, 1.0); gl_Position = vec4(pos, 1.0); }\n",
        "#version 450\n#extension GL_EXT_shader_explicit_arithmetic_types_float16 : require\n\
         layout(location = 0) in vec4 c;\nlayout(location = 0) out vec4 o;\n\
         void main() {\n    f16vec4 h = f16vec4(c);\n    o = vec4(h * float16_t(0.5));\n}\n",
    );
    let out = on_pair(&dir, &["translate", "--target-env", "vulkan", "--to", "wgsl,spv", "--out"], "out");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains(Code::OptionalWebGpuFeature.as_str()) && stdout.contains("p.frag:6:5"), "{stdout}");
    let wgsl = std::fs::read_to_string(dir.join("out/p.wgsl")).unwrap();
    assert!(wgsl.starts_with("enable f16;") && wgsl.contains("vec4<f16>"), "{wgsl}");
    if crate::render::have_gpu() {
        let out = on_pair(&dir, &["render", "--target-env", "vulkan", "--frames", "1", "--size", "16x16", "--out"], "frames");
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
    }
}

/// `gl_PrimitiveID` in a fragment stage: WebGPU has it as the optional `primitive-index`
/// feature, so the WGSL enables it and N0109 says so (E0306 before: "which WebGPU does not
/// have"), and a device with the feature draws it (lavapipe has it).
#[test]
fn a_fragment_primitive_id_translates_with_the_optional_feature() {
    let dir = pair_dir(
        "translate-primitive-id",
        "#version 330 core\nlayout(location = 0) in vec3 aPos;\nvoid main() { gl_Position = vec4(aPos, 1.0); }\n",
        "#version 330 core\nout vec4 color;\nvoid main() { color = vec4(float(gl_PrimitiveID % 4) / 3.0, 0.0, 0.0, 1.0); }\n",
    );
    let out = on_pair(&dir, &["translate", "--to", "wgsl,spv", "--out"], "out");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}");
    assert!(stdout.contains(Code::OptionalWebGpuFeature.as_str()) && stdout.contains("p.frag:3:"), "{stdout}");
    let wgsl = std::fs::read_to_string(dir.join("out/p.wgsl")).unwrap();
    assert!(wgsl.starts_with("enable primitive_index;") && wgsl.contains("@builtin(primitive_index)"), "{wgsl}");
    if crate::render::have_gpu() {
        let out = on_pair(&dir, &["render", "--frames", "1", "--size", "16x16", "--out"], "frames");
        assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
    }
}

/// A sampler array indexed at run time is legal below GLSL 4.00 with `GL_ARB_gpu_shader5`
/// (effectc reads the extension from the file, whose `#extension` lines its own parse does
/// not keep): the call on the chosen element translates; without the extension it is E0110.
#[test]
fn a_sampler_array_indexed_at_run_time_translates_with_gpu_shader5() {
    let vert = "#version 150\nin vec2 pos;\nout vec2 uv;\nvoid main() { uv = pos; gl_Position = vec4(pos, 0.0, 1.0); }\n";
    let frag = "#version 150\n#extension GL_ARB_gpu_shader5 : require\nuniform sampler2D layers[3];\nuniform int n;\nin vec2 uv;\n\
                out vec4 c;\nvoid main() { c = texture(layers[n], uv); }\n";
    let dir = pair_dir("translate-sampler-array-gpu-shader5", vert, frag);
    let out = on_pair(&dir, &["translate", "--to", "wgsl,spv", "--out"], "out");
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
    let wgsl = std::fs::read_to_string(dir.join("out/p.wgsl")).unwrap();
    assert!(wgsl.contains("layers_2"), "one texture per element: {wgsl}");
    let dir = pair_dir("translate-sampler-array-no-extension", vert, &frag.replace("#extension GL_ARB_gpu_shader5 : require\n", ""));
    let out = on_pair(&dir, &["translate", "--to", "wgsl", "--out"], "out");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{stdout}");
    assert!(stdout.contains(Code::NonConstantSamplerIndex.as_str()), "{stdout}");
}

/// Writes `text` to `name` in a fresh scratch folder `folder`, translates it for Vulkan
/// (`env`) to WGSL and SPIR-V, and returns effectc's stdout and the WGSL, asserting exit 0.
fn translate_vulkan_stage(folder: &str, name: &str, env: &str, text: &str) -> (String, String) {
    let (code, stdout, dir) = run_translate(folder, name, env, text);
    assert_eq!(code, Some(0), "{stdout}");
    let stem = name.split('.').next().unwrap_or(name);
    let wgsl = std::fs::read_to_string(dir.join(format!("out/{stem}.wgsl"))).unwrap();
    (stdout, wgsl)
}

/// `effectc translate --target-env ENV --to wgsl,spv` of one stage file `name` holding `text`
/// (in a fresh `folder`): exit code, stdout, the folder.
fn run_translate(folder: &str, name: &str, env: &str, text: &str) -> (Option<i32>, String, std::path::PathBuf) {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(folder);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let stage = dir.join(name);
    std::fs::write(&stage, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_effectc"))
        .args(["translate", "--target-env", env, "--to", "wgsl,spv", "--out"])
        .arg(dir.join("out"))
        .arg(&stage)
        .env("NO_COLOR", "1")
        .output()
        .unwrap();
    (out.status.code(), String::from_utf8_lossy(&out.stdout).into_owned(), dir)
}

/// Vulkan GLSL compute: a workgroup size given by specialization constants
/// (`local_size_x_id`) is their unspecialized defaults (1 where no constant has the id), and a
/// `writeonly` storage buffer is `read_write` in WGSL (which has no write-only storage);
/// naga's GLSL front refused the first ("Unexpected qualifier"), its validator the second.
#[test]
fn spec_constant_workgroup_sizes_and_write_only_buffers_translate() {
    let (_, wgsl) = translate_vulkan_stage(
        "translate-spec-workgroup",
        "fill.comp",
        "vulkan",
        "#version 450\nlayout(local_size_x_id = 0, local_size_y = 2, local_size_z_id = 7) in;\n\
         layout(constant_id = 0) const uint WIDTH = 16u;\n\
         layout(std430, set = 0, binding = 0) writeonly buffer Out { uint values[]; };\n\
         void main() { values[gl_GlobalInvocationID.x] = gl_GlobalInvocationID.y * WIDTH; }\n",
    );
    assert!(wgsl.contains("@workgroup_size(16, 2, 1)"), "{wgsl}");
    assert!(wgsl.contains("var<storage, read_write>"), "{wgsl}");
}

/// Vulkan 1.3 GLSL with what naga's SPIR-V front does not read as glslang writes it: an
/// array sized by `gl_WorkGroupSize` and a specialization-constant expression (folded to its
/// default), and texel buffers (storage buffers of texels at the bindings written, N0107).
#[test]
fn spec_constant_arrays_and_texel_buffers_translate_through_spirv() {
    let (stdout, wgsl) = translate_vulkan_stage(
        "translate-spec-arrays",
        "blur.comp",
        "vulkan1.3",
        "#version 450\nlayout(local_size_x = 32) in;\n\
         layout(constant_id = 0) const uint GROUP = 32u;\n\
         layout(constant_id = 1) const int TAPS = 3;\n\
         layout(constant_id = 2) const float GAIN = 0.5;\n\
         shared vec4 row[gl_WorkGroupSize.x + uint(2 * TAPS)];\n\
         layout(set = 0, binding = 0) uniform samplerBuffer source;\n\
         layout(set = 0, binding = 1, rgba32f) uniform writeonly imageBuffer target;\n\
         void main() {\n\
             int i = int(gl_GlobalInvocationID.x);\n\
             row[gl_LocalInvocationID.x] = texelFetch(source, i);\n\
             barrier();\n\
             vec4 sum = vec4(0.0);\n\
             for (int t = 0; t < 2 * TAPS; t++) sum += row[(gl_LocalInvocationID.x + uint(t)) % GROUP];\n\
             imageStore(target, i % imageSize(target), sum * GAIN);\n\
         }\n",
    );
    assert!(stdout.contains("N0107") && stdout.contains("buffer image `target`"), "{stdout}");
    assert!(wgsl.contains("@workgroup_size(32, 1, 1)"), "{wgsl}");
    assert!(wgsl.contains("array<vec4<f32>, 38>"), "32 + 2 * 3 texels of shared row: {wgsl}");
    assert!(wgsl.contains("override GAIN"), "a lone specialization constant stays overridable: {wgsl}");
    assert!(!wgsl.contains("texture"), "texel buffers are storage buffers: {wgsl}");
    assert!(wgsl.contains("@group(0) @binding(1) \nvar<storage, read_write> target"), "the binding written: {wgsl}");
}

/// A decision shared through workgroup memory (one invocation writes a `shared` flag or ORs
/// bits into a `shared` atomic, `barrier()`, all branch on it, a later `barrier()` behind
/// the branch) is written with `workgroupUniformLoad`, WGSL's uniform read, so tint's
/// uniformity analysis takes the later barrier; a load through an index computed at run
/// time stays a plain read (WGSL's uniform load wants a uniform pointer).
#[test]
fn workgroup_decisions_after_a_barrier_are_uniform_loads() {
    let (_, wgsl) = translate_vulkan_stage(
        "translate-uniform-loads",
        "last.comp",
        "vulkan",
        "#version 450\nlayout(local_size_x = 64) in;\n\
         layout(std430, set = 0, binding = 0) buffer Counter { uint done; uint result[]; };\n\
         shared bool is_last;\nshared uint votes;\nshared uint scratch[64];\n\
         void main() {\n\
           uint i = gl_LocalInvocationIndex;\n\
           scratch[i] = i;\n\
           if (i == 0u) { votes = 0u; is_last = atomicAdd(done, 1u) == 63u; }\n\
           barrier();\n\
           if (!is_last) return;\n\
           atomicOr(votes, scratch[63u - i] & 1u);\n\
           barrier();\n\
           if (votes == 0u) return;\n\
           barrier();\n\
           result[i] = scratch[(i + 1u) % 64u];\n\
         }\n",
    );
    assert!(wgsl.contains("workgroupUniformLoad((&is_last))"), "{wgsl}");
    assert!(wgsl.contains("workgroupUniformLoad((&votes))"), "{wgsl}");
    assert!(!wgsl.contains("workgroupUniformLoad((&scratch"), "a load at a run-time index stays plain:\n{wgsl}");
}

/// `outerProduct` on the route through SPIR-V (taken here for the subgroup operation) is
/// built column by column: naga's WGSL, MSL and HLSL writers cannot write the `Outer` it
/// reads from `OpOuterProduct`.
#[test]
fn outer_products_through_spirv_translate() {
    let (stdout, wgsl) = translate_vulkan_stage(
        "translate-outer-product",
        "outer.comp",
        "vulkan1.1",
        "#version 450\n#extension GL_KHR_shader_subgroup_arithmetic : require\nlayout(local_size_x = 8) in;\n\
         layout(std430, set = 0, binding = 0) buffer Out { mat3x2 m[]; };\n\
         void main() {\n\
           vec3 r = subgroupAdd(vec3(gl_GlobalInvocationID));\n\
           m[gl_GlobalInvocationID.x] = outerProduct(vec2(1.0, 2.0), r);\n\
         }\n",
    );
    assert!(stdout.contains(Code::SubgroupOfOne.as_str()), "{stdout}");
    assert!(!wgsl.contains("outerProduct"), "{wgsl}");
    assert!(wgsl.contains("mat3x2<f32>("), "{wgsl}");
}

/// Where both routes stop, `translate` names what stopped the route through SPIR-V, at the
/// user's line: naga's GLSL front stops first at the subgroup built-in (which the route
/// through SPIR-V takes), naga's SPIR-V front at the image atomic ("unsupported storage
/// class %11" in naga's words).
#[test]
fn untranslatable_programs_name_what_stopped_the_route_through_spirv() {
    let (code, stdout, _) = run_translate(
        "translate-image-atomics",
        "count.comp",
        "vulkan1.1",
        "#version 450\n#extension GL_KHR_shader_subgroup_basic : require\nlayout(local_size_x = 8) in;\n\
         layout(r32ui, set = 0, binding = 0) uniform uimage2D counts;\n\
         void main() {\n\
           uint lane = gl_SubgroupInvocationID;\n\
           imageAtomicAdd(counts, ivec2(gl_GlobalInvocationID.xy), lane + 1u);\n\
         }\n",
    );
    assert_eq!(code, Some(1), "{stdout}");
    assert!(stdout.contains("error[E0306]: the compute stage uses image atomics"), "{stdout}");
    assert!(stdout.contains("count.comp:7:"), "at the line of `imageAtomicAdd`:\n{stdout}");
    assert!(!stdout.contains("gl_SubgroupInvocationID`, which naga cannot translate"), "{stdout}");
}

/// Compute idioms naga refused: `texture()` in a compute stage (no derivatives: GL samples
/// the base level, written explicitly for naga), GL_KHR_memory_scope_semantics' scoped
/// coherence qualifiers (blanked: WGSL's barriers make storage visible), and a
/// `scalar`-layout uniform buffer whose `vec2` array is 8 bytes apart (WGSL's uniform rules
/// want 16: it becomes a read-only storage buffer, the same bytes).
#[test]
fn compute_stage_idioms_translate() {
    let (_, wgsl) = translate_vulkan_stage(
        "translate-compute-implicit-lod",
        "blit.comp",
        "opengl",
        "#version 430\nlayout(local_size_x = 8, local_size_y = 8) in;\n\
         layout(binding = 0) uniform sampler2D src;\n\
         layout(binding = 1, rgba8) writeonly uniform image2D dst;\n\
         void main() {\n\
           vec2 uv = (vec2(gl_GlobalInvocationID.xy) + 0.5) / vec2(textureSize(src, 0));\n\
           imageStore(dst, ivec2(gl_GlobalInvocationID.xy), texture(src, uv));\n\
         }\n",
    );
    assert!(wgsl.contains("textureSampleLevel("), "{wgsl}");
    let (_, wgsl) = translate_vulkan_stage(
        "translate-scoped-coherence",
        "count.comp",
        "vulkan1.3",
        "#version 450\n#extension GL_KHR_memory_scope_semantics : require\nlayout(local_size_x = 64) in;\n\
         layout(std430, set = 0, binding = 0) workgroupcoherent buffer Counts { uint n[]; };\n\
         layout(set = 0, binding = 1, r32f) uniform queuefamilycoherent image2D img;\n\
         void main() {\n\
           n[gl_GlobalInvocationID.x] += 1u;\n\
           imageStore(img, ivec2(gl_GlobalInvocationID.xy), vec4(float(n[0])));\n\
         }\n",
    );
    assert!(wgsl.contains("@compute"), "{wgsl}");
    let (_, wgsl) = translate_vulkan_stage(
        "translate-scalar-uniforms",
        "offsets.comp",
        "vulkan1.2",
        "#version 450\n#extension GL_EXT_scalar_block_layout : require\nlayout(local_size_x = 4) in;\n\
         layout(set = 0, binding = 0, scalar) uniform Offsets { vec2 at[4]; float scale; } offsets;\n\
         layout(std430, set = 0, binding = 1) buffer Out { vec2 v[]; };\n\
         void main() { v[gl_LocalInvocationIndex] = offsets.at[gl_LocalInvocationIndex] * offsets.scale; }\n",
    );
    assert!(wgsl.contains("var<storage> offsets") || wgsl.contains("var<storage, read> offsets"), "{wgsl}");
}

/// Arrays of textures and of storage images sized at run time (bindless) each get N0113,
/// which says how many elements the translation binds; naga's SPIR-V route takes both.
#[test]
fn runtime_sized_texture_and_image_arrays_are_noted() {
    let (code, stdout, _) = run_translate(
        "translate-bindless",
        "bindless.comp",
        "vulkan1.1",
        "#version 450\n#extension GL_EXT_nonuniform_qualifier : require\nlayout(local_size_x = 8, local_size_y = 8) in;\n\
         layout(set = 0, binding = 0) uniform sampler2D textures[];\n\
         layout(set = 1, binding = 0, rgba8) uniform writeonly image2D targets[];\n\
         layout(push_constant) uniform Pick { uint source; uint target; } pick;\n\
         void main() {\n\
           ivec2 p = ivec2(gl_GlobalInvocationID.xy);\n\
           imageStore(targets[nonuniformEXT(pick.target)], p, texelFetch(textures[nonuniformEXT(pick.source)], p, 0));\n\
         }\n",
    );
    assert_eq!(code, Some(0), "{stdout}");
    assert!(stdout.contains("note[N0113]: `textures` is sized at run time"), "{stdout}");
    assert!(stdout.contains("note[N0113]: `targets` is sized at run time"), "{stdout}");
}

/// A multisampled storage image (`image2DMSArray`; WGSL has none) is named as such where
/// translation stops, not as what naga's GLSL parser made of the unknown type name.
#[test]
fn multisampled_storage_images_are_named() {
    let (code, stdout, _) = run_translate(
        "translate-msaa-image",
        "resolve.comp",
        "vulkan1.1",
        "#version 450\nlayout(local_size_x = 8, local_size_y = 8) in;\n\
         layout(binding = 0, rgba8) uniform readonly image2DMSArray msaa_in;\n\
         layout(binding = 1, rgba8) uniform writeonly image2DArray resolved;\n\
         void main() {\n\
           ivec3 p = ivec3(gl_GlobalInvocationID);\n\
           imageStore(resolved, p, imageLoad(msaa_in, p, 0));\n\
         }\n",
    );
    assert_eq!(code, Some(1), "{stdout}");
    assert!(stdout.contains("error[E0306]: the compute stage uses multisampled storage images"), "{stdout}");
    assert!(stdout.contains("resolve.comp:3:"), "at the declaration:\n{stdout}");
}

/// The layer count of an arrayed storage image (`imageSize` of an `image2DArray`) is valid
/// SPIR-V: naga's writer asks it with `OpImageQuerySizeLod`, which storage images do not take.
#[test]
fn storage_image_layer_counts_are_valid_spirv() {
    let (code, stdout, dir) = run_translate(
        "translate-storage-layers",
        "layers.comp",
        "opengl",
        "#version 430\nlayout(local_size_x = 8, local_size_y = 8) in;\n\
         layout(binding = 0, rgba8) uniform writeonly image2DArray dst;\n\
         void main() {\n\
           ivec3 size = imageSize(dst);\n\
           imageStore(dst, ivec3(gl_GlobalInvocationID.xy, size.z - 1), vec4(float(size.z) / 8.0));\n\
         }\n",
    );
    assert_eq!(code, Some(0), "{stdout}");
    let bytes = std::fs::read(dir.join("out").join("layers.comp.spv")).unwrap();
    let words: Vec<u32> = bytes.chunks(4).map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]])).collect();
    // The opcodes, instruction by instruction after the 5-word header.
    let mut ops = Vec::new();
    let mut i = 5;
    while i < words.len() {
        ops.push(words[i] & 0xffff);
        i += (words[i] >> 16).max(1) as usize;
    }
    const QUERY_SIZE_LOD: u32 = 103;
    const QUERY_SIZE: u32 = 104;
    assert!(ops.contains(&QUERY_SIZE) && !ops.contains(&QUERY_SIZE_LOD), "{ops:?}");
    if spirv_val_available() {
        spirv_val(&words, &dir.join("layers.spv")).unwrap();
    }
}
