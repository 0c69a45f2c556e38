//! The scene sections of the manifest: `[camera]` (look-at camera and keyframes),
//! `[model]` (the model matrix) and `[render]` (frame defaults and pipeline state).
//!
//! Same habits as the rest of the walk: every problem is reported at its key or value and
//! the section still yields what could be read.

use std::ops::Range;

use toml::de::{DeTable, DeValue};

use super::{entries, key, Ctx, Val};
use crate::diag::Code;
use crate::manifest::{
    Blend, CameraDecl, CameraKey, Cull, DepthCompare, Ease, InstanceAttribute, InstanceSource, InstancesDecl, ModelDecl, RenderDecl,
    VerifyDecl, MAX_FRAMES, MAX_FRAME_SIDE, MAX_INSTANCES,
};

const CAMERA_KEYS: &[&str] = &["eye", "target", "up", "fov", "near", "far", "keys", "ease"];
const CAMERA_KEY_KEYS: &[&str] = &["time", "eye", "target"];
const MODEL_KEYS: &[&str] = &["translate", "rotate", "scale", "spin"];
const VERIFY_KEYS: &[&str] = &["tolerance", "max_differing"];
const RENDER_KEYS: &[&str] = &["size", "frames", "fps", "clear", "cull", "depth_test", "depth_write", "depth_compare", "blend"];
const INSTANCES_KEYS: &[&str] = &["count", "attributes"];
pub(super) const CULL_CHOICES: &[(&str, Cull)] = &[("none", Cull::None), ("back", Cull::Back), ("front", Cull::Front)];
pub(super) const BLEND_CHOICES: &[(&str, Blend)] =
    &[("none", Blend::None), ("alpha", Blend::Alpha), ("additive", Blend::Additive), ("premultiplied", Blend::Premultiplied)];
const INSTANCE_ATTRIBUTE_KEYS: &[&str] = &["values", "random", "seed", "sequence"];

impl Ctx<'_> {
    /// `n` finite numbers that fit in f32.
    pub(super) fn floats<const N: usize>(&mut self, v: &Val<'_>, what: &str) -> Option<[f32; N]> {
        let expected = format!("an array of {N} numbers");
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, what, &expected);
            return None;
        };
        if items.len() != N {
            self.report(
                Code::ManifestValue,
                v.span(),
                format!("{what} must be {expected}, found {}", items.len()),
                format!("expected {N} numbers"),
            );
            return None;
        }
        let mut out = [0.0f32; N];
        let mut ok = true;
        for (slot, item) in out.iter_mut().zip(items.iter()) {
            match self.float(item, what) {
                Some(x) => *slot = x,
                None => ok = false,
            }
        }
        ok.then_some(out)
    }

    /// A finite number that fits in f32.
    pub(super) fn float(&mut self, v: &Val<'_>, what: &str) -> Option<f32> {
        let x = self.number(v, what)?;
        if (x as f32).is_finite() {
            Some(x as f32)
        } else {
            self.report(Code::ManifestValue, v.span(), format!("{what} is too large"), "beyond the f32 range");
            None
        }
    }

    /// A number with `lo < x < hi`.
    fn float_in(&mut self, v: &Val<'_>, what: &str, lo: f32, hi: f32) -> Option<f32> {
        let x = self.float(v, what)?;
        if x > lo && x < hi {
            Some(x)
        } else {
            self.report(
                Code::ManifestValue,
                v.span(),
                format!("{what} must be greater than {lo} and less than {hi}"),
                format!("not in ({lo}, {hi})"),
            );
            None
        }
    }

    pub(super) fn boolean(&mut self, v: &Val<'_>, what: &str) -> Option<bool> {
        match v.get_ref() {
            DeValue::Boolean(b) => Some(*b),
            _ => {
                self.wrong_type(v, what, "`true` or `false`");
                None
            }
        }
    }

    pub(super) fn camera(&mut self, v: &Val<'_>) -> Option<CameraDecl> {
        let t = self.table(v, "`camera`")?;
        let mut cam = CameraDecl { span: v.span(), ..CameraDecl::default() };
        let mut ok = true;
        let mut near_span = None;
        for (k, v2) in entries(t) {
            let what = format!("`camera.{}`", key(k));
            let what = what.as_str();
            let done = match key(k) {
                "eye" => self.floats(v2, what).map(|x| cam.eye = x).is_some(),
                "target" => self.floats(v2, what).map(|x| cam.target = x).is_some(),
                "up" => self.floats(v2, what).map(|x| cam.up = x).is_some(),
                "fov" => self.float_in(v2, what, 0.0, 180.0).map(|x| cam.fov = x).is_some(),
                "near" => {
                    near_span = Some(v2.span());
                    self.float_in(v2, what, 0.0, f32::MAX).map(|x| cam.near = x).is_some()
                }
                "far" => self.float_in(v2, what, 0.0, f32::MAX).map(|x| cam.far = x).is_some(),
                "ease" => {
                    let choices = [("linear", Ease::Linear), ("smooth", Ease::Smooth)];
                    self.choice(v2, what, "easing", &choices).map(|e| cam.ease = e).is_some()
                }
                "keys" => match self.camera_keys(v2, &cam) {
                    Some(keys) => {
                        cam.keys = keys;
                        true
                    }
                    None => false,
                },
                other => {
                    self.unknown_key(other, k.span(), "in `[camera]`", CAMERA_KEYS);
                    false
                }
            };
            ok &= done;
        }
        if ok && cam.near >= cam.far {
            let span = near_span.unwrap_or_else(|| v.span());
            self.report(
                Code::ManifestValue,
                span,
                format!("`camera.near` ({}) must be less than `camera.far` ({})", cam.near, cam.far),
                "near plane beyond the far plane",
            );
            ok = false;
        }
        if ok && degenerate_view(cam.eye, cam.target, cam.up) {
            let d = self.report(
                Code::ManifestValue,
                v.span(),
                "the camera's `eye` equals its `target`, or `up` is parallel to the view direction".into(),
                "no view direction",
            );
            d.help = Some("move `eye` away from `target` and pick an `up` that is not along the view".into());
            ok = false;
        }
        ok.then_some(cam)
    }

    /// `keys = [{ time, eye, target? }, ...]` with strictly increasing times; a key without
    /// `target` looks at the camera's `target`.
    fn camera_keys(&mut self, v: &Val<'_>, cam: &CameraDecl) -> Option<Vec<CameraKey>> {
        let DeValue::Array(items) = v.get_ref() else {
            self.wrong_type(v, "`camera.keys`", "an array of tables (`[[camera.keys]]`)");
            return None;
        };
        if items.is_empty() {
            self.report(Code::ManifestMissing, v.span(), "`camera.keys` is empty".into(), "no keyframe");
            return None;
        }
        let mut keys: Vec<CameraKey> = Vec::new();
        let mut ok = true;
        let mut last: Option<(f64, Range<usize>)> = None;
        for item in items {
            let Some(t) = self.table(item, "a camera key") else {
                ok = false;
                continue;
            };
            match self.camera_key(item, t, cam, &mut last) {
                Some(k) => keys.push(k),
                None => ok = false,
            }
        }
        ok.then_some(keys)
    }

    fn camera_key(
        &mut self,
        item: &Val<'_>,
        t: &DeTable<'_>,
        cam: &CameraDecl,
        last: &mut Option<(f64, Range<usize>)>,
    ) -> Option<CameraKey> {
        let mut time = None;
        let mut eye = None;
        let mut target = cam.target;
        let mut ok = true;
        for (k, v) in entries(t) {
            let what = format!("`camera.keys.{}`", key(k));
            let what = what.as_str();
            ok &= match key(k) {
                "time" => match self.number(v, what) {
                    Some(x) if x >= 0.0 => {
                        time = Some((x, v.span()));
                        true
                    }
                    Some(_) => {
                        self.report(Code::ManifestValue, v.span(), format!("{what} must not be negative"), "negative time");
                        false
                    }
                    None => false,
                },
                "eye" => self.floats(v, what).map(|x| eye = Some(x)).is_some(),
                "target" => self.floats(v, what).map(|x| target = x).is_some(),
                other => {
                    self.unknown_key(other, k.span(), "in a camera key", CAMERA_KEY_KEYS);
                    false
                }
            };
        }
        let (Some((time, time_span)), Some(eye)) = (time, eye) else {
            if ok {
                let d = self.report(Code::ManifestMissing, item.span(), "a camera key needs `time` and `eye`".into(), "incomplete key");
                d.help = Some("write e.g. `{ time = 2.0, eye = [0, 1, 4] }`".into());
            }
            return None;
        };
        if let Some((prev, prev_span)) = last.clone() {
            if time <= prev {
                let file = self.file;
                let d = self.report(
                    Code::ManifestValue,
                    time_span.clone(),
                    format!("camera keys must have increasing times: {time} follows {prev}"),
                    "not after the previous key",
                );
                d.labels.push(crate::diag::Label { file, span: prev_span, message: "previous key".into() });
                ok = false;
            }
        }
        *last = Some((time, time_span));
        if ok && degenerate_view(eye, target, cam.up) {
            self.report(
                Code::ManifestValue,
                item.span(),
                "this key's `eye` equals its `target`, or `up` is parallel to the view direction".into(),
                "no view direction",
            );
            ok = false;
        }
        ok.then_some(CameraKey { time, eye, target })
    }

    pub(super) fn model(&mut self, v: &Val<'_>) -> Option<ModelDecl> {
        let t = self.table(v, "`model`")?;
        let mut m = ModelDecl::default();
        let mut ok = true;
        for (k, v2) in entries(t) {
            let what = format!("`model.{}`", key(k));
            let what = what.as_str();
            ok &= match key(k) {
                "translate" => self.floats(v2, what).map(|x| m.translate = x).is_some(),
                "rotate" => self.floats(v2, what).map(|x| m.rotate = x).is_some(),
                "spin" => self.floats(v2, what).map(|x| m.spin = x).is_some(),
                "scale" => {
                    let s = match v2.get_ref() {
                        DeValue::Array(_) => self.floats(v2, what),
                        _ => self.float(v2, what).map(|s| [s; 3]),
                    };
                    match s {
                        Some(s) if s.iter().all(|c| *c != 0.0) => {
                            m.scale = s;
                            true
                        }
                        Some(_) => {
                            self.report(Code::ManifestValue, v2.span(), format!("{what} must not be zero"), "flattens the mesh");
                            false
                        }
                        None => false,
                    }
                }
                other => {
                    self.unknown_key(other, k.span(), "in `[model]`", MODEL_KEYS);
                    false
                }
            };
        }
        ok.then_some(m)
    }

    pub(super) fn render(&mut self, v: &Val<'_>) -> Option<RenderDecl> {
        let t = self.table(v, "`render`")?;
        let mut r = RenderDecl::default();
        let mut ok = true;
        for (k, v2) in entries(t) {
            let what = format!("`render.{}`", key(k));
            let what = what.as_str();
            ok &= match key(k) {
                "size" => match v2.get_ref() {
                    DeValue::Array(items) if items.len() == 2 => {
                        let w = self.uint(&items[0], what, 1, MAX_FRAME_SIDE);
                        let h = self.uint(&items[1], what, 1, MAX_FRAME_SIDE);
                        match (w, h) {
                            (Some(w), Some(h)) => {
                                r.size = Some((w, h));
                                true
                            }
                            _ => false,
                        }
                    }
                    _ => {
                        self.wrong_type(v2, what, "`[width, height]`");
                        false
                    }
                },
                "frames" => self.uint(v2, what, 1, MAX_FRAMES).map(|n| r.frames = Some(n)).is_some(),
                "fps" => self.float_in(v2, what, 0.0, 100_000.0).map(|x| r.fps = Some(f64::from(x))).is_some(),
                "clear" => match v2.get_ref() {
                    DeValue::Array(items) if items.len() == 3 => {
                        self.floats::<3>(v2, what).map(|c| r.clear = [c[0], c[1], c[2], 1.0]).is_some()
                    }
                    _ => self.floats::<4>(v2, what).map(|c| r.clear = c).is_some(),
                },
                "cull" => self.choice(v2, what, "cull mode", CULL_CHOICES).map(|c| r.cull = c).is_some(),
                "depth_test" => self.boolean(v2, what).map(|b| r.depth_test = b).is_some(),
                "depth_write" => self.boolean(v2, what).map(|b| r.depth_write = b).is_some(),
                "depth_compare" => self.choice(v2, what, "depth comparison", DepthCompare::CHOICES).map(|c| r.depth_compare = c).is_some(),
                "blend" => self.choice(v2, what, "blend mode", BLEND_CHOICES).map(|b| r.blend = b).is_some(),
                other => {
                    self.unknown_key(other, k.span(), "in `[render]`", RENDER_KEYS);
                    false
                }
            };
        }
        ok.then_some(r)
    }
}

impl Ctx<'_> {
    /// `[verify]`: `tolerance` (0–255 per channel), `max_differing` (percent of pixels).
    pub(super) fn verify(&mut self, v: &Val<'_>) -> Option<VerifyDecl> {
        let t = self.table(v, "`verify`")?;
        let mut d = VerifyDecl::default();
        let mut ok = true;
        for (k, v2) in entries(t) {
            let what = format!("`verify.{}`", key(k));
            ok &= match key(k) {
                "tolerance" => self.uint(v2, &what, 0, 255).map(|n| d.tolerance = Some(n as u8)).is_some(),
                "max_differing" => self.float_in(v2, &what, 0.0, 100.0).map(|x| d.max_differing = Some(f64::from(x))).is_some(),
                other => {
                    self.unknown_key(other, k.span(), "in `[verify]`", VERIFY_KEYS);
                    false
                }
            };
        }
        ok.then_some(d)
    }

    pub(super) fn instances(&mut self, v: &Val<'_>) -> Option<InstancesDecl> {
        let t = self.table(v, "`instances`")?;
        let mut count = None;
        let mut attributes = Vec::new();
        let mut ok = true;
        let mut attribute_table = None;
        for (k, v2) in entries(t) {
            let what = format!("`instances.{}`", key(k));
            ok &= match key(k) {
                "count" => self.uint(v2, &what, 1, MAX_INSTANCES).map(|n| count = Some(n)).is_some(),
                "attributes" => {
                    attribute_table = Some(v2);
                    true
                }
                other => {
                    self.unknown_key(other, k.span(), "in `[instances]`", INSTANCES_KEYS);
                    false
                }
            };
        }
        let Some(count) = count else {
            if ok {
                let d = self.report(Code::ManifestMissing, v.span(), "`[instances]` needs `count`".into(), "no instance count");
                d.help = Some("add e.g. `count = 100`".into());
            }
            return None;
        };
        if let Some(at) = attribute_table {
            let at = self.table(at, "`instances.attributes`")?;
            for (k, v2) in entries(at) {
                match self.element_values("instances.attributes", key(k), k.span(), v2, Some(count)) {
                    Some(a) => attributes.push(a),
                    None => ok = false,
                }
            }
        }
        ok.then_some(InstancesDecl { span: v.span(), count, attributes })
    }

    /// `input = { values = [...] }`, `{ random = [lo, hi], seed = n }` or
    /// `{ sequence = [start, step] }` in `section`; `lo`, `hi`, `start`, `step` are numbers or
    /// vectors of 1–4 numbers. `count`: how many `values` an instance table needs (None: one
    /// per vertex, counted when the mesh is built).
    pub(super) fn element_values(
        &mut self,
        section: &str,
        input: &str,
        input_span: Range<usize>,
        v: &Val<'_>,
        count: Option<u32>,
    ) -> Option<InstanceAttribute> {
        let what = format!("`{section}.{input}`");
        let per = if count.is_some() { "instance" } else { "vertex" };
        if !super::is_ident(input) || input.starts_with("gl_") {
            self.report(Code::ManifestValue, input_span, format!("`{input}` is not a vertex shader input name"), "not a GLSL identifier");
            return None;
        }
        let t = self.table(v, &what)?;
        let mut source = None;
        let mut sources = 0;
        let mut seed = None;
        let mut components = 0;
        let mut ok = true;
        for (k, v2) in entries(t) {
            let w = format!("{what}.{}", key(k));
            match key(k) {
                "values" => {
                    sources += 1;
                    let DeValue::Array(items) = v2.get_ref() else {
                        self.wrong_type(v2, &w, &format!("an array with one value per {per}"));
                        ok = false;
                        continue;
                    };
                    if let Some(count) = count.filter(|n| items.len() != *n as usize) {
                        self.report(
                            Code::ManifestValue,
                            v2.span(),
                            format!("{w} has {} values for {count} instances", items.len()),
                            format!("expected {count} values"),
                        );
                        ok = false;
                        continue;
                    }
                    let mut values = Vec::with_capacity(items.len());
                    for item in items {
                        match self.vector(item, &w) {
                            Some((x, n)) => {
                                components = components.max(n);
                                values.push(x);
                            }
                            None => ok = false,
                        }
                    }
                    source = Some(InstanceSource::Values(values));
                }
                "random" | "sequence" => {
                    sources += 1;
                    let pair = match v2.get_ref() {
                        DeValue::Array(items) if items.len() == 2 => self.vector(&items[0], &w).zip(self.vector(&items[1], &w)),
                        _ => {
                            self.wrong_type(v2, &w, "`[a, b]` (numbers or vectors of up to 4 numbers)");
                            None
                        }
                    };
                    let Some(((a, na), (b, nb))) = pair else {
                        ok = false;
                        continue;
                    };
                    if na != nb {
                        self.report(
                            Code::ManifestValue,
                            v2.span(),
                            format!("{w}: both ends need the same number of components"),
                            "different sizes",
                        );
                        ok = false;
                        continue;
                    }
                    components = na;
                    source = Some(if key(k) == "random" {
                        InstanceSource::Random { lo: a, hi: b, seed: 0 }
                    } else {
                        InstanceSource::Sequence { start: a, step: b }
                    });
                }
                "seed" => match self.uint(v2, &w, 0, u32::MAX) {
                    Some(n) => seed = Some((n, k.span())),
                    None => ok = false,
                },
                other => {
                    self.unknown_key(other, k.span(), &format!("in {what}"), INSTANCE_ATTRIBUTE_KEYS);
                    ok = false;
                }
            }
        }
        if sources != 1 {
            if ok {
                let (code, msg) = if sources == 0 {
                    (Code::ManifestMissing, format!("{what} needs one of `values`, `random`, `sequence`"))
                } else {
                    (Code::ManifestConflict, format!("{what} has more than one of `values`, `random`, `sequence`"))
                };
                self.report(code, v.span(), msg, "one source needed");
            }
            return None;
        }
        match (&mut source, seed) {
            (Some(InstanceSource::Random { seed: s, .. }), Some((n, _))) => *s = n,
            (_, Some((_, span))) => {
                self.report(Code::ManifestConflict, span, format!("{what}: `seed` only applies to `random`"), "not random");
                ok = false;
            }
            _ => {}
        }
        let source = source?;
        ok.then_some(InstanceAttribute { input: input.to_string(), input_span, source, components })
    }

    /// A number or an array of 1–4 numbers: (padded value, component count).
    fn vector(&mut self, v: &Val<'_>, what: &str) -> Option<([f32; 4], usize)> {
        match v.get_ref() {
            DeValue::Array(items) if (1..=4).contains(&items.len()) => {
                let mut out = [0.0f32; 4];
                let mut ok = true;
                for (slot, item) in out.iter_mut().zip(items.iter()) {
                    match self.float(item, what) {
                        Some(x) => *slot = x,
                        None => ok = false,
                    }
                }
                ok.then_some((out, items.len()))
            }
            DeValue::Array(_) => {
                self.wrong_type(v, what, "a number or 1 to 4 numbers");
                None
            }
            _ => self.float(v, what).map(|x| ([x, 0.0, 0.0, 0.0], 1)),
        }
    }
}

/// True when `eye == target` or `up` is parallel to the view direction.
fn degenerate_view(eye: [f32; 3], target: [f32; 3], up: [f32; 3]) -> bool {
    let d = [target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]];
    let cross = [d[1] * up[2] - d[2] * up[1], d[2] * up[0] - d[0] * up[2], d[0] * up[1] - d[1] * up[0]];
    let len2 = |v: [f32; 3]| v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    len2(d) < 1e-12 || len2(cross) <= 1e-12 * len2(d) * len2(up).max(1e-30)
}
