//! A geometry stage's primitive layout: what it takes (`layout(triangles) in;`), what it
//! emits (`layout(triangle_strip, max_vertices = 3) out;`) and how often it runs per input
//! primitive (`layout(invocations = 4) in;`), read from its default-qualifier declarations.

use std::ops::Range;

use crate::front::syntax::{StageSyntax, Storage};

/// The primitive a geometry stage takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum InputPrimitive {
    Points,
    Lines,
    LinesAdjacency,
    Triangles,
    TrianglesAdjacency,
}

impl InputPrimitive {
    /// The layout name.
    pub const fn name(self) -> &'static str {
        match self {
            InputPrimitive::Points => "points",
            InputPrimitive::Lines => "lines",
            InputPrimitive::LinesAdjacency => "lines_adjacency",
            InputPrimitive::Triangles => "triangles",
            InputPrimitive::TrianglesAdjacency => "triangles_adjacency",
        }
    }
    /// Vertices per input primitive (the length of `gl_in[]`).
    pub const fn vertices(self) -> u32 {
        match self {
            InputPrimitive::Points => 1,
            InputPrimitive::Lines => 2,
            InputPrimitive::LinesAdjacency => 4,
            InputPrimitive::Triangles => 3,
            InputPrimitive::TrianglesAdjacency => 6,
        }
    }
    /// The list topology a stage before it must make (`point-list`, `line-list`,
    /// `triangle-list`).
    pub const fn list_topology(self) -> &'static str {
        match self {
            InputPrimitive::Points => "point-list",
            InputPrimitive::Lines | InputPrimitive::LinesAdjacency => "line-list",
            InputPrimitive::Triangles | InputPrimitive::TrianglesAdjacency => "triangle-list",
        }
    }
    fn from_name(name: &str) -> Option<InputPrimitive> {
        [
            InputPrimitive::Points,
            InputPrimitive::Lines,
            InputPrimitive::LinesAdjacency,
            InputPrimitive::Triangles,
            InputPrimitive::TrianglesAdjacency,
        ]
        .into_iter()
        .find(|p| p.name() == name)
    }
}

/// The primitive a geometry stage emits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OutputPrimitive {
    Points,
    LineStrip,
    TriangleStrip,
}

impl OutputPrimitive {
    /// The layout name.
    pub const fn name(self) -> &'static str {
        match self {
            OutputPrimitive::Points => "points",
            OutputPrimitive::LineStrip => "line_strip",
            OutputPrimitive::TriangleStrip => "triangle_strip",
        }
    }
    /// Vertices of one primitive of the list the strips become (1, 2 or 3).
    pub const fn list_vertices(self) -> u32 {
        match self {
            OutputPrimitive::Points => 1,
            OutputPrimitive::LineStrip => 2,
            OutputPrimitive::TriangleStrip => 3,
        }
    }
    /// At most how many list primitives `max_vertices` emitted vertices make: a strip of n
    /// vertices makes n − 2 triangles or n − 1 lines; points are one each.
    pub const fn max_primitives(self, max_vertices: u32) -> u32 {
        match self {
            OutputPrimitive::Points => max_vertices,
            OutputPrimitive::LineStrip => max_vertices.saturating_sub(1),
            OutputPrimitive::TriangleStrip => max_vertices.saturating_sub(2),
        }
    }
    fn from_name(name: &str) -> Option<OutputPrimitive> {
        [OutputPrimitive::Points, OutputPrimitive::LineStrip, OutputPrimitive::TriangleStrip].into_iter().find(|p| p.name() == name)
    }
}

/// A geometry stage's layout.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GeometryLayout {
    pub input: InputPrimitive,
    pub output: OutputPrimitive,
    pub max_vertices: u32,
    /// Runs per input primitive (`gl_InvocationID` counts them); 1 unless declared.
    pub invocations: u32,
}

impl GeometryLayout {
    /// Vertices the folded draw spends on one input primitive: one per corner of every list
    /// primitive the strips can make, for every invocation.
    pub const fn slots_per_primitive(&self) -> u32 {
        self.output.max_primitives(self.max_vertices) * self.output.list_vertices() * self.invocations
    }
}

/// What is missing or wrong in a geometry stage's layout, and where (the declaration, when
/// there is one).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LayoutProblem {
    pub message: String,
    pub span: Option<Range<usize>>,
    /// The declaration to add, for a missing item.
    pub example: Option<&'static str>,
    /// The layout is legal GLSL, but a count is an expression effectc cannot evaluate: only
    /// the lowering cannot proceed (the link rules have nothing to report).
    pub unreadable: bool,
}

/// Reads the layout of geometry stage `s`. Repeated declarations must agree (GLSL).
pub fn geometry_layout(s: &StageSyntax) -> Result<GeometryLayout, LayoutProblem> {
    let mut input: Option<(InputPrimitive, Range<usize>)> = None;
    let mut output: Option<(OutputPrimitive, Range<usize>)> = None;
    let mut max_vertices: Option<(u32, Range<usize>)> = None;
    let mut invocations: Option<(u32, Range<usize>)> = None;
    // A count given as an expression effectc cannot evaluate: legal, but not lowerable.
    let mut unreadable: Option<LayoutProblem> = None;
    for d in &s.defaults {
        let span = d.span.clone();
        for (name, value) in &d.layout {
            let problem = |message: String| LayoutProblem { message, span: Some(span.clone()), example: None, unreadable: false };
            match (d.storage, name.as_str(), value) {
                (_, "max_vertices" | "invocations", None) => {
                    let message = format!("`{name}` is an expression effectc cannot evaluate (write the number)");
                    unreadable.get_or_insert(LayoutProblem { unreadable: true, ..problem(message) });
                }
                (Some(Storage::In), "invocations", Some(n)) => {
                    set(&mut invocations, positive(*n, "invocations", &problem)?, &span, "invocations")?
                }
                (Some(Storage::In), other, None) => match InputPrimitive::from_name(other) {
                    Some(p) => set(&mut input, p, &span, "input primitive")?,
                    None => continue,
                },
                (Some(Storage::Out), "max_vertices", Some(n)) => {
                    set(&mut max_vertices, non_negative(*n, "max_vertices", &problem)?, &span, "max_vertices")?
                }
                (Some(Storage::Out), other, None) => match OutputPrimitive::from_name(other) {
                    Some(p) => set(&mut output, p, &span, "output primitive")?,
                    None => continue,
                },
                _ => continue,
            }
        }
    }
    let missing = |what: &str, example: &'static str| LayoutProblem {
        message: format!("the geometry stage declares no {what}"),
        span: None,
        example: Some(example),
        unreadable: false,
    };
    let input = input.ok_or_else(|| missing("input primitive", "layout(triangles) in;"))?.0;
    let output = output.ok_or_else(|| missing("output primitive", "layout(triangle_strip, max_vertices = 3) out;"))?.0;
    if let Some(problem) = unreadable {
        return Err(problem);
    }
    let max_vertices = max_vertices.ok_or_else(|| missing("`max_vertices`", "layout(triangle_strip, max_vertices = 3) out;"))?.0;
    Ok(GeometryLayout { input, output, max_vertices, invocations: invocations.map_or(1, |(n, _)| n) })
}

/// Records `value` for a layout item, or the conflict with an earlier declaration.
fn set<T: PartialEq + Copy>(slot: &mut Option<(T, Range<usize>)>, value: T, span: &Range<usize>, what: &str) -> Result<(), LayoutProblem> {
    match slot {
        Some((earlier, _)) if *earlier != value => Err(LayoutProblem {
            message: format!("the {what} is declared twice with different values"),
            span: Some(span.clone()),
            example: None,
            unreadable: false,
        }),
        _ => {
            *slot = Some((value, span.clone()));
            Ok(())
        }
    }
}

/// `max_vertices`, which may be 0 (a stage that emits nothing; glslang and GL accept it).
fn non_negative(n: i64, name: &str, problem: &dyn Fn(String) -> LayoutProblem) -> Result<u32, LayoutProblem> {
    u32::try_from(n).ok().ok_or_else(|| problem(format!("`{name} = {n}` must not be negative")))
}

/// A layout count that must be at least 1.
fn positive(n: i64, name: &str, problem: &dyn Fn(String) -> LayoutProblem) -> Result<u32, LayoutProblem> {
    u32::try_from(n).ok().filter(|n| *n >= 1).ok_or_else(|| problem(format!("`{name} = {n}` must be at least 1")))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::FileId;
    use crate::stage::StageKind;

    fn layout(src: &str) -> Result<GeometryLayout, LayoutProblem> {
        let s = crate::front::syntax::analyse(FileId(0), src, StageKind::Geometry, crate::config::TargetEnv::Auto).expect("parses");
        geometry_layout(&s)
    }

    const BODY: &str = "void main() { gl_Position = gl_in[0].gl_Position; EmitVertex(); EndPrimitive(); }\n";

    #[test]
    fn the_seed_explode_layout_is_read() {
        let l =
            layout(&format!("#version 420 core\nlayout (triangles) in;\nlayout (triangle_strip, max_vertices = 3) out;\n{BODY}")).unwrap();
        assert_eq!(
            l,
            GeometryLayout { input: InputPrimitive::Triangles, output: OutputPrimitive::TriangleStrip, max_vertices: 3, invocations: 1 }
        );
        assert_eq!(l.slots_per_primitive(), 3, "one triangle");
    }

    #[test]
    fn slots_follow_the_output_primitive_and_invocations() {
        let quads = layout(&format!("#version 330\nlayout(points) in;\nlayout(triangle_strip, max_vertices = 4) out;\n{BODY}")).unwrap();
        assert_eq!((quads.input.vertices(), quads.slots_per_primitive()), (1, 6), "a quad is two triangles");
        let lines = layout(&format!("#version 330\nlayout(lines) in;\nlayout(line_strip, max_vertices = 5) out;\n{BODY}")).unwrap();
        assert_eq!((lines.input.vertices(), lines.slots_per_primitive()), (2, 8), "four segments");
        let layered =
            layout(&format!("#version 400\nlayout(triangles, invocations = 6) in;\nlayout(points, max_vertices = 3) out;\n{BODY}"))
                .unwrap();
        assert_eq!((layered.invocations, layered.slots_per_primitive()), (6, 18));
    }

    #[test]
    fn missing_and_conflicting_layouts_are_problems() {
        let no_input = layout(&format!("#version 330\nlayout(triangle_strip, max_vertices = 3) out;\n{BODY}")).unwrap_err();
        assert!(no_input.message.contains("no input primitive") && no_input.span.is_none(), "{no_input:?}");
        let no_max = layout(&format!("#version 330\nlayout(triangles) in;\nlayout(triangle_strip) out;\n{BODY}")).unwrap_err();
        assert!(no_max.message.contains("max_vertices"), "{no_max:?}");
        let twice =
            layout(&format!("#version 330\nlayout(triangles) in;\nlayout(lines) in;\nlayout(points, max_vertices = 1) out;\n{BODY}"))
                .unwrap_err();
        assert!(twice.message.contains("declared twice") && twice.span.is_some(), "{twice:?}");
        // A count effectc cannot evaluate is legal GLSL: marked so link leaves it alone.
        let expr =
            layout(&format!("#version 440\nlayout(triangles) in;\nlayout(points, max_vertices = int(4.0)) out;\n{BODY}")).unwrap_err();
        assert!(expr.unreadable && expr.message.contains("cannot evaluate"), "{expr:?}");
        assert!(!no_max.unreadable && !twice.unreadable, "missing and conflicting items are link errors");
        // `max_vertices = 0` is legal (a stage that emits nothing); a negative count is not,
        // and neither is zero invocations.
        let zero = layout(&format!("#version 330\nlayout(triangles) in;\nlayout(points, max_vertices = 0) out;\n{BODY}")).unwrap();
        assert_eq!(zero.max_vertices, 0);
        let negative = layout(&format!("#version 330\nlayout(triangles) in;\nlayout(points, max_vertices = -1) out;\n{BODY}")).unwrap_err();
        assert!(negative.message.contains("must not be negative"), "{negative:?}");
        let none = layout(&format!("#version 400\nlayout(triangles, invocations = 0) in;\nlayout(points, max_vertices = 1) out;\n{BODY}"))
            .unwrap_err();
        assert!(none.message.contains("at least 1"), "{none:?}");
    }
}
