//! The bytes of one uniform value in a slot of the emitted module's uniform buffer: numbers
//! into the leading components of their slot, booleans as 0/1, matrices column by column
//! with the emitted column stride, arrays element by element, and a std140 two-row matrix
//! stored as `vec4` columns (`front::spirv_two_row_matrices`) given its matrix's numbers.

use naga::{Handle, Module, ScalarKind, Type, TypeInner};

use crate::manifest::UniformValue;

/// Writes one value into the slot of type `ty` at byte `offset` of `buf` (the layout rules
/// of [`pack`](super::pack)).
pub fn write_slot(module: &Module, ty: Handle<Type>, offset: u32, value: &UniformValue, buf: &mut [u8]) -> Result<(), String> {
    write_value(module, ty, offset as usize, value, buf)
}

fn scalar_bytes(kind: ScalarKind, v: &UniformValue) -> Result<[u8; 4], String> {
    let f = match v {
        UniformValue::Bool(b) => f64::from(u8::from(*b)),
        UniformValue::Int(i) => *i as f64,
        UniformValue::Float(f) => *f,
        UniformValue::List(_) => return Err("a list where a number belongs".into()),
    };
    Ok(match kind {
        ScalarKind::Float => (f as f32).to_le_bytes(),
        ScalarKind::Sint => (f as i32).to_le_bytes(),
        ScalarKind::Uint | ScalarKind::Bool => (f.max(0.0) as u32).to_le_bytes(),
        _ => return Err("unsupported scalar kind".into()),
    })
}

/// The scalar kind of an array of `n` (2 to 4) `vec4`s 16 bytes apart given `2n` numbers,
/// none of them a list: a two-row matrix's value for its stored columns.
fn two_row_matrix_columns(
    module: &Module,
    base: Handle<Type>,
    stride: u32,
    size: naga::ArraySize,
    value: &UniformValue,
) -> Option<ScalarKind> {
    let naga::ArraySize::Constant(n) = size else { return None };
    let TypeInner::Vector { size: naga::VectorSize::Quad, scalar } = module.types[base].inner else { return None };
    let UniformValue::List(items) = value else { return None };
    let flat = items.iter().all(|i| !matches!(i, UniformValue::List(_)));
    (stride == 16 && (2..=4).contains(&n.get()) && flat && items.len() == 2 * n.get() as usize).then_some(scalar.kind)
}

fn write_value(module: &Module, ty: Handle<Type>, offset: usize, value: &UniformValue, buf: &mut [u8]) -> Result<(), String> {
    let put = |buf: &mut [u8], at: usize, bytes: [u8; 4]| -> Result<(), String> {
        buf.get_mut(at..at + 4).ok_or("value runs past the block")?.copy_from_slice(&bytes);
        Ok(())
    };
    match &module.types[ty].inner {
        TypeInner::Scalar(s) => {
            let v = value.scalars().into_iter().next().ok_or("empty value")?;
            put(buf, offset, scalar_bytes(s.kind, v)?)
        }
        TypeInner::Vector { size, scalar } => {
            let scalars = value.scalars();
            if scalars.len() > *size as usize {
                return Err(format!("{} numbers for a {}-component slot", scalars.len(), *size as u8));
            }
            for (i, v) in scalars.into_iter().enumerate() {
                put(buf, offset + 4 * i, scalar_bytes(scalar.kind, v)?)?;
            }
            Ok(())
        }
        TypeInner::Matrix { columns, rows, scalar } => {
            let (c, r) = (*columns as usize, *rows as usize);
            let stride = if r == 2 { 8 } else { 16 };
            let scalars = value.scalars();
            if scalars.len() != c * r {
                return Err(format!("{} numbers for a {c}x{r} matrix", scalars.len()));
            }
            for (i, v) in scalars.into_iter().enumerate() {
                put(buf, offset + (i / r) * stride + 4 * (i % r), scalar_bytes(scalar.kind, v)?)?;
            }
            Ok(())
        }
        TypeInner::Array { base, stride, size } => {
            if let Some(columns) = two_row_matrix_columns(module, *base, *stride, *size, value) {
                // A `mat2`/`mat3x2`/`mat4x2` of a std140 block, which the route through
                // SPIR-V stores as `vec4` columns (`spirv_two_row_matrices`): the matrix's
                // numbers, column by column, each column in a `vec4`'s `.xy`.
                for (i, v) in value.scalars().into_iter().enumerate() {
                    put(buf, offset + (i / 2) * 16 + 4 * (i % 2), scalar_bytes(columns, v)?)?;
                }
                return Ok(());
            }
            let UniformValue::List(items) = value else { return Err("an array needs a list".into()) };
            if let naga::ArraySize::Constant(n) = size {
                if items.len() > n.get() as usize {
                    return Err(format!("{} elements for an array of {n}", items.len()));
                }
            }
            for (i, item) in items.iter().enumerate() {
                write_value(module, *base, offset + i * *stride as usize, item, buf)?;
            }
            Ok(())
        }
        _ => Err("a struct value must be given member by member (`name.member`)".into()),
    }
}
