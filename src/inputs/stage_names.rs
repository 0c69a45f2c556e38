//! The stage of a file: from its name (`.vert`, `x.vert.glsl`, `x_vs.glsl`, `vertex.glsl`),
//! else, for a `.glsl` file, from its text (what it writes or calls), with the evidence.
//!
//! The name also gives the file's program stem (`x.vert.glsl` and `x_fs.glsl` are both of
//! program `x`), which the directory walk groups by.

use std::path::Path;

use crate::stage::StageKind;

/// Extensions of files that may hold any stage (glslang's `x.vert.glsl` convention).
const GENERIC: [&str; 3] = ["glsl", "shader", "sl"];

/// The stage a file's name gives, and its program stem.
pub fn from_name(path: &Path) -> Option<(StageKind, String)> {
    let name = path.file_name()?.to_str()?;
    let (stem, ext) = name.rsplit_once('.').unwrap_or((name, ""));
    if let Some(kind) = StageKind::from_extension(ext) {
        return Some((kind, stem.to_string()));
    }
    if !GENERIC.contains(&ext.to_ascii_lowercase().as_str()) {
        return None;
    }
    // `x.vert.glsl`, `x.vs.glsl`
    if let Some((inner_stem, inner)) = stem.rsplit_once('.') {
        if let Some(kind) = StageKind::from_extension(inner) {
            return Some((kind, inner_stem.to_string()));
        }
    }
    // `x_vs.glsl`, `x_vert.glsl`, `x-frag.glsl`
    if let Some(i) = stem.rfind(['_', '-']) {
        if let Some(kind) = StageKind::from_extension(&stem[i + 1..]) {
            return Some((kind, stem[..i].to_string()));
        }
    }
    // `vertex.glsl`, `fragment.glsl`: the directory's one program.
    StageKind::from_extension(stem).map(|kind| (kind, String::new()))
}

/// The stage a `.glsl` file's text shows, and the evidence (None: not a stage with `main`,
/// or the text shows no stage or more than one).
pub fn from_text(text: &str) -> Option<(StageKind, &'static str)> {
    let code = super::without_comments(text);
    if !super::code_defines_main(&code) {
        return None;
    }
    if let Some(kind) = pragma_stage(&code) {
        return Some((kind, "its `#pragma shader_stage` names it"));
    }
    let has = |word: &str| contains_word(&code, word);
    let geometry = has("EmitVertex") || has("EmitStreamVertex");
    let tess_eval = has("gl_TessCoord");
    let tess_control = has("gl_TessLevelOuter") && has("gl_InvocationID") && !tess_eval;
    let position = has("gl_Position");
    let color_out = ["out vec4", "out highp vec4", "out mediump vec4", "out lowp vec4"].iter().any(|d| code.contains(d));
    let fragment = has("gl_FragColor") || has("gl_FragData") || has("gl_FragCoord") || has("discard") || color_out;
    let rules: [(bool, StageKind, &'static str); 6] = [
        (geometry, StageKind::Geometry, "it calls `EmitVertex`"),
        (tess_control, StageKind::TessControl, "it writes `gl_TessLevelOuter`"),
        (tess_eval, StageKind::TessEval, "it reads `gl_TessCoord`"),
        (position && !geometry && !tess_eval && !tess_control, StageKind::Vertex, "it writes `gl_Position`"),
        // `out vec4` is any stage's output: the other stages' built-ins tell them first.
        (
            fragment && !position && !geometry && !tess_eval && !tess_control,
            StageKind::Fragment,
            "it writes a fragment output and no `gl_Position`",
        ),
        (has("local_size_x") && !position && !fragment, StageKind::Compute, "it declares `local_size_x`"),
    ];
    let mut shown = rules.iter().filter(|(yes, _, _)| *yes);
    let (_, kind, why) = shown.next()?;
    if shown.next().is_some() {
        return None;
    }
    Some((*kind, why))
}

/// The stage shaderc's `#pragma shader_stage(NAME)` names (glslc's convention for `.glsl`
/// files).
fn pragma_stage(code: &str) -> Option<StageKind> {
    code.lines().find_map(|line| {
        let d = line.trim_start().strip_prefix('#')?.trim_start().strip_prefix("pragma")?.trim_start();
        let name = d.strip_prefix("shader_stage")?.trim_start().strip_prefix('(')?.split(')').next()?.trim();
        Some(match name {
            "vertex" => StageKind::Vertex,
            "fragment" => StageKind::Fragment,
            "geometry" => StageKind::Geometry,
            "tesscontrol" => StageKind::TessControl,
            "tesseval" => StageKind::TessEval,
            "compute" => StageKind::Compute,
            "task" => StageKind::Task,
            "mesh" => StageKind::Mesh,
            "raygen" => StageKind::RayGeneration,
            "intersect" => StageKind::Intersection,
            "anyhit" => StageKind::AnyHit,
            "closesthit" => StageKind::ClosestHit,
            "miss" => StageKind::Miss,
            "callable" => StageKind::Callable,
            _ => return None,
        })
    })
}

fn contains_word(text: &str, word: &str) -> bool {
    text.match_indices(word).any(|(i, _)| {
        let before = text[..i].chars().next_back();
        let after = text[i + word.len()..].chars().next();
        let part = |c: Option<char>| c.is_some_and(|c| c.is_alphanumeric() || c == '_');
        !part(before) && !part(after)
    })
}

/// A file that holds two stages behind conditionals on macros the host code defines
/// (`#if defined(VERTEX)` … `#elif defined(FRAGMENT)`, the emulator packs' format): the
/// vertex stage's macro and the fragment stage's. The known pairs are the ones shader
/// packs use: `VERTEX`/`FRAGMENT`, `VERTEX_SHADER`/`FRAGMENT_SHADER`, `VS`/`FS`,
/// `_VERTEX_`/`_FRAGMENT_`, `COMPILING_VS`/`COMPILING_FS`.
pub fn two_stage_macros(text: &str) -> Option<(&'static str, &'static str)> {
    const PAIRS: [(&str, &str); 5] = [
        ("VERTEX", "FRAGMENT"),
        ("VERTEX_SHADER", "FRAGMENT_SHADER"),
        ("VS", "FS"),
        ("_VERTEX_", "_FRAGMENT_"),
        ("COMPILING_VS", "COMPILING_FS"),
    ];
    let tested: Vec<&str> = text.lines().filter_map(conditional_macro).collect();
    PAIRS.into_iter().find(|(v, f)| tested.contains(v) && tested.contains(f))
}

/// The macro a `#ifdef M`, `#if defined(M)`, `#if defined M` or `#elif defined(M)` line
/// tests.
fn conditional_macro(line: &str) -> Option<&str> {
    let d = line.trim_start().strip_prefix('#')?.trim_start();
    let rest = if let Some(r) = d.strip_prefix("ifdef") {
        r
    } else {
        let r = d.strip_prefix("elif").or_else(|| d.strip_prefix("if"))?.trim_start();
        r.strip_prefix("defined")?
    };
    let name = rest.trim_start().trim_start_matches('(').trim_start();
    let end = name.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(name.len());
    (end > 0).then(|| &name[..end])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stage_names_people_use() {
        let kind = |n: &str| from_name(Path::new(n));
        assert_eq!(kind("sun.vert"), Some((StageKind::Vertex, "sun".into())));
        assert_eq!(kind("sun.vert.glsl"), Some((StageKind::Vertex, "sun".into())));
        assert_eq!(kind("sun.fs.glsl"), Some((StageKind::Fragment, "sun".into())));
        assert_eq!(kind("sun_vs.glsl"), Some((StageKind::Vertex, "sun".into())));
        assert_eq!(kind("sun_frag.glsl"), Some((StageKind::Fragment, "sun".into())));
        assert_eq!(kind("sun-geom.glsl"), Some((StageKind::Geometry, "sun".into())));
        assert_eq!(kind("vertex.glsl"), Some((StageKind::Vertex, String::new())));
        assert_eq!(kind("common.glsl"), None);
        assert_eq!(kind("notes_vs.txt"), None);
        assert_eq!(kind("shadow.rchit"), Some((StageKind::ClosestHit, "shadow".into())));
        assert_eq!(kind("cull.task.glsl"), Some((StageKind::Task, "cull".into())));
        assert_eq!(kind("cull.mesh"), Some((StageKind::Mesh, "cull".into())));
    }

    #[test]
    fn stages_the_text_shows() {
        let v = "in vec3 p;\nvoid main() { gl_Position = vec4(p, 1.0); }\n";
        assert_eq!(from_text(v).map(|(k, _)| k), Some(StageKind::Vertex));
        let f = "void main() { gl_FragColor = vec4(1.0); }\n";
        assert_eq!(from_text(f).map(|(k, _)| k), Some(StageKind::Fragment));
        let g = "layout(points) in;\nvoid main() { gl_Position = gl_in[0].gl_Position; EmitVertex(); }\n";
        assert_eq!(from_text(g).map(|(k, _)| k), Some(StageKind::Geometry));
        assert_eq!(from_text("float helper(float x) { return x; }\n"), None, "no main: an include");
        let core = "in vec2 uv;\nout vec4 color;\nvoid main() { color = vec4(uv, 0.0, 1.0); }\n";
        assert_eq!(from_text(core).map(|(k, _)| k), Some(StageKind::Fragment));
        let both = "void main() { gl_Position = vec4(0.0); gl_FragColor = vec4(1.0); }\n";
        assert_eq!(from_text(both).map(|(k, _)| k), Some(StageKind::Vertex), "gl_Position decides");
        assert_eq!(from_text("// gl_Position = gl_FragColor;\nvoid main() { }\n"), None, "comments are no evidence");
        let pragma = "#pragma shader_stage(compute)\nlayout(local_size_x = 8) in;\nvoid main() { gl_Position; }\n";
        assert_eq!(from_text(pragma).map(|(k, _)| k), Some(StageKind::Compute), "shaderc's pragma decides");
        let raygen = "#version 460\n#pragma shader_stage( raygen )\nvoid main() { }\n";
        assert_eq!(from_text(raygen).map(|(k, _)| k), Some(StageKind::RayGeneration));
        assert_eq!(from_text("// #pragma shader_stage(vertex)\nvoid main() { }\n"), None, "not in a comment");
    }
    #[test]
    fn two_stage_files_are_told_by_their_conditionals() {
        let retro = "#if defined(VERTEX)\nvoid main() {}\n#elif defined(FRAGMENT)\nvoid main() {}\n#endif\n";
        assert_eq!(two_stage_macros(retro), Some(("VERTEX", "FRAGMENT")));
        assert_eq!(
            two_stage_macros("#ifdef VERTEX_SHADER\n#endif\n#ifdef FRAGMENT_SHADER\n#endif\n"),
            Some(("VERTEX_SHADER", "FRAGMENT_SHADER"))
        );
        assert_eq!(two_stage_macros("#ifdef VERTEX\n#endif\n"), None, "one stage only");
        assert_eq!(two_stage_macros("#if defined VS\n#else\n#endif\n#ifdef FS\n#endif\n"), Some(("VS", "FS")));
    }
}
