//! Which mesh attribute a vertex input's name suggests (`aPos`, `vertPosition`, `in_Normal`,
//! `aTexCoords`, `tangent`, `vColor`, …): the guess the renderer and the static analysis share.

/// The attribute an input's name suggests.
pub fn by_name(name: &str) -> Option<&'static str> {
    let n = name.to_ascii_lowercase();
    let has = |parts: &[&str]| parts.iter().any(|p| n.contains(p));
    // "vertex" contains "tex": look for uv words in what remains without it.
    let rest = n.replace("vertex", "");
    let rest_has = |parts: &[&str]| parts.iter().any(|p| rest.contains(p));
    if has(&["bitangent", "binormal", "bitan"]) {
        Some("bitangent")
    } else if has(&["tangent", "tang"]) {
        Some("tangent")
    } else if has(&["normal", "norm"]) {
        Some("normal")
    } else if has(&["pos"]) {
        Some("position")
    } else if rest_has(&["uv", "tex", "coord", "st0"]) || n == "st" || n.ends_with("_st") {
        Some("uv")
    } else if has(&["color", "colour", "col"]) {
        Some("color")
    } else if has(&["vertex", "vert", "point"]) || ["p", "a_p", "in_p", "v"].contains(&n.as_str()) {
        Some("position")
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
            ("aPos", "position"),
            ("vertPosition", "position"),
            ("vertexPosition_modelspace", "position"),
            ("in_Position", "position"),
            ("aNormal", "normal"),
            ("vertexNormal", "normal"),
            ("aTexCoords", "uv"),
            ("vertTexCoords", "uv"),
            ("a_uv", "uv"),
            ("aTangent", "tangent"),
            ("aBitangent", "bitangent"),
            ("aColor", "color"),
            ("vertexColour", "color"),
        ] {
            assert_eq!(by_name(name), Some(attr), "{name}");
        }
        assert_eq!(by_name("instanceMatrix"), None);
    }
}
