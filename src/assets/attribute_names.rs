//! Which mesh attribute a vertex input's name suggests (`aPos`, `vertPosition`, `in_Normal`,
//! `aTexCoords`, `tangent`, `vColor`, …): the guess the renderer and the static analysis share.

use crate::manifest::MeshAttribute;

/// The attribute an input's name suggests.
pub fn by_name(name: &str) -> Option<MeshAttribute> {
    let n = name.to_ascii_lowercase();
    let has = |parts: &[&str]| parts.iter().any(|p| n.contains(p));
    // "vertex" contains "tex": look for uv words in what remains without it.
    let rest = n.replace("vertex", "");
    let rest_has = |parts: &[&str]| parts.iter().any(|p| rest.contains(p));
    if has(&["bitangent", "binormal", "bitan"]) {
        Some(MeshAttribute::Bitangent)
    } else if has(&["tangent", "tang"]) {
        Some(MeshAttribute::Tangent)
    } else if has(&["normal", "norm"]) {
        Some(MeshAttribute::Normal)
    } else if has(&["pos"]) {
        Some(MeshAttribute::Position)
    } else if rest_has(&["uv", "tex", "st0"]) || (has(&["coord"]) && !has(&["vert"])) || n == "st" || n.ends_with("_st") {
        // A bare "coord" is a texture coordinate; a vertex's coordinate (`VertexCoord`,
        // the emulator packs' position) is a position.
        Some(MeshAttribute::Uv)
    } else if has(&["color", "colour", "col"]) {
        Some(MeshAttribute::Color)
    } else if has(&["vertex", "vert", "point"]) || ["p", "a_p", "in_p", "v"].contains(&n.as_str()) {
        Some(MeshAttribute::Position)
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tutorial_names_map_to_attributes() {
        for (name, attr) in [
            ("aPos", MeshAttribute::Position),
            ("vertPosition", MeshAttribute::Position),
            ("vertexPosition_modelspace", MeshAttribute::Position),
            ("in_Position", MeshAttribute::Position),
            ("aNormal", MeshAttribute::Normal),
            ("vertexNormal", MeshAttribute::Normal),
            ("aTexCoords", MeshAttribute::Uv),
            ("vertTexCoords", MeshAttribute::Uv),
            ("a_uv", MeshAttribute::Uv),
            ("aTangent", MeshAttribute::Tangent),
            ("aBitangent", MeshAttribute::Bitangent),
            ("aColor", MeshAttribute::Color),
            ("vertexColour", MeshAttribute::Color),
            // The emulator packs' full-screen pass: the vertex's coordinate is its position.
            ("VertexCoord", MeshAttribute::Position),
            ("TexCoord", MeshAttribute::Uv),
            ("coord", MeshAttribute::Uv),
        ] {
            assert_eq!(by_name(name), Some(attr), "{name}");
        }
        assert_eq!(by_name("instanceMatrix"), None);
    }
}
