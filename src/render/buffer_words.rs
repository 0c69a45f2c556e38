//! The frame of a compute program that stores to buffers only: the first words of the
//! buffer it stores to, one 32-bit word per pixel in reading order (word 0 top left, rows of
//! the frame's width), each read as the scalar its place in the buffer's type holds
//! (`f32`, `i32`, `u32`) and shaded from black (the smallest finite value of its kind in the
//! frame) to white (the largest); NaN and infinities are magenta, pixels past the buffer's
//! end transparent.

use naga::{Handle, Module, ScalarKind, TypeInner};

/// How a word of a buffer is read.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum WordKind {
    Float,
    Sint,
    Uint,
}

/// The kind of every word of a buffer of type `ty`: its fixed part word by word, then the
/// pattern a trailing runtime-sized array repeats (element stride), if any.
#[derive(Debug, PartialEq)]
pub struct WordLayout {
    fixed: Vec<WordKind>,
    repeated: Vec<WordKind>,
}

impl WordLayout {
    pub fn of(module: &Module, ty: Handle<naga::Type>) -> WordLayout {
        let mut fixed = Vec::new();
        let mut repeated = Vec::new();
        let layout = |offset: u32, ty: Handle<naga::Type>, out: &mut Vec<WordKind>| fill(module, ty, offset, out);
        match &module.types[ty].inner {
            TypeInner::Struct { members, span } => {
                for m in members {
                    match module.types[m.ty].inner {
                        TypeInner::Array { base, size: naga::ArraySize::Dynamic, stride } => {
                            fixed.resize(m.offset as usize / 4, WordKind::Uint);
                            layout(0, base, &mut repeated);
                            repeated.resize((stride as usize / 4).max(1), WordKind::Uint);
                        }
                        _ => layout(m.offset, m.ty, &mut fixed),
                    }
                }
                if repeated.is_empty() {
                    fixed.resize((*span as usize).div_ceil(4), WordKind::Uint);
                }
            }
            _ => layout(0, ty, &mut fixed),
        }
        WordLayout { fixed, repeated }
    }

    /// The kind of word `i`.
    pub fn kind(&self, i: usize) -> WordKind {
        match self.fixed.get(i) {
            Some(k) => *k,
            None if !self.repeated.is_empty() => self.repeated[(i - self.fixed.len()) % self.repeated.len()],
            None => WordKind::Uint,
        }
    }
}

/// Writes the kind of each word `ty` covers at byte `offset` into `out` (grown as needed;
/// padding stays `Uint`).
fn fill(module: &Module, ty: Handle<naga::Type>, offset: u32, out: &mut Vec<WordKind>) {
    let mut put = |at: u32, kind: WordKind| {
        let i = at as usize / 4;
        if out.len() <= i {
            out.resize(i + 1, WordKind::Uint);
        }
        out[i] = kind;
    };
    let kind_of = |k: ScalarKind| match k {
        ScalarKind::Float | ScalarKind::AbstractFloat => WordKind::Float,
        ScalarKind::Sint | ScalarKind::AbstractInt => WordKind::Sint,
        ScalarKind::Uint | ScalarKind::Bool => WordKind::Uint,
    };
    match &module.types[ty].inner {
        TypeInner::Scalar(s) | TypeInner::Atomic(s) => {
            for w in 0..u32::from(s.width).div_ceil(4) {
                put(offset + 4 * w, kind_of(s.kind));
            }
        }
        TypeInner::Vector { size, scalar } => {
            for c in 0..*size as u32 {
                put(offset + c * u32::from(scalar.width), kind_of(scalar.kind));
            }
        }
        TypeInner::Matrix { columns, rows, scalar } => {
            let column = if *rows == naga::VectorSize::Bi { 2 } else { 4 } * u32::from(scalar.width);
            for c in 0..*columns as u32 {
                for r in 0..*rows as u32 {
                    put(offset + c * column + r * u32::from(scalar.width), kind_of(scalar.kind));
                }
            }
        }
        TypeInner::Array { base, size: naga::ArraySize::Constant(n), stride } => {
            for e in 0..n.get() {
                fill(module, *base, offset + e * stride, out);
            }
        }
        TypeInner::Struct { members, .. } => {
            for m in members {
                fill(module, m.ty, offset + m.offset, out);
            }
        }
        _ => {}
    }
}

/// The picture of `bytes` (a buffer's first words, little-endian) read by `layout`, `size`
/// pixels, RGBA in 0..1, top row first.
pub fn picture(bytes: &[u8], layout: &WordLayout, size: (u32, u32)) -> Vec<f32> {
    let pixels = (size.0 * size.1) as usize;
    let values: Vec<(WordKind, f64)> = bytes
        .chunks_exact(4)
        .take(pixels)
        .enumerate()
        .map(|(i, c)| {
            let word = u32::from_le_bytes([c[0], c[1], c[2], c[3]]);
            let kind = layout.kind(i);
            let value = match kind {
                WordKind::Float => f64::from(f32::from_bits(word)),
                WordKind::Sint => f64::from(word as i32),
                WordKind::Uint => f64::from(word),
            };
            (kind, value)
        })
        .collect();
    // Each kind shaded over its own range: a float position and an integer flag side by side.
    let range = |kind: WordKind| {
        let finite = values.iter().filter(|(k, v)| *k == kind && v.is_finite()).map(|(_, v)| *v);
        finite.fold(None, |r: Option<(f64, f64)>, v| Some(r.map_or((v, v), |(lo, hi)| (lo.min(v), hi.max(v)))))
    };
    let ranges = [WordKind::Float, WordKind::Sint, WordKind::Uint].map(|k| (k, range(k)));
    let mut out = vec![0.0f32; pixels * 4];
    for (i, (kind, v)) in values.iter().enumerate() {
        let px = &mut out[i * 4..i * 4 + 4];
        if !v.is_finite() {
            px.copy_from_slice(&[1.0, 0.0, 1.0, 1.0]);
            continue;
        }
        let (lo, hi) = ranges.iter().find(|(k, _)| k == kind).and_then(|(_, r)| *r).unwrap_or((0.0, 0.0));
        let shade = if hi > lo {
            ((v - lo) / (hi - lo)) as f32
        } else if *v == 0.0 {
            0.0
        } else {
            1.0
        };
        px.copy_from_slice(&[shade, shade, shade, 1.0]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn module_of(wgsl: &str) -> Module {
        naga::front::wgsl::parse_str(wgsl).expect("valid WGSL")
    }

    #[test]
    fn words_take_the_kind_of_their_place_in_the_buffer() {
        let m = module_of(
            "struct P { pos: vec3<f32>, flags: u32, id: i32 }\n\
             struct B { count: u32, items: array<P> }\n\
             @group(0) @binding(0) var<storage, read_write> b: B;\n\
             @compute @workgroup_size(1) fn main() { b.items[0].flags = 1u; }",
        );
        let (_, var) = m.global_variables.iter().next().expect("a global");
        let layout = WordLayout::of(&m, var.ty);
        // count, 3 words of padding before the 16-aligned array; P: vec3 + flags, id, 3 padding.
        let kinds: Vec<WordKind> = (0..12).map(|i| layout.kind(i)).collect();
        use WordKind::*;
        assert_eq!(kinds, [Uint, Uint, Uint, Uint, Float, Float, Float, Uint, Sint, Uint, Uint, Uint]);
        assert_eq!(layout.kind(12), Float, "the second element repeats the pattern");
    }

    #[test]
    fn each_kind_is_shaded_over_its_own_range_and_non_finite_floats_stand_out() {
        let layout = WordLayout { fixed: vec![WordKind::Float, WordKind::Float, WordKind::Float, WordKind::Uint], repeated: Vec::new() };
        let words: Vec<u32> = vec![0.0f32.to_bits(), 2.0f32.to_bits(), f32::NAN.to_bits(), 7];
        let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
        let px = picture(&bytes, &layout, (3, 2));
        assert_eq!(&px[0..4], &[0.0, 0.0, 0.0, 1.0]);
        assert_eq!(&px[4..8], &[1.0, 1.0, 1.0, 1.0]);
        assert_eq!(&px[8..12], &[1.0, 0.0, 1.0, 1.0], "NaN is magenta");
        assert_eq!(&px[12..16], &[1.0, 1.0, 1.0, 1.0], "a lone nonzero value of its kind is white");
        assert_eq!(&px[16..24], &[0.0; 8], "past the buffer: transparent");
    }
}
