//! Values the renderer supplies every frame (`semantic = "time"`, matrices, resolution, …)
//! and the guesses made for uniforms nobody gave a value.
//!
//! A guess is made only for a uniform the manifest does not mention (every uniform of a
//! bare stage file): by name and type (`iTime`, `u_time` → time; `projection` → the
//! projection matrix; `viewPos` → camera position; …); failing that, matrices get the
//! identity, colours (`…color…`, `diffuse`, `specular`) white, `ambient` dark grey,
//! `shininess` 32, light positions a light above-right-front, and everything else zero.
//! Members of uniform structs (`material.diffuse`) are guessed by their own names. The renderer reports each guess as a warning.

use glam::{Mat3, Mat4, Vec3};

use crate::assets::camera::View;
use crate::manifest::{Semantic, UniformValue};

/// Everything a semantic can depend on, for one frame.
#[derive(Debug, Clone, Copy)]
pub struct FrameState {
    pub index: u32,
    pub time: f64,
    pub delta: f64,
    pub size: (u32, u32),
    pub view: View,
    pub model: Mat4,
}

/// The shape of the slot a value goes into: `(columns, rows)`; vectors are `(1, n)`,
/// scalars `(1, 1)`.
pub type Shape = (u8, u8);

/// The value of `semantic` this frame, shaped for the slot.
pub fn value(semantic: Semantic, f: &FrameState, shape: Shape) -> UniformValue {
    let (w, h) = (f.size.0 as f64, f.size.1 as f64);
    match semantic {
        Semantic::Time => number(f.time),
        Semantic::DeltaTime => number(f.delta),
        Semantic::Frame => UniformValue::Int(i64::from(f.index)),
        // `vec3`: Shadertoy's `iResolution` (z = 1); `vec4`: RetroArch's sizes (w, h, 1/w, 1/h).
        Semantic::Resolution if shape.1 == 4 => floats(&[w, h, 1.0 / w, 1.0 / h]),
        Semantic::Resolution => floats(&[w, h, 1.0][..shape.1.clamp(1, 3) as usize]),
        // No pointer in headless rendering: the centre of the frame, not clicked.
        Semantic::Mouse => floats(&[w / 2.0, h / 2.0, 0.0, 0.0][..shape.1.clamp(1, 4) as usize]),
        Semantic::CameraPosition => {
            let e = f.view.eye;
            floats(&[e.x as f64, e.y as f64, e.z as f64, 1.0][..shape.1.clamp(1, 4) as usize])
        }
        Semantic::Model => matrix(f.model, shape),
        Semantic::View => matrix(f.view.view, shape),
        Semantic::Projection => matrix(f.view.projection, shape),
        Semantic::ModelView => matrix(f.view.view * f.model, shape),
        Semantic::ViewProjection => matrix(f.view.projection * f.view.view, shape),
        Semantic::ModelViewProjection => matrix(f.view.projection * f.view.view * f.model, shape),
        Semantic::NormalMatrix => {
            let n = Mat3::from_mat4(f.view.view * f.model).inverse().transpose();
            matrix(Mat4::from_mat3(n), shape)
        }
    }
}

fn number(x: f64) -> UniformValue {
    UniformValue::Float(x)
}

pub(crate) fn floats(xs: &[f64]) -> UniformValue {
    UniformValue::List(xs.iter().map(|x| UniformValue::Float(*x)).collect())
}

/// A matrix as `columns` lists of `rows` numbers (the upper-left part of `m`).
pub fn matrix(m: Mat4, (columns, rows): Shape) -> UniformValue {
    let cols = m.to_cols_array_2d();
    UniformValue::List(
        cols.iter()
            .take(columns as usize)
            .map(|c| floats(&c.iter().take(rows as usize).map(|x| f64::from(*x)).collect::<Vec<_>>()))
            .collect(),
    )
}

/// What a uniform without a manifest entry gets.
#[derive(Debug, Clone, PartialEq)]
pub enum Guess {
    /// Bound to a semantic because of its name.
    Semantic(Semantic),
    /// A constant chosen by name or type (identity matrix, white, a light position, zero).
    Constant(UniformValue, &'static str),
}

/// The guess for a uniform named `name` whose slot has `shape` and scalar type
/// `is_float` (integers and booleans never take a semantic other than `frame`).
pub fn guess(name: &str, shape: Shape, is_float: bool) -> Guess {
    if let Some(s) = crate::manifest::guess::semantic_by_name(name, shape, is_float) {
        return Guess::Semantic(s);
    }
    let lower = name.to_ascii_lowercase();
    let (columns, rows) = shape;
    if columns > 1 {
        return Guess::Constant(matrix(Mat4::IDENTITY, shape), "the identity matrix");
    }
    if is_float && rows >= 3 && lower.contains("ambient") {
        return Guess::Constant(floats(&[0.2, 0.2, 0.2, 1.0][..rows as usize]), "dark grey (0.2)");
    }
    if is_float && rows >= 3 && ["color", "colour", "diffuse", "specular", "albedo"].iter().any(|w| lower.contains(w)) {
        return Guess::Constant(floats(&[1.0; 4][..rows as usize]), "white");
    }
    // RetroArch plays forward: its `FrameDirection` is 1 (-1 while rewinding).
    if rows == 1 && columns == 1 && lower == "framedirection" {
        return Guess::Constant(if is_float { UniformValue::Float(1.0) } else { UniformValue::Int(1) }, "1, RetroArch's forward play");
    }
    if is_float && rows == 1 && (lower.contains("shininess") || lower.contains("specularpower")) {
        return Guess::Constant(UniformValue::Float(32.0), "32");
    }
    if is_float && rows >= 3 && lower.contains("light") && (lower.contains("pos") || lower.contains("dir")) {
        let light = Vec3::new(1.2, 1.0, 2.0);
        return Guess::Constant(
            floats(&[light.x as f64, light.y as f64, light.z as f64, 1.0][..rows as usize]),
            "a light above, right and in front of the origin",
        );
    }
    Guess::Constant(UniformValue::Int(0), "zero")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn common_names_are_recognised_with_their_types() {
        assert_eq!(guess("iTime", (1, 1), true), Guess::Semantic(Semantic::Time));
        assert_eq!(guess("u_time", (1, 1), true), Guess::Semantic(Semantic::Time));
        assert_eq!(guess("iResolution", (1, 3), true), Guess::Semantic(Semantic::Resolution));
        assert_eq!(guess("projection", (4, 4), true), Guess::Semantic(Semantic::Projection));
        assert_eq!(guess("MVP", (4, 4), true), Guess::Semantic(Semantic::ModelViewProjection));
        assert_eq!(guess("viewPos", (1, 3), true), Guess::Semantic(Semantic::CameraPosition));
        assert_eq!(guess("normalMatrix", (3, 3), true), Guess::Semantic(Semantic::NormalMatrix));
        // RetroArch's sizes: the frame's, a `vec4` too (only for them: `iResolution` is no vec4).
        assert_eq!(guess("SourceSize", (1, 4), true), Guess::Semantic(Semantic::Resolution));
        assert_eq!(guess("OutputSize", (1, 2), true), Guess::Semantic(Semantic::Resolution));
        assert!(matches!(guess("iResolution", (1, 4), true), Guess::Constant(..)));
        assert!(crate::manifest::guess::is_retroarch_size("TextureSize") && !crate::manifest::guess::is_retroarch_size("iResolution"));
        // The name fits but the type does not: no semantic.
        assert!(matches!(guess("time", (1, 3), true), Guess::Constant(..)));
        assert!(matches!(guess("model", (1, 4), true), Guess::Constant(..)));
    }

    #[test]
    fn other_uniforms_get_identity_white_a_light_or_zero() {
        assert_eq!(guess("transform", (4, 4), true), Guess::Constant(matrix(Mat4::IDENTITY, (4, 4)), "the identity matrix"));
        assert!(matches!(guess("objectColor", (1, 3), true), Guess::Constant(_, "white")));
        assert!(matches!(guess("lightPos", (1, 3), true), Guess::Constant(_, w) if w.contains("light")));
        assert_eq!(guess("material.shininess", (1, 1), true), Guess::Constant(UniformValue::Float(32.0), "32"));
        assert!(matches!(guess("light.ambient", (1, 3), true), Guess::Constant(_, w) if w.contains("grey")));
        assert!(matches!(guess("light.position", (1, 3), true), Guess::Constant(_, w) if w.contains("light")));
        assert_eq!(guess("radius", (1, 1), true), Guess::Constant(UniformValue::Int(0), "zero"));
        assert_eq!(guess("FrameDirection", (1, 1), false), Guess::Constant(UniformValue::Int(1), "1, RetroArch's forward play"));
    }

    #[test]
    fn semantic_values_follow_the_slot_shape() {
        let view = crate::assets::camera::view_at(&Default::default(), 0.0, 2.0);
        let f = FrameState { index: 3, time: 1.5, delta: 0.5, size: (200, 100), view, model: Mat4::IDENTITY };
        assert_eq!(value(Semantic::Time, &f, (1, 1)), UniformValue::Float(1.5));
        assert_eq!(value(Semantic::Frame, &f, (1, 1)), UniformValue::Int(3));
        assert_eq!(value(Semantic::Resolution, &f, (1, 3)).dims(), vec![3]);
        assert_eq!(value(Semantic::Resolution, &f, (1, 2)).scalars()[0], &UniformValue::Float(200.0));
        assert_eq!(value(Semantic::Resolution, &f, (1, 4)), floats(&[200.0, 100.0, 0.005, 0.01]), "w, h, 1/w, 1/h");
        assert_eq!(value(Semantic::NormalMatrix, &f, (3, 3)).dims(), vec![3, 3]);
        assert_eq!(value(Semantic::Model, &f, (4, 4)), matrix(Mat4::IDENTITY, (4, 4)));
    }
}
