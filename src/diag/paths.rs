//! How a path is shown in diagnostics: lexically cleaned (`.` dropped, `dir/..` folded)
//! and made relative to the working directory when it lies below it, so every format
//! names a file the same way (`effects/x/../../a.vert` → `a.vert`) and GitHub annotations
//! land on the file the pull request shows.

use std::path::{Component, Path, PathBuf};

/// `path` as diagnostics show it, relative to the working directory `cwd`: below `cwd` →
/// relative to it; elsewhere → relative with `..` when `path` was relative, else absolute.
/// Purely lexical: symbolic links are not followed.
pub fn display_path(path: &str, cwd: Option<&Path>) -> String {
    let given = Path::new(path);
    if path.is_empty() {
        return String::new();
    }
    let Some(cwd) = cwd.filter(|c| c.is_absolute()) else { return clean(given).display().to_string() };
    let absolute = clean(&cwd.join(given));
    let base = clean(cwd);
    if let Ok(inside) = absolute.strip_prefix(&base) {
        return match inside.as_os_str().is_empty() {
            true => ".".to_string(),
            false => inside.display().to_string(),
        };
    }
    if given.is_absolute() {
        return absolute.display().to_string();
    }
    let common = absolute.components().zip(base.components()).take_while(|(a, b)| a == b).count();
    let mut out = PathBuf::new();
    for _ in base.components().skip(common) {
        out.push("..");
    }
    out.extend(absolute.components().skip(common));
    out.display().to_string()
}

/// `p` absolute (joined to the working directory) and lexically clean: links are not
/// followed, so a removed file keeps its path. How `--watch` compares paths.
pub fn absolute(p: &Path) -> PathBuf {
    match std::env::current_dir() {
        Ok(cwd) => clean(&cwd.join(p)),
        Err(_) => clean(p),
    }
}

/// `path` with `.` components dropped and `name/..` folded; a leading `..` of a relative
/// path stays (there is nothing to fold it into).
fn clean(path: &Path) -> PathBuf {
    let mut out: Vec<Component<'_>> = Vec::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => match out.last() {
                Some(Component::Normal(_)) => {
                    out.pop();
                }
                Some(Component::RootDir | Component::Prefix(_)) => {}
                _ => out.push(c),
            },
            other => out.push(other),
        }
    }
    out.iter().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_are_cleaned_and_relative_to_the_working_directory() {
        let cwd = Some(Path::new("/repo"));
        assert_eq!(display_path("effects/x/../../a.vert", cwd), "a.vert");
        assert_eq!(display_path("./effects/sun/sun.frag", cwd), "effects/sun/sun.frag");
        assert_eq!(display_path("/repo/effects/sun/sun.frag", cwd), "effects/sun/sun.frag");
        assert_eq!(display_path("../shared/seed.vert", cwd), "../shared/seed.vert");
        assert_eq!(display_path("effects/../../other/a.frag", cwd), "../other/a.frag");
        assert_eq!(display_path("/elsewhere/./a.frag", cwd), "/elsewhere/a.frag");
        assert_eq!(display_path("a/b/../c.vert", None), "a/c.vert");
        assert_eq!(display_path("../../a.vert", None), "../../a.vert");
        assert_eq!(display_path("", cwd), "");
        assert_eq!(absolute(Path::new("a/./b/../c.vert")), absolute(Path::new("a/c.vert")));
        assert!(absolute(Path::new("x")).is_absolute());
    }
}
