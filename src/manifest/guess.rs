//! The semantic a uniform's name suggests (`iTime`, `u_time` → time; `projection` → the
//! projection matrix; `viewPos` → the camera position), when its type fits: the guess the
//! renderer makes for a uniform nobody gave a value, and the static analysis for bare
//! stage files.

use super::Semantic;

/// RetroArch's sizes, guessed as the frame's (a scene of one pass whose source is drawn at
/// the output size); as a `vec4` they hold the reciprocals too (`SourceSize.zw`).
const RETROARCH_SIZES: &[&str] = &["outputsize", "texturesize", "inputsize", "sourcesize", "originalsize", "finalviewportsize"];

/// One of RetroArch's size uniforms (`OutputSize`, `SourceSize`, …).
pub fn is_retroarch_size(name: &str) -> bool {
    RETROARCH_SIZES.contains(&normalised(name).as_str())
}

/// The semantic a uniform's name suggests, if its type fits it.
pub fn semantic_by_name(name: &str, shape: (u8, u8), is_float: bool) -> Option<Semantic> {
    let key = normalised(name);
    let candidates: &[(&[&str], Semantic)] = &[
        (&["time", "globaltime", "elapsed", "elapsedtime", "seconds", "timevar"], Semantic::Time),
        (&["deltatime", "timedelta", "dt", "frametime"], Semantic::DeltaTime),
        (&["frame", "framecount", "framenumber", "frameindex"], Semantic::Frame),
        (&["resolution", "screensize", "viewportsize", "viewport", "screenresolution"], Semantic::Resolution),
        (RETROARCH_SIZES, Semantic::Resolution),
        (&["mouse", "mousepos", "pointer"], Semantic::Mouse),
        (&["model", "modelmatrix", "world", "worldmatrix", "modelmat"], Semantic::Model),
        (&["view", "viewmatrix", "viewmat", "camera", "cameramatrix"], Semantic::View),
        (&["projection", "proj", "projectionmatrix", "projmatrix", "projmat", "perspective"], Semantic::Projection),
        (&["modelview", "mv", "modelviewmatrix", "mvmatrix"], Semantic::ModelView),
        (&["viewprojection", "viewproj", "vp", "viewprojectionmatrix", "projview", "pv"], Semantic::ViewProjection),
        (
            &["mvp", "modelviewprojection", "mvpmatrix", "modelviewprojectionmatrix", "pvm", "wvp", "worldviewprojection"],
            Semantic::ModelViewProjection,
        ),
        (&["normalmatrix", "normalmat", "nmatrix"], Semantic::NormalMatrix),
        (
            &["viewpos", "viewposition", "campos", "camerapos", "cameraposition", "eye", "eyepos", "eyeposition", "camerapositionworld"],
            Semantic::CameraPosition,
        ),
    ];
    let semantic = candidates.iter().find(|(names, _)| names.contains(&key.as_str()))?.1;
    let ty = type_name(shape, is_float)?;
    let retroarch = ty == "vec4" && RETROARCH_SIZES.contains(&key.as_str());
    (semantic.glsl_types().contains(&ty) || retroarch).then_some(semantic)
}

/// `u_Time`, `iTime`, `uTime`, `g_time`, `m_ProjectionMatrix` → `time`, `projectionmatrix`.
fn normalised(name: &str) -> String {
    let mut n = name;
    for prefix in ["u_", "g_", "m_", "a_"] {
        if let Some(rest) = n.strip_prefix(prefix) {
            n = rest;
        }
    }
    // Shadertoy's `iTime` and the common `uTime`: a lone lowercase prefix before a capital.
    let bytes = n.as_bytes();
    if bytes.len() > 2 && (bytes[0] == b'i' || bytes[0] == b'u') && bytes[1].is_ascii_uppercase() {
        n = &n[1..];
    }
    n.replace('_', "").to_ascii_lowercase()
}

/// The GLSL type name of a slot shape, for [`Semantic::glsl_types`].
fn type_name((columns, rows): (u8, u8), is_float: bool) -> Option<&'static str> {
    Some(match (columns, rows, is_float) {
        (1, 1, true) => "float",
        (1, 1, false) => "int",
        (1, 2, true) => "vec2",
        (1, 3, true) => "vec3",
        (1, 4, true) => "vec4",
        (3, 3, true) => "mat3",
        (4, 4, true) => "mat4",
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_types_must_both_fit() {
        assert_eq!(semantic_by_name("iTime", (1, 1), true), Some(Semantic::Time));
        assert_eq!(semantic_by_name("u_Resolution", (1, 2), true), Some(Semantic::Resolution));
        assert_eq!(semantic_by_name("time", (1, 3), true), None);
        assert_eq!(semantic_by_name("radius", (1, 1), true), None);
    }
}
