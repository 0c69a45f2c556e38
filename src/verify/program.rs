//! The user's original GLSL compiled and linked by the OpenGL driver: every stage's text as
//! the front read it (includes inlined, nothing rewritten), one program object. The
//! driver's errors become E0502 diagnostics at the line they name in the user's file.

use glow::HasContext;

use crate::diag::{Code, Diagnostic, FileId, Files};
use crate::front::reference::log::{span_on_line, LineTable};
use crate::stage::StageKind;

/// A linked GL program.
pub struct GlProgram {
    pub program: glow::Program,
}

/// Compiles and links `stages` (file of the stage text, kind). Errors are the driver's own,
/// placed in the user's files.
pub fn link(gl: &glow::Context, files: &Files, stages: &[(FileId, StageKind)]) -> Result<GlProgram, Vec<Diagnostic>> {
    // SAFETY: calls on the current context with objects it created.
    unsafe {
        let program = gl.create_program().map_err(|e| vec![Diagnostic::new(Code::GlRejects, e)])?;
        let mut shaders = Vec::new();
        let mut errors = Vec::new();
        for &(file, kind) in stages {
            let created = shader_type(kind).ok_or_else(|| format!("OpenGL has no {} stage", kind.title()));
            let shader = match created.and_then(|t| gl.create_shader(t)) {
                Ok(s) => s,
                Err(e) => {
                    errors.push(Diagnostic::new(Code::GlRejects, e).in_file(file));
                    continue;
                }
            };
            gl.shader_source(shader, &for_driver(files.text(file)));
            gl.compile_shader(shader);
            if !gl.get_shader_compile_status(shader) {
                errors.extend(place(files, file, &gl.get_shader_info_log(shader), kind));
            }
            gl.attach_shader(program, shader);
            shaders.push(shader);
        }
        if errors.is_empty() {
            gl.link_program(program);
            if !gl.get_program_link_status(program) {
                let log = gl.get_program_info_log(program);
                let first = stages.first().map_or(FileId(0), |s| s.0);
                errors.push(
                    Diagnostic::new(Code::GlRejects, "the OpenGL driver does not link the program")
                        .in_file(first)
                        .with_note(format!("the driver's log: {}", log.trim())),
                );
            }
        }
        for s in shaders {
            gl.detach_shader(program, s);
            gl.delete_shader(s);
        }
        if errors.is_empty() {
            Ok(GlProgram { program })
        } else {
            gl.delete_program(program);
            Err(errors)
        }
    }
}

/// Extensions about `#include`: the front has inlined the files already, and a GL driver
/// without them (Mesa) refuses the directive.
const INCLUDE_EXTENSIONS: [&str; 3] =
    ["GL_GOOGLE_include_directive", "GL_ARB_shading_language_include", "GL_GOOGLE_cpp_style_line_directive"];

/// The stage text as the driver gets it: `#extension` lines for the include extensions
/// blanked (lines and columns of everything else unchanged).
fn for_driver(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for line in text.split_inclusive('\n') {
        let t = line.trim_start();
        let about_include =
            t.starts_with('#') && t[1..].trim_start().starts_with("extension") && INCLUDE_EXTENSIONS.iter().any(|e| t.contains(e));
        if about_include {
            let body = line.trim_end_matches(['\n', '\r']);
            out.push_str(&" ".repeat(body.len()));
            out.push_str(&line[body.len()..]);
        } else {
            out.push_str(line);
        }
    }
    out
}

/// The GL shader type of a stage (None: a stage only Vulkan has).
fn shader_type(kind: StageKind) -> Option<u32> {
    Some(match kind {
        StageKind::Vertex => glow::VERTEX_SHADER,
        StageKind::TessControl => glow::TESS_CONTROL_SHADER,
        StageKind::TessEval => glow::TESS_EVALUATION_SHADER,
        StageKind::Geometry => glow::GEOMETRY_SHADER,
        StageKind::Fragment => glow::FRAGMENT_SHADER,
        StageKind::Compute => glow::COMPUTE_SHADER,
        // GL_NV_mesh_shader's stages.
        StageKind::Task => 0x955A,
        StageKind::Mesh => 0x9559,
        _ => return None,
    })
}

/// One error of a driver's compile log: `0:12(5): error: message` (Mesa), `0(12) : error
/// C0000: message` (NVIDIA), `ERROR: 0:12: message` (others).
#[derive(Debug, Clone, PartialEq)]
pub struct LogError {
    /// (source string, line, column); column 0 when the driver gives none.
    pub at: Option<(i64, i64, i64)>,
    pub text: String,
}

/// The errors of a driver log, warnings left out.
pub fn parse_log(log: &str) -> Vec<LogError> {
    let mut out = Vec::new();
    for line in log.lines().map(str::trim).filter(|l| !l.is_empty()) {
        let lower = line.to_ascii_lowercase();
        if !lower.contains("error") {
            continue;
        }
        out.push(parse_line(line).unwrap_or(LogError { at: None, text: line.to_string() }));
    }
    out
}

fn parse_line(line: &str) -> Option<LogError> {
    let line = line.strip_prefix("ERROR:").map_or(line, str::trim_start);
    let (string, rest) = line.split_once([':', '('])?;
    let string: i64 = string.trim().parse().ok()?;
    let digits = |s: &str| s.chars().take_while(char::is_ascii_digit).collect::<String>();
    let l = digits(rest);
    let line_no: i64 = l.parse().ok()?;
    let mut rest = &rest[l.len()..];
    let mut column = 0;
    if let Some(r) = rest.strip_prefix('(') {
        let c = digits(r);
        column = c.parse().unwrap_or(0);
        rest = r[c.len()..].strip_prefix(')').unwrap_or(&r[c.len()..]);
    }
    let rest = rest.trim_start_matches([')', ' ', ':']);
    let text = rest.strip_prefix("error").map_or(rest, |r| r.trim_start_matches([':', ' '])).trim();
    Some(LogError { at: Some((string, line_no, column)), text: text.to_string() })
}

/// The errors of a stage's compile log as diagnostics in `file`.
fn place(files: &Files, file: FileId, log: &str, kind: StageKind) -> Vec<Diagnostic> {
    let text = files.text(file);
    let table = LineTable::new(text);
    let mut out: Vec<Diagnostic> = parse_log(log)
        .into_iter()
        .map(|e| {
            let d = Diagnostic::new(Code::GlRejects, e.text.clone());
            let d = match e.at.and_then(|(s, l, c)| table.line_range(s, l).map(|r| (r, c))) {
                Some((line, column)) => d.at(file, span_on_line(text, line, column, &e.text), "the OpenGL driver reports this here"),
                None => d.in_file(file),
            };
            d.with_note(format!("the OpenGL driver does not compile this {kind} stage"))
        })
        .collect();
    if out.is_empty() {
        out.push(
            Diagnostic::new(Code::GlRejects, format!("the OpenGL driver does not compile this {kind} stage"))
                .in_file(file)
                .with_note(format!("the driver's log: {}", log.trim())),
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn include_extensions_are_blanked_in_place() {
        let text = "#version 330\r\n#extension GL_GOOGLE_include_directive : require\r\nvoid main() {}\n";
        let out = for_driver(text);
        assert_eq!(out.len(), text.len());
        assert!(!out.contains("extension") && out.contains("void main"), "{out:?}");
        assert_eq!(for_driver("#extension GL_ARB_gpu_shader5 : enable\n"), "#extension GL_ARB_gpu_shader5 : enable\n");
    }

    #[test]
    fn mesa_nvidia_and_plain_lines_parse() {
        let mesa = parse_log("0:12(5): error: `foo' undeclared\n0:3(1): warning: unused");
        assert_eq!(mesa, vec![LogError { at: Some((0, 12, 5)), text: "`foo' undeclared".into() }]);
        let nv = parse_log("0(7) : error C1008: undefined variable \"x\"");
        assert_eq!(nv[0].at, Some((0, 7, 0)));
        assert!(nv[0].text.contains("undefined variable"), "{:?}", nv[0]);
        let plain = parse_log("ERROR: 0:4: 'x' : undeclared identifier");
        assert_eq!(plain[0].at, Some((0, 4, 0)));
        assert_eq!(parse_log("error: linking failed")[0].at, None);
    }
}
