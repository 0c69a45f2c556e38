//! The pass graph of a multi-pass effect: which pass feeds which, what reaches the output,
//! and which targets can share a texture.
//!
//! Passes run in manifest order, like a GL render loop. A pass *reads* the targets it
//! samples, and the targets it draws into when it keeps their contents (`clear = false`);
//! every read is of the latest earlier pass that wrote the target.
//!
//! Pruning walks the passes backwards with the set of targets whose current contents are
//! still needed (at first only `output`): a pass runs only when it writes one of them;
//! attachments of a running pass that nobody needs afterwards are dropped (not attached,
//! the output at that location is discarded). Targets whose lifetimes (first write to last
//! use among the passes that run) do not overlap share one texture when format and size
//! agree.

use std::collections::BTreeSet;

use crate::manifest::{Effect, PassClear, PassDecl, TargetFormat};

/// Why a pass does not run.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Skip {
    /// Nothing it writes is read later or is the output.
    Unused,
}

/// The plan for running an effect's passes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PassPlan {
    /// Per pass (manifest order): does it run?
    pub runs: Vec<bool>,
    /// Per pass: colour attachments (by output location) that are attached. A dropped
    /// attachment's output is discarded.
    pub attached: Vec<Vec<bool>>,
    /// Per pass: the depth attachment's contents are needed after the pass.
    pub depth_kept: Vec<bool>,
    /// Textures to allocate, each shared by targets whose lifetimes do not overlap.
    pub textures: Vec<PhysicalTexture>,
    /// Planned with `keep_all` (nothing pruned or shared).
    pub keep_all: bool,
}

/// One texture and the targets that live in it, in order of use.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PhysicalTexture {
    pub format: TargetFormat,
    pub size: (u32, u32),
    /// (target name, first pass, last pass) with indices into `Effect::passes`.
    pub targets: Vec<(String, usize, usize)>,
}

impl PassPlan {
    /// The texture index a target lives in (None for targets no running pass touches).
    pub fn texture_of(&self, target: &str) -> Option<usize> {
        self.textures.iter().position(|t| t.targets.iter().any(|(n, _, _)| n == target))
    }
    /// The passes that run, in order.
    pub fn running(&self) -> impl Iterator<Item = usize> + '_ {
        self.runs.iter().enumerate().filter(|(_, r)| **r).map(|(i, _)| i)
    }
    /// The same plan with its textures allocated for another output size (which passes
    /// run and what they attach do not depend on it).
    pub fn sized(&self, effect: &Effect, output_size: (u32, u32)) -> PassPlan {
        let textures = allocate(effect, output_size, &self.runs, &self.attached, self.keep_all);
        PassPlan { textures, ..self.clone() }
    }
}

/// The targets a pass reads: those it samples and, with `clear = false`, those it draws into.
pub fn reads(pass: &PassDecl) -> Vec<&str> {
    let mut out: Vec<&str> = pass.samples.iter().map(|s| s.target.name.as_str()).collect();
    if pass.clear == PassClear::Keep {
        out.extend(written(pass));
    }
    out
}

/// The targets a pass writes (colour targets, then the depth target).
pub fn written(pass: &PassDecl) -> Vec<&str> {
    let mut out: Vec<&str> = pass.targets.iter().map(|t| t.name.as_str()).collect();
    out.extend(pass.depth.as_ref().map(|d| d.name.as_str()));
    out
}

/// The latest pass before `pass` that writes `target`.
pub fn writer_before(effect: &Effect, pass: usize, target: &str) -> Option<usize> {
    (0..pass).rev().find(|&j| effect.passes[j].writes(target))
}

/// Plans which passes run and where their targets live. With `keep_all` every pass and
/// attachment runs and no texture is shared (`--dump-targets`: every target can be read back).
pub fn plan(effect: &Effect, output_size: (u32, u32), keep_all: bool) -> PassPlan {
    let n = effect.passes.len();
    let mut runs = vec![keep_all; n];
    let mut attached: Vec<Vec<bool>> = effect.passes.iter().map(|p| vec![keep_all; p.targets.len()]).collect();
    let mut depth_kept = vec![keep_all; n];
    if !keep_all {
        let mut live: BTreeSet<&str> = effect.output.iter().map(|o| o.name.as_str()).collect();
        for (i, pass) in effect.passes.iter().enumerate().rev() {
            if !written(pass).iter().any(|t| live.contains(t)) {
                continue;
            }
            runs[i] = true;
            for (slot, t) in attached[i].iter_mut().zip(&pass.targets) {
                *slot = live.contains(t.name.as_str());
            }
            depth_kept[i] = pass.depth.as_ref().is_some_and(|d| live.contains(d.name.as_str()));
            if pass.clear != PassClear::Keep {
                for t in written(pass) {
                    live.remove(t);
                }
            }
            live.extend(reads(pass));
        }
    }
    let textures = allocate(effect, output_size, &runs, &attached, keep_all);
    PassPlan { runs, attached, depth_kept, textures, keep_all }
}

/// Lifetimes of the targets the running passes use, then a greedy assignment to textures.
fn allocate(effect: &Effect, output_size: (u32, u32), runs: &[bool], attached: &[Vec<bool>], keep_all: bool) -> Vec<PhysicalTexture> {
    let last = effect.passes.len();
    // (name, first, last) in order of first use.
    let mut lifetimes: Vec<(String, usize, usize)> = Vec::new();
    let mut touch = |name: &str, i: usize| match lifetimes.iter_mut().find(|(n, _, _)| n == name) {
        Some(l) => l.2 = l.2.max(i),
        None => lifetimes.push((name.to_owned(), i, i)),
    };
    for (i, pass) in effect.passes.iter().enumerate().filter(|(i, _)| runs[*i]) {
        for t in reads(pass) {
            touch(t, i);
        }
        for (t, on) in pass.targets.iter().zip(&attached[i]) {
            if *on {
                touch(&t.name, i);
            }
        }
        if let Some(d) = &pass.depth {
            touch(&d.name, i);
        }
    }
    if let Some(o) = &effect.output {
        if let Some(l) = lifetimes.iter_mut().find(|(n, _, _)| *n == o.name) {
            l.2 = last;
        }
    }
    let mut textures: Vec<PhysicalTexture> = Vec::new();
    for (name, first, end) in lifetimes {
        let Some(decl) = effect.target(&name) else { continue };
        let size = decl.size.resolve(output_size);
        let free = (!keep_all)
            .then(|| {
                textures.iter().position(|t| t.format == decl.format && t.size == size && t.targets.iter().all(|(_, _, e)| *e < first))
            })
            .flatten();
        match free {
            Some(i) => textures[i].targets.push((name, first, end)),
            None => textures.push(PhysicalTexture { format: decl.format, size, targets: vec![(name, first, end)] }),
        }
    }
    textures
}

/// The dependency cycle through `pass` reading `target` written only later, if any: the
/// chain of (pass, target) from the later writer back to `pass`.
pub fn cycle_through(effect: &Effect, pass: usize, target: &str) -> Option<Vec<(usize, String)>> {
    // Later writers of `target`; a cycle exists when one of them (transitively) reads
    // something `pass` writes.
    let writers: Vec<usize> = (pass..effect.passes.len()).filter(|&j| effect.passes[j].writes(target)).collect();
    for w in writers {
        let mut path = vec![(w, target.to_owned())];
        let mut seen = BTreeSet::new();
        if depends_on(effect, w, pass, &mut path, &mut seen) {
            return Some(path);
        }
    }
    None
}

/// Whether `from` reads (transitively) what `to` writes; `path` collects the chain.
fn depends_on(effect: &Effect, from: usize, to: usize, path: &mut Vec<(usize, String)>, seen: &mut BTreeSet<usize>) -> bool {
    if !seen.insert(from) {
        return false;
    }
    for t in reads(&effect.passes[from]) {
        // Any writer of t: the latest before `from`, or any at all when t is read before written.
        let writers: Vec<usize> = match writer_before(effect, from, t) {
            Some(w) => vec![w],
            None => (0..effect.passes.len()).filter(|&j| effect.passes[j].writes(t)).collect(),
        };
        for w in writers {
            path.push((w, t.to_owned()));
            if w == to || depends_on(effect, w, to, path, seen) {
                return true;
            }
            path.pop();
        }
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::diag::FileId;

    /// An effect from `[[passes]]` text (stage files are not read by the parser's graph part).
    fn effect(passes: &str) -> Effect {
        let root = tempfile::Builder::new().prefix("effectc-graph-").tempdir().unwrap();
        let dir = root.path();
        for f in ["a.vert", "a.frag"] {
            std::fs::write(dir.join(f), "").unwrap();
        }
        let text = format!(
            "output = \"final\"\n[targets]\na = {{}}\nb = {{}}\nc = {{}}\nd = {{ format = \"rgba16f\" }}\nz = {{ format = \"depth32f\" }}\nfinal = {{}}\n{passes}"
        );
        crate::manifest::parse_for_tests(&text, FileId(0), dir).unwrap()
    }

    fn pass(name: &str, extra: &str) -> String {
        format!("[[passes]]\nname = \"{name}\"\nstages = {{ vertex = \"a.vert\", fragment = \"a.frag\" }}\n{extra}\n")
    }

    #[test]
    fn passes_that_do_not_reach_the_output_do_not_run() {
        let e = effect(
            &[
                pass("scene", "targets = [\"a\", \"b\"]"),
                pass("debug", "targets = [\"c\"]"),
                pass("post", "samples = { t = \"a\" }\ntargets = [\"final\"]"),
            ]
            .concat(),
        );
        let plan = plan(&e, (64, 64), false);
        assert_eq!(plan.runs, [true, false, true]);
        assert_eq!(plan.attached[0], [true, false], "b is never read");
        // Keeping everything (--dump-targets): every pass and attachment, no sharing.
        let all = plan_all(&e);
        assert_eq!(all.runs, [true, true, true]);
        assert_eq!(all.attached[0], [true, true]);
        assert!(all.textures.iter().all(|t| t.targets.len() == 1));
    }

    fn plan_all(e: &Effect) -> PassPlan {
        plan(e, (64, 64), true)
    }

    #[test]
    fn a_kept_target_makes_its_earlier_writer_run() {
        // `overlay` draws onto `final` with clear = false: the combine before it must run;
        // the first write of `final` is overwritten by `combine` (it clears), so `early` does not.
        let e = effect(
            &[
                pass("early", "targets = [\"final\"]"),
                pass("combine", "targets = [\"final\"]\ndepth = \"z\""),
                pass("overlay", "targets = [\"final\"]\ndepth = \"z\"\nclear = false"),
            ]
            .concat(),
        );
        let plan = plan(&e, (64, 64), false);
        assert_eq!(plan.runs, [false, true, true]);
        assert_eq!(plan.depth_kept, [false, true, false]);
    }

    #[test]
    fn targets_share_a_texture_when_lifetimes_do_not_overlap() {
        let e = effect(
            &[
                pass("p0", "targets = [\"a\"]"),
                pass("p1", "samples = { t = \"a\" }\ntargets = [\"b\"]"),
                pass("p2", "samples = { t = \"b\" }\ntargets = [\"c\"]"),
                pass("p3", "samples = { t = \"c\" }\ntargets = [\"d\"]"),
                pass("p4", "samples = { t = \"d\" }\ntargets = [\"final\"]"),
            ]
            .concat(),
        );
        let plan = plan(&e, (64, 64), false);
        // a [0,1], c [2,3] and final [4,end] share the first texture; b [1,2] overlaps
        // both a and c; d is rgba16f: its own.
        assert_eq!(plan.textures.len(), 3, "{:#?}", plan.textures);
        assert_eq!(plan.texture_of("a"), plan.texture_of("c"));
        assert_eq!(plan.texture_of("a"), plan.texture_of("final"));
        assert_ne!(plan.texture_of("a"), plan.texture_of("b"));
        assert_ne!(plan.texture_of("d"), plan.texture_of("a"));
        // A target read while another is written never shares with it.
        for t in &plan.textures {
            for w in t.targets.windows(2) {
                assert!(w[0].2 < w[1].1, "{:?} overlaps {:?}", w[0], w[1]);
            }
        }
    }

    #[test]
    fn cycles_are_found_with_their_chain() {
        let e = effect(
            &[
                pass("first", "samples = { t = \"b\" }\ntargets = [\"a\"]"),
                pass("second", "samples = { t = \"a\" }\ntargets = [\"b\"]"),
                pass("third", "samples = { t = \"c\" }\ntargets = [\"final\"]"),
                pass("fourth", "targets = [\"c\"]"),
            ]
            .concat(),
        );
        let chain = cycle_through(&e, 0, "b").expect("first ← second ← first");
        assert_eq!(chain, [(1, "b".to_string()), (0, "a".to_string())]);
        // `third` reads `c` before `fourth` writes it, but `fourth` does not depend on `third`.
        assert_eq!(cycle_through(&e, 2, "c"), None);
        assert_eq!(writer_before(&e, 2, "c"), None);
        assert_eq!(writer_before(&e, 1, "a"), Some(0));
    }
}
