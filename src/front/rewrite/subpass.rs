//! Vulkan GLSL's subpass inputs (input attachments), which WebGPU and naga lack, read as
//! what they are: the texture of the attachment at the fragment's own texel. A
//! single-sampled `subpassInput` (`i`/`u` too) is declared `texture2D` (its
//! `input_attachment_index` goes with the layout items [`blocks`](super::blocks) drops),
//! and `subpassLoad(x)` is `texelFetch(x, ivec2(gl_FragCoord.xy), 0)`. A multisampled
//! `subpassInputMS` is left as written (naga reads no multisampled `texelFetch`).

use super::Ctx;
use crate::front::syntax::{word_occurrences, Storage};

/// The texture type read in place of a single-sampled subpass input type.
fn texture_type(subpass: &str) -> Option<&'static str> {
    match subpass {
        "subpassInput" => Some("texture2D"),
        "isubpassInput" => Some("itexture2D"),
        "usubpassInput" => Some("utexture2D"),
        _ => None,
    }
}

/// Whether the layout item named `item` of a uniform of type `ty` goes: the attachment
/// index of a subpass input read as a texture.
pub(super) fn drops_layout_item(ty: &str, item: &str) -> bool {
    item == "input_attachment_index" && texture_type(ty).is_some()
}

impl Ctx<'_> {
    /// The declarations' types and the `subpassLoad` calls of single-sampled inputs.
    pub(super) fn subpass_inputs(&mut self) {
        let s = self.s;
        let inputs: Vec<&str> = s
            .globals
            .iter()
            .filter(|g| g.storage == Storage::Uniform && texture_type(&g.ty.base).is_some())
            .map(|g| g.name.as_str())
            .collect();
        if inputs.is_empty() {
            return;
        }
        for g in s.globals.iter().filter(|g| g.storage == Storage::Uniform) {
            let Some(texture) = texture_type(&g.ty.base) else { continue };
            if let Some(at) = word_occurrences(&s.text, g.decl_span.start..g.name_span.start, &g.ty.base).into_iter().next() {
                self.edits.replace(at, texture);
            }
        }
        for c in s.calls.iter().filter(|c| c.name == "subpassLoad" && !c.from_macro && c.args.len() == 1) {
            if !c.first_arg_name.as_deref().is_some_and(|n| inputs.contains(&n)) {
                continue;
            }
            self.edits.replace(c.name_span.clone(), "texelFetch");
            self.edits.insert(c.span.end - 1, ", ivec2(gl_FragCoord.xy), 0");
        }
    }
}
