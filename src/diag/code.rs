//! Every diagnostic code effectc emits, in one table: [`Code`].
//!
//! A code is a letter for its severity (`E` error, `W` warning, `N` note) and four digits;
//! the hundreds group codes by the step that reports them (`E00xx` manifest and inputs,
//! `E01xx` front, `E02xx` link, `E03xx` translate, `E04xx` render, `E05xx` verify, `E07xx` stress and
//! hazards, `E08xx` bench). The table is sorted by the code string, so the derived order of
//! [`Code`] is the order of the strings. The README's *Diagnostics* table lists every code
//! (`tests/suite/codes.rs` checks it).

use std::fmt;
use std::str::FromStr;

use super::Severity;

/// Generates [`Code`] from `Variant => "CODE", "title"` rows: the enum, [`Code::ALL`],
/// [`Code::as_str`] and [`Code::title`].
macro_rules! codes {
    ($($variant:ident => $code:literal, $title:literal,)*) => {
        /// A stable diagnostic code; its letter gives the severity ([`Code::severity`]).
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
        pub enum Code {
            $(
                #[doc = concat!("`", $code, "`: ", $title, ".")]
                $variant,
            )*
        }

        impl Code {
            /// Every code, in table (= string) order.
            pub const ALL: &'static [Code] = &[$(Code::$variant,)*];

            /// The code as printed: `E0405`.
            pub const fn as_str(self) -> &'static str {
                match self {
                    $(Code::$variant => $code,)*
                }
            }

            /// What the code means, in one line.
            pub const fn title(self) -> &'static str {
                match self {
                    $(Code::$variant => $title,)*
                }
            }
        }
    };
}

codes! {
    // The manifest (`manifest`).
    ManifestSyntax => "E0001", "TOML syntax error in the manifest, or the manifest is not UTF-8",
    ManifestIo => "E0002", "the manifest could not be read",
    StageFileNotFound => "E0003", "a stage file named in the manifest does not exist",
    ManifestUnknownKey => "E0004", "unknown key in the manifest",
    ManifestType => "E0005", "manifest value has the wrong TOML type",
    ManifestValue => "E0006", "invalid manifest value",
    ManifestMissing => "E0007", "required manifest key or section missing",
    AssetNotFound => "E0008", "texture image or mesh file not found",
    ManifestConflict => "E0009", "manifest keys that exclude each other",
    // Inputs and outputs (`inputs`, `check`, `output`).
    InputIo => "E0010", "input missing or unreadable",
    UnknownStage => "E0011", "the stage of a file cannot be told from its name or its text",
    NotText => "E0012", "stage file is not text: a byte outside UTF-8 outside comments",
    InputRefused => "E0013", "input is not a regular file, or over the size limit",
    OutputIo => "E0014", "output cannot be written",
    ConfigInvalid => "E0015", "`effectc.toml` cannot be read or has an invalid setting",
    // The front: syntax, rewrite, naga (`front`).
    BadVersion => "E0101", "bad `#version` directive",
    SyntaxError => "E0102", "GLSL syntax error",
    NoMain => "E0103", "stage has no `main` function",
    IncludeUnresolved => "E0104", "an `#include` that cannot be read or includes itself",
    ReferenceRejects => "E0105", "the reference compiler (glslang) rejects the stage",
    OutsideRoot => "E0106", "a file outside the project root (an `#include`, a manifest path)",
    StageLimit => "E0107", "a stage beyond a limit effectc enforces (statement length, macro expansion)",
    NonConstantSamplerIndex => "E0110", "sampler array indexed with a non-constant expression",
    NonConstantFragDataIndex => "E0111", "`gl_FragData` indexed with a non-constant expression",
    RemovedInVersionStrict => "E0120", "construct removed from the declared version (`--strict`)",
    NagaParse => "E0150", "naga GLSL parse error",
    NagaValidation => "E0151", "naga validation error",
    NagaCrashed => "E0152", "naga crashed on the stage",
    // The link between stages, and manifest ↔ shader (`link`).
    InputBlockUnmatched => "E0201", "input block has no output block of the same block name",
    NoProducer => "E0202", "input read by the stage has no matching output",
    OtherStageName => "E0203", "name declared only in another stage",
    UniformTypeMismatch => "E0204", "uniform declared with different types in two stages",
    UniformBlockMismatch => "E0205", "uniform block declared differently in two stages",
    UniformStructMismatch => "E0206", "struct used by uniforms defined differently in two stages",
    VaryingTypeMismatch => "E0207", "output and input types differ",
    InterpolationMismatch => "E0208", "interpolation qualifiers differ",
    CentroidMismatch => "E0209", "centroid qualifiers differ",
    LocationMismatch => "E0210", "explicit locations differ",
    InterfaceBlockMismatch => "E0211", "interface blocks of the same name differ",
    GeometryInputNotArray => "E0212", "geometry input is not an array",
    EsOutputLocation => "E0213", "GLSL ES fragment output without a location beside others",
    GeometryLayout => "E0214", "geometry stage layout missing, conflicting or out of range",
    UniformUndeclared => "E0220", "manifest uniform is not declared by any stage",
    UniformDefaultType => "E0221", "manifest default does not fit the declared type",
    SemanticType => "E0222", "semantic does not fit the declared type",
    RangeNotNumeric => "E0223", "range on a uniform that is not a scalar number",
    TextureNoSampler => "E0224", "texture entry names no sampler uniform",
    UniformPathMismatch => "E0225", "manifest uniform path does not fit the declaration",
    TextureKindMismatch => "E0226", "texture kind does not match the sampler type",
    AttributeUnknown => "E0227", "mesh or instance attribute names no vertex input",
    AttributeConflict => "E0228", "vertex input fed twice or given too many components",
    ReferenceLinkFails => "E0230", "the reference compiler (glslang) refuses to link the program",
    PassUnknownTarget => "E0240", "pass or output names an undeclared target",
    PassReadBeforeWrite => "E0241", "pass reads a target no earlier pass writes",
    PassCycle => "E0242", "pass graph has a cycle or feedback loop",
    PassFormat => "E0243", "sampler or output does not fit the target's format",
    PassOutputCount => "E0244", "fragment outputs do not match the pass's targets",
    PassUnknownSampler => "E0245", "`samples` entry names no sampler of the pass",
    PassSizeMismatch => "E0246", "attachments of one pass have different sizes",
    // Translation (`back`).
    BindingConflict => "E0301", "stages bind different resources at one binding",
    SwitchFallThrough => "E0302", "`switch` case falls through, which WGSL cannot say",
    StageNotTranslatable => "E0303", "stage effectc cannot translate (a geometry or tessellation stage it cannot fold)",
    StageNotValid => "E0304", "stage did not validate, so the program cannot be translated",
    TranslateInternal => "E0305", "internal translation error",
    TargetCannotExpress => "E0306", "a target cannot express the program",
    // Rendering (`render`).
    NoAdapter => "E0401", "no usable GPU adapter",
    PipelineRejected => "E0402", "wgpu rejected the pipeline or a resource",
    FrameTimeout => "E0403", "a frame did not finish within the timeout",
    NonFinitePixels => "E0404", "NaN or Inf pixels in a float render",
    RenderLimit => "E0405", "request beyond the adapter's limits or the memory cap",
    AssetLoad => "E0406", "texture or mesh file could not be loaded",
    FrameFailed => "E0407", "a frame failed on the device",
    Unrenderable => "E0408", "the program cannot be rendered",
    // Verify (`verify`).
    NoGlDriver => "E0501", "no OpenGL driver to verify against",
    GlRejects => "E0502", "the OpenGL driver does not compile, link or draw the original program",
    FramesDiffer => "E0503", "the translation draws a different picture than the OpenGL driver",
    NotAGlProgram => "E0504", "Vulkan GLSL cannot be verified against an OpenGL driver",
    // Stress (`stress`).
    StressNonFinite => "E0701", "a stress case renders NaN or Inf pixels",
    HazardConfirmed => "E0703", "a hazard warning confirmed by a render (`stress --confirm`)",
    // Bench (`bench`).
    KnobUnknown => "E0801", "knob names no numeric uniform",
    NothingToBench => "E0802", "nothing to bench",
    KnobValues => "E0803", "`--knob` values that are not numbers",
    // Notes.
    PairedInFolder => "N0001", "a fragment stage paired with the one vertex stage of its folder",
    StageAlone => "N0002", "a stage checked alone: no link rule ran",
    StageFromText => "N0003", "a `.glsl` file's stage told from its text",
    PairedByHostCode => "N0004", "stages paired as the host code names them together",
    SyntaxAndInterfaceOnly => "N0101", "stage checked for syntax and interface only",
    NagaCannotTake => "N0102", "a legal construct naga cannot take: stage checked for syntax and interface only",
    ShadowBiasDropped => "N0103", "the bias or explicit gradients of a shadow lookup are dropped",
    PointCoordConstant => "N0104", "`gl_PointCoord` is (0.5, 0.5): WebGPU points are one pixel wide",
    LayerSelected => "N0105", "`gl_Layer`/`gl_ViewportIndex` select which primitives a draw keeps (WebGPU cannot route them)",
    ReferenceOnly => "N0106", "a stage the reference compiler accepts and effectc's own analysis cannot read: checked by glslang only",
    TexelBufferAsStorage => "N0107", "a buffer texture (`samplerBuffer`) or buffer image (`imageBuffer`) read from a storage buffer: WebGPU has no texel buffers",
    ClipDistancesDropped => "N0108", "`gl_ClipDistance`/`gl_CullDistance` computed, not passed: WebGPU clips and culls by neither",
    OptionalWebGpuFeature => "N0109", "the translation needs an optional WebGPU feature (`primitive-index`, `dual-source-blending`, `shader-f16`)",
    InterpolationApproximated => "N0110", "a fragment built-in WebGPU has no per-call form of, written as GL evaluates it on a single-sampled target (`interpolateAt*`, `gl_HelperInvocation`)",
    ImageFormatChosen => "N0111", "an image declared without a format gets the widest of its type (`rgba32f`, `rgba32i`, `rgba32ui`): WebGPU storage textures have one",
    IntegerTextureFetched => "N0112", "`texture`/`textureLod` of an integer sampler is written as `texelFetch` of the nearest texel, wrapping as GL_REPEAT (WebGPU samples float textures only)",
    RuntimeArrayBound => "N0113", "an array of textures, images or samplers sized at run time (bindless) is translated as 4 elements, one binding each",
    WideIntegersPaired => "N0114", "64-bit integers are held as two 32-bit words (`vec2<u32>`): WGSL has no 64-bit integers",
    SubgroupOfOne => "N0115", "subgroup operations are computed for subgroups of one invocation (`gl_SubgroupSize` 1): WGSL has no subgroups naga and tint both take",
    TessellationFolded => "N0116", "tessellation stages run inside the vertex stage, with a fixed number of vertices per patch (levels above the draw's cap are drawn at it)",
    AttachmentDropped => "N0241", "MRT attachment nobody reads is not attached",
    BufferShown => "N0401", "a compute program that stores to no image is shown as the words of the storage buffer it stores to",
    HazardAnalysisStopped => "N0701", "the static hazard analysis of a stage stopped at its work limit: its warnings are incomplete",
    // Warnings.
    StageExtension => "W0001", "stage file extension names another stage",
    DefaultOutOfRange => "W0002", "uniform default outside its declared range",
    UnusedGeneratorParam => "W0003", "texture generator parameter has no effect",
    SuppressionInvalid => "W0004", "suppression or config names an unknown code, an error, or is malformed",
    SuppressionUnused => "W0005", "suppression that silences nothing",
    NoProgramFound => "W0006", "a folder with no program in it: nothing was checked",
    RemovedInVersion => "W0120", "construct removed from the declared version",
    UniformInitializerIgnored => "W0130", "uniform initializer ignored",
    DoublesAsFloats => "W0131", "64-bit floats taken as 32-bit (WebGPU, WGSL, MSL and GLSL ES have no f64)",
    RewriteFailed => "W0190", "effectc could not rewrite an expression for naga",
    UnreadOutput => "W0201", "output never read by the next stage",
    UnusedInput => "W0202", "unread input with no producer",
    InterpolationDiffers => "W0203", "interpolation qualifiers differ (allowed since GLSL 4.30)",
    CentroidDiffers => "W0204", "centroid qualifiers differ (allowed since GLSL 4.30)",
    UniformNoDefault => "W0220", "uniform has no default in effect.toml",
    UniformUnread => "W0221", "uniform declared but never read",
    SamplerNoTexture => "W0222", "sampler has no [textures] entry",
    DefaultUnread => "W0223", "manifest default for a uniform no stage reads",
    PassUnused => "W0240", "pass whose results never reach the output (skipped)",
    AttributeGuessed => "W0401", "vertex input matched to a mesh attribute by a guess",
    AttributeZero => "W0402", "vertex input no mesh attribute fits reads zeros",
    UniformGuessed => "W0403", "uniform without a manifest value got a guessed one",
    TexturePlaceholder => "W0404", "sampler without a texture reads a placeholder",
    MeshGuessed => "W0405", "mesh chosen by effectc (no [mesh])",
    StressHiddenNonFinite => "W0702", "a stress case computes non-finite values its output hides",
    HazardDivision => "W0710", "division by a value that can be zero",
    HazardAsin => "W0711", "asin/acos of a value that can leave [-1, 1]",
    HazardSqrt => "W0712", "sqrt of a value that can be negative",
    HazardLog => "W0713", "log of a value that can be zero or negative",
    HazardPow => "W0714", "pow of a negative base, or 0 to a power <= 0",
    HazardNormalize => "W0715", "normalize of a vector that can be zero",
    HazardInverseSqrt => "W0716", "inversesqrt of a value that can be zero or negative",
    HazardTrig => "W0717", "sin/cos argument too large for f32",
    HazardSinHash => "W0718", "`fract(sin(x) * K)` hash depends on the GPU's sin precision",
    HazardCounterOverflow => "W0719", "loop counter can overflow",
    HazardNegativeRemainder => "W0720", "integer `%` of a value that can be negative (undefined in GLSL)",
    HazardShift => "W0721", "shift by an amount that can be negative or at least 32 (undefined in GLSL)",
    HazardAtan2 => "W0722", "`atan(y, x)` where both can be 0 (undefined in GLSL)",
}

impl Code {
    /// From the letter: `E` error, `W` warning, `N` note.
    pub const fn severity(self) -> Severity {
        match self.as_str().as_bytes()[0] {
            b'E' => Severity::Error,
            b'W' => Severity::Warning,
            _ => Severity::Note,
        }
    }
}

impl Code {
    /// The numeric hazard warnings of the static analysis (`W0710`–`W0722`).
    pub fn is_hazard(self) -> bool {
        matches!(
            self,
            Code::HazardDivision
                | Code::HazardAsin
                | Code::HazardSqrt
                | Code::HazardLog
                | Code::HazardPow
                | Code::HazardNormalize
                | Code::HazardInverseSqrt
                | Code::HazardTrig
                | Code::HazardSinHash
                | Code::HazardCounterOverflow
                | Code::HazardNegativeRemainder
                | Code::HazardShift
                | Code::HazardAtan2
        )
    }
}

impl fmt::Display for Code {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl serde::Serialize for Code {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.as_str())
    }
}

/// A string that is not one of [`Code::ALL`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownCode(pub String);

impl fmt::Display for UnknownCode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown diagnostic code `{}`", self.0)
    }
}

impl std::error::Error for UnknownCode {}

impl FromStr for Code {
    type Err = UnknownCode;
    fn from_str(s: &str) -> Result<Code, UnknownCode> {
        Code::ALL.iter().copied().find(|c| c.as_str() == s).ok_or_else(|| UnknownCode(s.to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn codes_are_well_formed_unique_and_sorted() {
        for c in Code::ALL {
            let s = c.as_str();
            let (letter, digits) = s.split_at(1);
            assert!(["E", "W", "N"].contains(&letter) && digits.len() == 4, "{c:?}: `{s}` is not [EWN][0-9]{{4}}");
            assert!(digits.bytes().all(|b| b.is_ascii_digit()), "{c:?}: `{s}` is not [EWN][0-9]{{4}}");
            assert!(!c.title().trim().is_empty(), "{c:?} has no title");
            assert_eq!(s.parse::<Code>(), Ok(*c));
        }
        for w in Code::ALL.windows(2) {
            assert!(w[0].as_str() < w[1].as_str(), "{} must come after {} (sorted, unique)", w[0], w[1]);
            // The derived order (declaration order) is the string order.
            assert!(w[0] < w[1]);
        }
        assert!("E9999".parse::<Code>().is_err());
    }

    #[test]
    fn severity_follows_the_letter() {
        assert_eq!(Code::RenderLimit.severity(), Severity::Error);
        assert_eq!(Code::RemovedInVersion.severity(), Severity::Warning);
        assert_eq!(Code::AttachmentDropped.severity(), Severity::Note);
        assert_eq!(Code::RenderLimit.to_string(), "E0405");
        assert_eq!(serde_json::to_string(&Code::PassUnused).unwrap(), "\"W0240\"");
    }
}
