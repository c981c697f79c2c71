//! The bounded, sorted walk of a project folder for its source files (an AX project's `src/`, an
//! OpenPLC v4 project's `pous/`).
//!
//! Input: a folder, the caller's bounds (how many folders down, how many files at most) and its
//! file filter. Output: the paths of the files under the folder that the filter accepts, in name
//! order (each folder's entries sorted by file name, a sub-folder's files where its name sorts),
//! each path the folder joined with the names below it.
//!
//! Invariants: never panics; reads no file, only folder listings, and writes nothing; a folder that
//! cannot be listed (and an entry whose type cannot be read) is passed over; folders deeper than
//! the depth bound (the folder itself is depth 0) are not listed, and no more files than the file
//! bound are returned, so the walk ends on any folder tree; symbolic links are not followed: a
//! link (to a file or a folder) is neither a file nor a folder here, as the entry's own type says.

use std::path::{Path, PathBuf};

/// The files under `dir` that `keep` accepts, at most `max_depth` folders down and at most
/// `max_files` of them, in name order (see the module header).
pub(crate) fn files_under(
    dir: &Path,
    max_depth: usize,
    max_files: usize,
    keep: impl Fn(&Path) -> bool,
) -> Vec<PathBuf> {
    let mut out = Vec::new();
    walk(dir, 0, max_depth, max_files, &keep, &mut out);
    out
}

/// Adds to `out` the files under `dir`, which is `depth` folders down.
fn walk(
    dir: &Path,
    depth: usize,
    max_depth: usize,
    max_files: usize,
    keep: &dyn Fn(&Path) -> bool,
    out: &mut Vec<PathBuf>,
) {
    if depth > max_depth || out.len() >= max_files {
        return;
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut entries: Vec<_> = entries.filter_map(Result::ok).collect();
    entries.sort_by_key(|e| e.file_name());
    for e in entries {
        let Ok(t) = e.file_type() else { continue };
        let path = e.path();
        if t.is_dir() {
            walk(&path, depth + 1, max_depth, max_files, keep, out);
        } else if t.is_file() && keep(&path) && out.len() < max_files {
            out.push(path);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::files_under;

    #[test]
    fn sorted_bounded_and_filtered() {
        let root = tempfile::tempdir().unwrap();
        let at = |rel: &str| root.path().join(rel);
        for d in ["b", "b/c", "b/c/d"] {
            std::fs::create_dir(at(d)).unwrap();
        }
        for f in ["z.st", "a.st", "a.txt", "b/m.st", "b/c/n.st", "b/c/d/o.st"] {
            std::fs::write(at(f), "").unwrap();
        }
        let st = |p: &std::path::Path| p.extension().is_some_and(|x| x == "st");
        assert_eq!(
            files_under(root.path(), 2, 100, st),
            [at("a.st"), at("b/c/n.st"), at("b/m.st"), at("z.st")]
        );
        assert_eq!(
            files_under(root.path(), 9, 2, st),
            [at("a.st"), at("b/c/d/o.st")]
        );
        assert!(files_under(&at("missing"), 9, 9, st).is_empty());
    }
}
