//! `<effect>.reflect.json` is enough to drive the WGSL on its own: every uniform member
//! (struct fields and arrays included) has its offset, size and the name the WGSL declares,
//! every pass its targets and reads, and a buffer packed from the JSON alone renders the
//! frame effectc renders.

use std::path::{Path, PathBuf};
use std::time::Duration;

use serde_json::Value;

use effectc::check::Outcome;
use effectc::render::frames::Pixels;
use effectc::render::memory::{MemoryDrawer, MemoryRequest};

use crate::common::{self, code, effectc, scratch, stdout};
use crate::render::have_gpu;

/// `effectc translate DIR --to wgsl,reflect`: each unit's (reflection, WGSL).
fn reflections(input: &Path, out: &Path) -> Vec<(Value, String)> {
    let o = effectc(&["translate", input.to_str().unwrap(), "--to", "wgsl,reflect", "--out", out.to_str().unwrap()]);
    assert_eq!(code(&o), 0, "{}: {}", input.display(), stdout(&o));
    let mut files: Vec<PathBuf> = walk(out).into_iter().filter(|p| p.to_string_lossy().ends_with(".reflect.json")).collect();
    files.sort();
    assert!(!files.is_empty(), "{}: no reflection written", input.display());
    files
        .into_iter()
        .map(|f| {
            let json: Value = serde_json::from_str(&std::fs::read_to_string(&f).unwrap()).unwrap();
            let wgsl = std::fs::read_to_string(f.to_string_lossy().replace(".reflect.json", ".wgsl")).unwrap();
            (json, wgsl)
        })
        .collect()
}

fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            out.extend(walk(&p));
        } else {
            out.push(p);
        }
    }
    out
}

fn n(v: &Value) -> u64 {
    v.as_u64().unwrap_or_else(|| panic!("not a count: {v}"))
}

/// Checks `members` lie in `[start, end)` in order without overlapping, each declared in
/// the WGSL under its `wgsl_name`; returns how many members (at any depth) there are.
fn check_members(members: &[Value], (start, end): (u64, u64), wgsl: &str, at: &str) -> usize {
    let mut cursor = start;
    let mut count = 0;
    for m in members {
        let (name, offset, size) = (m["name"].as_str().unwrap(), n(&m["offset"]), n(&m["size"]));
        assert!(offset >= cursor && offset + size <= end, "{at}: `{name}` at {offset}+{size} outside {cursor}..{end}");
        let wgsl_name = m["wgsl_name"].as_str().unwrap();
        assert!(
            wgsl.contains(&format!("    {wgsl_name}: {}", m["wgsl_type"].as_str().unwrap())),
            "{at}: `{wgsl_name}` is not declared:\n{wgsl}"
        );
        count += 1;
        if let Some(fields) = m["members"].as_array() {
            // Fields are given for element 0 of an array of structs.
            let element = m["array"]["stride"].as_u64().unwrap_or(size);
            count += check_members(fields, (offset, offset + element), wgsl, &format!("{at}.{name}"));
        }
        cursor = offset + size;
    }
    count
}

#[test]
fn every_shipped_effect_reflects_each_member_pass_and_name_the_wgsl_declares() {
    let dir = scratch("reflection", "effects");
    let mut members = 0;
    let mut passes = 0;
    for effect in common::subdirs("effects") {
        let name = common::name_of(&effect);
        for (json, wgsl) in reflections(&effect, &dir.join(&name)) {
            let at = json["effect"].as_str().unwrap().to_string();
            if let Some(block) = json["uniform_block"].as_object() {
                members += check_members(block["members"].as_array().unwrap(), (0, n(&block["size"])), &wgsl, &at);
            }
            for b in json["bindings"].as_array().unwrap() {
                let wgsl_name = b["wgsl_name"].as_str().unwrap();
                assert!(
                    wgsl.contains(&format!("> {wgsl_name}: ")) || wgsl.contains(&format!("var {wgsl_name}: ")),
                    "{at}: binding `{wgsl_name}`"
                );
            }
            for v in json["vertex_inputs"].as_array().unwrap() {
                // A folded geometry program pulls its inputs from storage buffers: no WGSL name.
                let Some(wgsl_name) = v["wgsl_name"].as_str() else {
                    assert!(json["geometry"].is_object(), "{at}: input without a WGSL name: {v}");
                    continue;
                };
                assert!(wgsl.contains(&format!("{wgsl_name}: {}", v["wgsl_type"].as_str().unwrap())), "{at}: input `{wgsl_name}`");
            }
            let manifest = std::fs::read_to_string(effect.join("effect.toml")).unwrap();
            if manifest.contains("[[passes]]") {
                let pass = &json["pass"];
                assert!(pass.is_object(), "{at}: a pass's reflection names its pass");
                assert_eq!(format!("{name}.{}", pass["name"].as_str().unwrap()), at);
                let targets = pass["targets"].as_array().unwrap();
                assert!(!targets.is_empty() || pass["depth"].is_object(), "{at}: a pass draws into something");
                for t in targets.iter().chain(pass["depth"].as_object().map(|_| &pass["depth"])) {
                    assert_ne!(t["format"], "unknown", "{at}: {t}");
                }
                for r in pass["reads"].as_array().unwrap() {
                    let sampler = r["sampler"].as_str().unwrap();
                    assert!(json["bindings"].as_array().unwrap().iter().any(|b| b["glsl"] == sampler), "{at}: read by `{sampler}`");
                }
                passes += 1;
            } else {
                assert!(json["pass"].is_null(), "{at}: a single-pass effect has no pass");
            }
        }
    }
    assert!(members > 100 && passes >= 15, "{members} members, {passes} passes reflected");
}

#[test]
fn struct_fields_arrays_and_renamed_names_are_reflected_as_the_wgsl_declares_them() {
    let dir = scratch("reflection", "fields");
    std::fs::create_dir_all(&dir).unwrap();
    let vert = "#version 330\nstruct Light { vec3 position; float radius; bool on; };\nuniform Light lights[2];\nuniform mat3 m3;\n\
                uniform vec4 tint0;\nin vec3 pos0;\nout vec3 c;\nvoid main() {\n    c = lights[1].position * lights[0].radius * \
                (lights[1].on ? 1.0 : 0.0) + m3 * pos0 + tint0.xyz;\n    gl_Position = vec4(pos0, 1.0);\n}\n";
    std::fs::write(dir.join("p.vert"), vert).unwrap();
    std::fs::write(dir.join("p.frag"), "#version 330\nin vec3 c;\nout vec4 o;\nvoid main() { o = vec4(c, 1.0); }\n").unwrap();
    let (json, wgsl) = reflections(&dir, &dir.join("out")).remove(0);
    let block = &json["uniform_block"];
    check_members(block["members"].as_array().unwrap(), (0, n(&block["size"])), &wgsl, "p");
    let member = |name: &str| block["members"].as_array().unwrap().iter().find(|m| m["name"] == name).unwrap().clone();
    let lights = member("lights");
    assert_eq!((n(&lights["array"]["length"]), n(&lights["array"]["stride"])), (2, 32), "{lights}");
    let fields: Vec<(&str, u64, &str)> = lights["members"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| (f["name"].as_str().unwrap(), n(&f["offset"]), f["repr"].as_str().unwrap()))
        .collect();
    assert_eq!(fields, [("position", 0, "plain"), ("radius", 12, "plain"), ("on", 16, "bool_as_uint")]);
    // naga's WGSL adds `_` to names ending in a digit; the reflection says so.
    assert_eq!((member("m3")["wgsl_name"].as_str(), n(&member("m3")["column_stride"])), (Some("m3_"), 16));
    assert_eq!(member("tint0")["wgsl_name"], "tint0_");
    assert_eq!(json["vertex_inputs"][0]["wgsl_name"], "pos0_");
}

/// Writes `value` (numbers, booleans and lists of them, as the reflection gives values)
/// into the slot of WGSL type `ty` at `offset`, by the JSON's layout facts alone.
fn write(buf: &mut [u8], offset: usize, slot: &Value, ty: &str, value: &Value) {
    if let (Some(stride), Some(items)) = (slot["array"]["stride"].as_u64(), value.as_array()) {
        let element = ty.strip_prefix("array<").and_then(|t| t.rsplit_once(',')).map(|(e, _)| e.trim()).unwrap();
        let element_slot = serde_json::json!({ "column_stride": slot["column_stride"] });
        for (i, item) in items.iter().enumerate() {
            write(buf, offset + i * stride as usize, &element_slot, element, item);
        }
        return;
    }
    let mut scalars = Vec::new();
    flatten(value, &mut scalars);
    let put = |buf: &mut [u8], at: usize, v: f64| {
        let bytes = match ty.rsplit('<').next().unwrap().trim_end_matches('>') {
            "i32" => (v as i32).to_le_bytes(),
            "u32" => (v as u32).to_le_bytes(),
            _ => (v as f32).to_le_bytes(),
        };
        buf[at..at + 4].copy_from_slice(&bytes);
    };
    let rows = ty.strip_prefix("mat").map(|t| t.as_bytes()[2] - b'0');
    for (k, v) in scalars.into_iter().enumerate() {
        match (rows, slot["column_stride"].as_u64()) {
            (Some(r), Some(stride)) => put(buf, offset + (k / r as usize) * stride as usize + 4 * (k % r as usize), v),
            _ => put(buf, offset + 4 * k, v),
        }
    }
}

fn flatten(v: &Value, out: &mut Vec<f64>) {
    match v {
        Value::Array(items) => items.iter().for_each(|i| flatten(i, out)),
        Value::Bool(b) => out.push(f64::from(u8::from(*b))),
        _ => out.push(v.as_f64().unwrap()),
    }
}

/// The member whose slot is exactly `[start, start + len)` (an array element's too).
fn slot_at(members: &[Value], start: u64, len: u64, shift: u64) -> Option<(Value, String)> {
    for m in members {
        let (offset, size) = (n(&m["offset"]) + shift, n(&m["size"]));
        if offset == start && size == len {
            return Some((m.clone(), m["wgsl_type"].as_str().unwrap().to_string()));
        }
        if start < offset || start >= offset + size {
            continue;
        }
        let stride = m["array"]["stride"].as_u64();
        let i = stride.map_or(0, |s| (start - offset) / s);
        if let Some(fields) = m["members"].as_array() {
            return slot_at(fields, start, len, shift + i * stride.unwrap_or(0));
        }
        if let Some(s) = stride {
            let element = m["wgsl_type"].as_str().unwrap().strip_prefix("array<").and_then(|t| t.rsplit_once(',')).unwrap().0.trim();
            let slot = serde_json::json!({ "column_stride": m["column_stride"] });
            return (offset + i * s == start).then(|| (slot, element.to_string()));
        }
    }
    None
}

/// The uniform block packed from the reflection alone: every fill with a value.
fn pack(block: &Value) -> Vec<u8> {
    let mut buf = vec![0u8; n(&block["size"]) as usize];
    for fill in block["fills"].as_array().unwrap() {
        let value = &fill["value"];
        if value.is_null() {
            continue; // a semantic: the renderer writes it every frame
        }
        let (start, end) = (n(&fill["bytes"][0]), n(&fill["bytes"][1]));
        let (slot, ty) =
            slot_at(block["members"].as_array().unwrap(), start, end - start, 0).unwrap_or_else(|| panic!("no member holds {fill}"));
        write(&mut buf, start as usize, &slot, &ty, value);
    }
    buf
}

#[test]
fn a_uniform_buffer_packed_from_the_reflection_alone_renders_the_same_frame() {
    if !have_gpu() {
        return;
    }
    let gpu = effectc::render::device::Gpu::new().unwrap();
    let dir = scratch("reflection", "pack");
    for effect in ["sun", "wood", "bloom"] {
        let path = PathBuf::from("effects").join(effect);
        let blocks: Vec<(usize, Value)> = reflections(&path, &dir.join(effect))
            .into_iter()
            .filter(|(json, _)| json["uniform_block"].is_object())
            .map(|(json, _)| (json["pass"]["index"].as_u64().unwrap_or(0) as usize, json["uniform_block"].clone()))
            .collect();
        let (_, checked) = common::check(&path);
        let c = &checked[0];
        let m = MemoryRequest {
            size: (64, 64),
            frames: 1,
            start: 0.75,
            step: 0.1,
            float: false,
            timeout: Duration::from_secs(60),
            read_back: None,
            degenerate: None,
        };
        let mut outcome = Outcome::default();
        let mut drawer =
            MemoryDrawer::new(&gpu, c, &mut outcome, &[], m, None).unwrap_or_else(|| panic!("{effect}: {:?}", outcome.diagnostics));
        let mut frame = |drawer: &mut MemoryDrawer<'_>| match drawer.render(&gpu, &mut outcome, m.start).unwrap().frames.remove(0) {
            Pixels::Rgba8(p) => p,
            Pixels::Rgba32F(_) => unreachable!(),
        };
        let rendered = frame(&mut drawer);
        let block_of = |pass: usize, group: u32, binding: u32| {
            let (_, b) =
                blocks.iter().find(|(p, b)| *p == pass && n(&b["group"]) == u64::from(group) && n(&b["binding"]) == u64::from(binding))?;
            Some(b)
        };
        let replaced = drawer.set_uniform_bytes(&|p, g, b| block_of(p, g, b).map(pack)).unwrap();
        assert_eq!(replaced, blocks.len(), "{effect}: every reflected block has a buffer");
        assert_eq!(frame(&mut drawer), rendered, "{effect}: the JSON-packed buffer draws another frame");
        // The values matter: a zeroed buffer draws something else.
        drawer.set_uniform_bytes(&|p, g, b| block_of(p, g, b).map(|b| vec![0u8; n(&b["size"]) as usize])).unwrap();
        assert_ne!(frame(&mut drawer), rendered, "{effect}: zeroed uniforms draw the same frame: the test proves nothing");
    }
}
