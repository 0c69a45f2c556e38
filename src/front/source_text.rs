//! A GLSL file's bytes as the text the front reads.
//!
//! GLSL's character set is ASCII, and compilers read comments without looking at them:
//! glslang and Mesa take a file whose comments hold Latin-1 or Windows-1252 bytes
//! (`Iñigo Quílez` in a shader's header, written before editors saved UTF-8). Such a file
//! is read with each byte that is not UTF-8 standing as one `?`, so every offset (and every
//! span into the user's file) holds. A byte that is not UTF-8 outside a comment is no GLSL:
//! the file is refused there (E0012).

/// The text of `bytes`; else the offset of the first byte outside UTF-8 that is not in a
/// comment, and the text with every such byte as `?` (for pointing at it).
pub fn of(bytes: Vec<u8>) -> Result<String, (usize, String)> {
    let bytes = match String::from_utf8(bytes) {
        Ok(text) => return Ok(text),
        Err(e) => e.into_bytes(),
    };
    let mut text = String::with_capacity(bytes.len());
    let mut foreign = Vec::new();
    for chunk in bytes.utf8_chunks() {
        text.push_str(chunk.valid());
        for _ in chunk.invalid() {
            foreign.push(text.len());
            text.push('?');
        }
    }
    let code = crate::front::version::blank_comments(&text);
    match foreign.into_iter().find(|&at| code[at] == b'?') {
        Some(at) => Err((at, text)),
        None => Ok(text),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latin1_in_comments_is_read_byte_for_byte() {
        let bytes = b"// I\xf1igo Qu\xedlez\n/* \xe9t\xe9 */ void main() {}\n".to_vec();
        let text = of(bytes.clone()).unwrap();
        assert_eq!(text.len(), bytes.len(), "one byte stands for one byte");
        assert_eq!(text, "// I?igo Qu?lez\n/* ?t? */ void main() {}\n");
        assert_eq!(of(b"void main() {}\n".to_vec()).unwrap(), "void main() {}\n");
        assert_eq!(of("// Iñigo, in UTF-8\n".as_bytes().to_vec()).unwrap(), "// Iñigo, in UTF-8\n");
    }

    #[test]
    fn a_foreign_byte_outside_comments_is_refused_where_it_stands() {
        assert_eq!(of(b"// ok \xe9\nfloat \xe9t\xe9;\n".to_vec()), Err((14, "// ok ?\nfloat ?t?;\n".into())));
        assert_eq!(of(b"\x89PNG\r\n\x1a\n\0\0".to_vec()).map_err(|(at, _)| at), Err(0));
    }
}
