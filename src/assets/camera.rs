//! The camera and the model transform at a point in time.
//!
//! Matrices follow OpenGL's conventions, as the GLSL being rendered expects: right-handed
//! view space looking down −z, a projection that maps depth to [−1, 1] (the translation maps
//! clip depth to WebGPU's range at the end of the vertex stage), column-major storage.
//! Camera keyframes are interpolated as seed 003 does (a lerp between the surrounding keys,
//! optionally smoothstepped); before the first key and after the last the camera holds still.

use glam::{EulerRot, Mat4, Quat, Vec3};

use crate::manifest::{CameraDecl, Ease, ModelDecl};

/// Where the camera is and what it sees at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct View {
    pub eye: Vec3,
    pub view: Mat4,
    pub projection: Mat4,
}

/// The camera at `time` seconds for a target of `aspect` = width / height.
pub fn view_at(cam: &CameraDecl, time: f64, aspect: f32) -> View {
    let (eye, target) = eye_and_target(cam, time);
    let up = Vec3::from(cam.up);
    let view = Mat4::look_at_rh(eye, target, up);
    let projection = Mat4::perspective_rh_gl(cam.fov.to_radians(), aspect.max(1e-6), cam.near, cam.far);
    View { eye, view, projection }
}

/// Eye and target after keyframe interpolation.
fn eye_and_target(cam: &CameraDecl, time: f64) -> (Vec3, Vec3) {
    let keys = &cam.keys;
    let (Some(first), Some(last)) = (keys.first(), keys.last()) else {
        return (cam.eye.into(), cam.target.into());
    };
    if time <= first.time {
        return (first.eye.into(), first.target.into());
    }
    if time >= last.time {
        return (last.eye.into(), last.target.into());
    }
    let next = keys.iter().position(|k| k.time > time).unwrap_or(keys.len() - 1);
    let (a, b) = (&keys[next - 1], &keys[next]);
    let mut s = ((time - a.time) / (b.time - a.time)) as f32;
    if cam.ease == Ease::Smooth {
        s = s * s * (3.0 - 2.0 * s);
    }
    let lerp = |p: [f32; 3], q: [f32; 3]| Vec3::from(p).lerp(Vec3::from(q), s);
    (lerp(a.eye, b.eye), lerp(a.target, b.target))
}

/// The model matrix at `time`: scale, then rotation (x, then y, then z; `rotate` plus
/// `spin` × time, in degrees), then translation.
pub fn model_at(m: &ModelDecl, time: f64) -> Mat4 {
    let angle = |i: usize| (f64::from(m.rotate[i]) + f64::from(m.spin[i]) * time).rem_euclid(360.0).to_radians() as f32;
    let rotation = Quat::from_euler(EulerRot::ZYX, angle(2), angle(1), angle(0));
    Mat4::from_scale_rotation_translation(m.scale.into(), rotation, m.translate.into())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::manifest::CameraKey;

    fn close(a: Vec3, b: Vec3) -> bool {
        (a - b).length() < 1e-5
    }

    #[test]
    fn the_default_camera_looks_at_the_origin_from_above_right_front() {
        let v = view_at(&CameraDecl::default(), 0.0, 1.0);
        assert!(close(v.eye, Vec3::new(1.8, 1.4, 2.6)));
        let origin = v.projection * v.view * glam::Vec4::new(0.0, 0.0, 0.0, 1.0);
        let ndc = origin.truncate() / origin.w;
        assert!(ndc.x.abs() < 1e-6 && ndc.y.abs() < 1e-6, "the target projects to the centre");
        assert!(ndc.z > -1.0 && ndc.z < 1.0, "GL depth range");
    }

    #[test]
    fn keyframes_interpolate_and_hold_at_the_ends() {
        let cam = CameraDecl {
            keys: vec![
                CameraKey { time: 1.0, eye: [0.0, 0.0, 2.0], target: [0.0; 3] },
                CameraKey { time: 3.0, eye: [0.0, 0.0, 6.0], target: [0.0; 3] },
            ],
            ..CameraDecl::default()
        };
        assert!(close(eye_and_target(&cam, 0.0).0, Vec3::new(0.0, 0.0, 2.0)));
        assert!(close(eye_and_target(&cam, 2.0).0, Vec3::new(0.0, 0.0, 4.0)));
        assert!(close(eye_and_target(&cam, 2.5).0, Vec3::new(0.0, 0.0, 5.0)));
        assert!(close(eye_and_target(&cam, 9.0).0, Vec3::new(0.0, 0.0, 6.0)));
        let smooth = CameraDecl { ease: Ease::Smooth, ..cam };
        let quarter = eye_and_target(&smooth, 1.5).0.z;
        assert!(quarter > 2.0 && quarter < 3.0, "smoothstep starts slower than linear: {quarter}");
    }

    #[test]
    fn the_model_spins_with_time() {
        let m = ModelDecl { spin: [0.0, 90.0, 0.0], ..ModelDecl::default() };
        let x = model_at(&m, 1.0).transform_point3(Vec3::X);
        assert!(close(x, Vec3::new(0.0, 0.0, -1.0)), "{x}");
        assert_eq!(model_at(&ModelDecl::default(), 5.0), Mat4::IDENTITY);
    }
}
