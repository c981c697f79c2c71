//! Writing a build into the user's folder without touching what ladderc did not write.
//!
//! Input: the output folder and the build's files (relative path, contents). Output: the files in place
//! and the manifest `DIR/.ladderc-manifest`, one line `<sha256 hex>  <path>` per file ladderc wrote
//! (the format of `sha256sum`, so `sha256sum -c .ladderc-manifest` checks it), sorted by path.
//! Invariants:
//! - A file is replaced only when the previous manifest lists it and it still has the hash recorded
//!   there. Any other existing file of the new build (the user's own, or one the user changed since) is a
//!   conflict: the whole build is refused, listing every conflict, and nothing is written.
//! - Files of the previous manifest that the new build does not produce are removed only when unchanged;
//!   changed ones are left in place and dropped from the manifest (they are the user's now).
//! - Every file is written to a temporary file in its destination folder and renamed over the old one,
//!   so a reader never sees a partly written file; an I/O error before the renames leaves the folder as
//!   it was. The manifest is renamed into place last.
//! - No file is `fsync`ed (as cc, rustc and make do not): the output is atomic against a crash of
//!   ladderc, and as durable as the file system makes a rename; durability across a power loss is the
//!   build system's business. Syncing the nine files of a build made it wait for the disk (about
//!   50 ms of wall time on 10,000 rungs; crates/ladderc/BENCHMARKS.md, Round 14).
//! - A regular file at `DIR` is never replaced by a folder. `DIR` may be `.` or any existing folder.

use sha2::{Digest, Sha256};
use std::collections::BTreeMap;
use std::io::Write;
use std::path::{Component, Path, PathBuf};

/// The manifest's file name inside the output folder.
pub const MANIFEST: &str = ".ladderc-manifest";

/// Why a build was not written.
#[derive(Debug)]
pub enum WriteError {
    /// The output path exists and is not a folder.
    NotAFolder(PathBuf),
    /// Existing files that ladderc did not write, or that were changed since it wrote them (relative
    /// paths, sorted).
    Conflicts(Vec<String>),
    /// A file-system error on this path.
    Io(PathBuf, std::io::Error),
}

impl std::fmt::Display for WriteError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            WriteError::NotAFolder(p) => write!(f, "{} exists and is not a folder", p.display()),
            WriteError::Conflicts(c) => write!(
                f,
                "would overwrite {} file(s) that ladderc did not write or that were changed since: {}",
                c.len(),
                c.join(", ")
            ),
            WriteError::Io(p, e) => write!(f, "cannot write {}: {e}", p.display()),
        }
    }
}

/// The SHA-256 of `bytes` in lower-case hex.
pub fn sha256_hex(bytes: &[u8]) -> String {
    hex(&Sha256::digest(bytes))
}

/// The manifest's entries (path -> hash); empty when there is none. A line that cannot be read makes the
/// whole manifest untrusted (empty), so that nothing is replaced on its word.
pub fn read_manifest(dir: &Path) -> BTreeMap<String, String> {
    let Ok(text) = std::fs::read_to_string(dir.join(MANIFEST)) else {
        return BTreeMap::new();
    };
    let mut out = BTreeMap::new();
    for line in text.lines().filter(|l| !l.is_empty()) {
        match line.split_once("  ") {
            Some((hash, path))
                if hash.len() == 64
                    && hash.bytes().all(|b| b.is_ascii_hexdigit())
                    && is_plain_relative(path) =>
            {
                out.insert(path.to_string(), hash.to_ascii_lowercase());
            }
            _ => return BTreeMap::new(),
        }
    }
    out
}

/// A relative path of normal components only (no `..`, no root): it stays inside the folder.
fn is_plain_relative(p: &str) -> bool {
    !p.is_empty()
        && Path::new(p)
            .components()
            .all(|c| matches!(c, Component::Normal(_)))
}

/// The hash of the regular file at `path`; `None` when it does not exist; `Some(None)` when something
/// else is there (a folder) or it cannot be read.
fn current_hash(path: &Path) -> Option<Option<String>> {
    current_hash_known(path, None)
}

/// [`current_hash`], given the contents about to replace the file and their hash: a file that holds
/// exactly those bytes (the usual rebuild) has that hash, found by comparing instead of hashing again.
/// The file is read in 64 KiB pieces, never whole (a rebuild of a 43 MB `program.c` allocated and
/// faulted in 43 MB more for the check), and hashed only from where it differs from the contents (the
/// equal part before that is hashed from the contents).
fn current_hash_known(path: &Path, known: Option<(&[u8], &str)>) -> Option<Option<String>> {
    use std::io::Read as _;
    let meta = std::fs::symlink_metadata(path).ok()?;
    if !meta.is_file() {
        return Some(None);
    }
    let Ok(mut file) = std::fs::File::open(path) else {
        return Some(None);
    };
    let contents = known.map_or(&[][..], |k| k.0);
    let mut buf = vec![0u8; 64 * 1024];
    // `Err(n)`: the first `n` bytes read equal `contents[..n]`, nothing hashed yet; `Ok(h)`: the
    // file differs (or there is nothing to compare with) and `h` has hashed all bytes read.
    let mut state: Result<Sha256, usize> = match known {
        Some(_) => Err(0),
        None => Ok(Sha256::new()),
    };
    loop {
        let n = match file.read(&mut buf) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(_) => return Some(None),
        };
        let piece = &buf[..n];
        state = match state {
            Err(done) if contents.get(done..done + n) == Some(piece) => Err(done + n),
            Err(done) => {
                let mut h = Sha256::new();
                h.update(&contents[..done]);
                h.update(piece);
                Ok(h)
            }
            Ok(mut h) => {
                h.update(piece);
                Ok(h)
            }
        };
    }
    Some(Some(match (state, known) {
        (Err(done), Some((_, hash))) if done == contents.len() => hash.to_string(),
        (Err(done), _) => sha256_hex(&contents[..done]),
        (Ok(h), _) => hex(&h.finalize()),
    }))
}

fn hex(digest: &[u8]) -> String {
    const DIGITS: &[u8; 16] = b"0123456789abcdef";
    let mut s = String::with_capacity(digest.len() * 2);
    for b in digest {
        s.push(DIGITS[usize::from(b >> 4)] as char);
        s.push(DIGITS[usize::from(b & 15)] as char);
    }
    s
}

/// Writes `files` into `dir` under the rules of the module header.
pub fn write_project(dir: &Path, files: &[(String, Vec<u8>)]) -> Result<(), WriteError> {
    let io = |p: &Path| {
        let p = p.to_path_buf();
        move |e| WriteError::Io(p, e)
    };
    match std::fs::metadata(dir) {
        Ok(m) if !m.is_dir() => return Err(WriteError::NotAFolder(dir.to_path_buf())),
        Ok(_) => {}
        Err(_) => {
            if std::fs::symlink_metadata(dir).is_ok() {
                // a dangling symbolic link: not ours to replace
                return Err(WriteError::NotAFolder(dir.to_path_buf()));
            }
            std::fs::create_dir_all(dir).map_err(io(dir))?;
        }
    }
    let old = read_manifest(dir);
    let mut conflicts = Vec::new();
    let mut new_manifest = BTreeMap::new();
    for (rel, contents) in files {
        assert!(is_plain_relative(rel), "generated path {rel}");
        if rel == MANIFEST {
            conflicts.push(rel.clone());
            continue;
        }
        // Every folder on the way must be a folder (or absent).
        let mut prefix = PathBuf::new();
        let comps: Vec<_> = Path::new(rel).components().collect();
        for c in &comps[..comps.len() - 1] {
            prefix.push(c);
            if let Ok(m) = std::fs::symlink_metadata(dir.join(&prefix)) {
                if !m.is_dir() {
                    conflicts.push(prefix.display().to_string());
                }
            }
        }
        let hash = sha256_hex(contents);
        match current_hash_known(&dir.join(rel), Some((contents, &hash))) {
            None => {}
            Some(Some(h)) if old.get(rel) == Some(&h) => {}
            Some(_) => conflicts.push(rel.clone()),
        }
        new_manifest.insert(rel.clone(), hash);
    }
    if !conflicts.is_empty() {
        conflicts.sort();
        conflicts.dedup();
        return Err(WriteError::Conflicts(conflicts));
    }
    // Stage every file beside its destination; nothing visible changes until the renames.
    let mut staged = Vec::new();
    for (rel, contents) in files {
        let dest = dir.join(rel);
        let parent = dest.parent().unwrap_or(dir);
        std::fs::create_dir_all(parent).map_err(io(parent))?;
        staged.push((stage(parent, contents).map_err(io(&dest))?, dest));
    }
    let mut manifest_text = String::new();
    for (path, hash) in &new_manifest {
        manifest_text.push_str(&format!("{hash}  {path}\n"));
    }
    let manifest = stage(dir, manifest_text.as_bytes()).map_err(io(&dir.join(MANIFEST)))?;
    for (tmp, dest) in staged {
        tmp.persist(&dest)
            .map_err(|e| WriteError::Io(dest, e.error))?;
    }
    // Files of the previous build that this one does not produce: removed when unchanged.
    for (rel, hash) in &old {
        if new_manifest.contains_key(rel) {
            continue;
        }
        let path = dir.join(rel);
        if current_hash(&path) == Some(Some(hash.clone())) {
            std::fs::remove_file(&path).map_err(io(&path))?;
        }
    }
    let dest = dir.join(MANIFEST);
    manifest
        .persist(&dest)
        .map_err(|e| WriteError::Io(dest, e.error))?;
    Ok(())
}

/// `build -o DIR [--depfile FILE]`: [`write_project`], then the depfile (its outputs: every file
/// written and the manifest), as diagnostics: E9100 (DIR is not a folder), E9101 (conflicts), E9002 (I/O).
pub fn write_build(
    dir: &Path,
    files: &[(String, Vec<u8>)],
    depfile: Option<&Path>,
    inputs: &[PathBuf],
) -> Result<(), Box<diagnostics::Diagnostic>> {
    use diagnostics::{code, Diagnostic};
    write_project(dir, files).map_err(|e| {
        let d = match &e {
            WriteError::NotAFolder(_) => Diagnostic::error(code::E9100, e.to_string())
                .with_hint("choose another -o, or remove that file yourself"),
            WriteError::Conflicts(list) => Diagnostic::error(code::E9101, e.to_string())
                .with_note(format!(
                    "ladderc replaces only files listed in {} with the hash they had when it wrote them",
                    dir.join(MANIFEST).display()
                ))
                .with_hint(format!(
                    "move {} away, or build into another folder",
                    if list.len() == 1 { "it" } else { "them" }
                )),
            WriteError::Io(..) => Diagnostic::error(code::E9002, e.to_string())
                .with_hint("check that the folder can be written"),
        };
        Box::new(d)
    })?;
    if let Some(dep) = depfile {
        let mut outputs: Vec<PathBuf> = files.iter().map(|(rel, _)| dir.join(rel)).collect();
        outputs.push(dir.join(MANIFEST));
        let text = crate::depfile::render(&outputs, inputs);
        write_file_atomically(dep, text.as_bytes()).map_err(|e| {
            Box::new(
                Diagnostic::error(code::E9002, format!("cannot write {}: {e}", dep.display()))
                    .with_hint("check that the depfile's folder exists and can be written"),
            )
        })?;
    }
    Ok(())
}

/// Writes one file through a temporary file in its folder and a rename.
pub fn write_file_atomically(path: &Path, contents: &[u8]) -> std::io::Result<()> {
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if std::fs::metadata(path).is_ok_and(|m| m.is_dir()) {
        return Err(std::io::Error::other("it is a folder"));
    }
    stage(parent, contents)?
        .persist(path)
        .map(|_| ())
        .map_err(|e| e.error)
}

/// A temporary file in `dir` holding `contents`, readable by everyone as a normal file would be.
fn stage(dir: &Path, contents: &[u8]) -> std::io::Result<tempfile::NamedTempFile> {
    let mut b = tempfile::Builder::new();
    b.prefix(".ladderc-tmp-");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        b.permissions(std::fs::Permissions::from_mode(0o644));
    }
    let mut f = b.tempfile_in(dir)?;
    f.write_all(contents)?;
    Ok(f)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn files(list: &[(&str, &str)]) -> Vec<(String, Vec<u8>)> {
        list.iter()
            .map(|(p, c)| (p.to_string(), c.as_bytes().to_vec()))
            .collect()
    }

    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn the_users_files_stay_and_old_outputs_go_only_when_unchanged() {
        let root = tempfile::tempdir().unwrap();
        let out = root.path().join("out");
        std::fs::create_dir(&out).unwrap();
        std::fs::write(out.join("main_fw.c"), "user").unwrap();
        write_project(&out, &files(&[("a.c", "1"), ("b.h", "2")])).unwrap();
        assert_eq!(names(&out), [MANIFEST, "a.c", "b.h", "main_fw.c"]);
        // a rebuild replaces a.c; b.h is not produced any more and goes
        write_project(&out, &files(&[("a.c", "3"), ("c.c", "4")])).unwrap();
        assert_eq!(names(&out), [MANIFEST, "a.c", "c.c", "main_fw.c"]);
        assert_eq!(std::fs::read_to_string(out.join("a.c")).unwrap(), "3");
        assert_eq!(
            std::fs::read_to_string(out.join("main_fw.c")).unwrap(),
            "user"
        );
        let m = read_manifest(&out);
        assert_eq!(m.keys().collect::<Vec<_>>(), ["a.c", "c.c"]);
        assert_eq!(m["a.c"], sha256_hex(b"3"));
        // the user edits c.c: it is theirs now; a build that drops c.c leaves it, one that writes it is
        // refused with nothing written
        std::fs::write(out.join("c.c"), "edited").unwrap();
        let err = write_project(&out, &files(&[("a.c", "5"), ("c.c", "6")])).unwrap_err();
        assert!(
            matches!(&err, WriteError::Conflicts(c) if c == &["c.c"]),
            "{err}"
        );
        assert_eq!(std::fs::read_to_string(out.join("a.c")).unwrap(), "3");
        assert_eq!(names(&out), [MANIFEST, "a.c", "c.c", "main_fw.c"]);
        write_project(&out, &files(&[("a.c", "5")])).unwrap();
        assert_eq!(std::fs::read_to_string(out.join("c.c")).unwrap(), "edited");
        assert_eq!(read_manifest(&out).len(), 1);
    }

    #[test]
    fn an_existing_files_hash_is_its_own_whatever_the_contents_about_to_replace_it() {
        let root = tempfile::tempdir().unwrap();
        let path = root.path().join("p.c");
        // larger than one 64 KiB read, so the comparison spans pieces
        let big: Vec<u8> = (0..200_000u32).map(|i| (i % 251) as u8).collect();
        std::fs::write(&path, &big).unwrap();
        let own = sha256_hex(&big);
        let mut same_len = big.clone();
        same_len[150_000] ^= 1;
        let cases: [&[u8]; 5] = [&big, &same_len, &big[..100_000], &[], b"x"];
        for contents in cases {
            // a wrong hash for the contents shows that it is used only when the bytes are equal
            let claimed = if contents == big.as_slice() {
                own.clone()
            } else {
                "0".repeat(64)
            };
            assert_eq!(
                current_hash_known(&path, Some((contents, &claimed))),
                Some(Some(own.clone()))
            );
        }
        let mut longer = big.clone();
        longer.push(0);
        assert_eq!(
            current_hash_known(&path, Some((&longer, "0"))),
            Some(Some(own.clone()))
        );
        assert_eq!(current_hash(&path), Some(Some(own)));
        assert_eq!(current_hash(&root.path().join("none")), None);
        assert_eq!(current_hash(root.path()), Some(None));
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
    }

    #[test]
    fn an_existing_file_of_the_build_that_ladderc_did_not_write_is_refused() {
        let root = tempfile::tempdir().unwrap();
        std::fs::write(root.path().join("Makefile"), "mine").unwrap();
        std::fs::create_dir(root.path().join("program.c")).unwrap();
        let err = write_project(
            root.path(),
            &files(&[("Makefile", "x"), ("program.c", "y"), ("z", "")]),
        )
        .unwrap_err();
        match err {
            WriteError::Conflicts(c) => assert_eq!(c, ["Makefile", "program.c"]),
            e => panic!("{e}"),
        }
        assert_eq!(names(root.path()), ["Makefile", "program.c"]);
        assert_eq!(
            std::fs::read_to_string(root.path().join("Makefile")).unwrap(),
            "mine"
        );
    }

    #[test]
    fn a_regular_file_is_never_replaced_by_a_folder() {
        let root = tempfile::tempdir().unwrap();
        let out = root.path().join("out");
        std::fs::write(&out, "a file").unwrap();
        let err = write_project(&out, &files(&[("a.c", "1")])).unwrap_err();
        assert!(matches!(err, WriteError::NotAFolder(_)));
        assert_eq!(std::fs::read_to_string(&out).unwrap(), "a file");
    }

    #[test]
    fn an_unreadable_manifest_trusts_nothing() {
        let root = tempfile::tempdir().unwrap();
        write_project(root.path(), &files(&[("a.c", "1")])).unwrap();
        std::fs::write(root.path().join(MANIFEST), "garbage\n").unwrap();
        assert!(read_manifest(root.path()).is_empty());
        let err = write_project(root.path(), &files(&[("a.c", "2")])).unwrap_err();
        assert!(matches!(err, WriteError::Conflicts(_)));
        // a manifest entry cannot point outside the folder
        let h = sha256_hex(b"1");
        std::fs::write(root.path().join(MANIFEST), format!("{h}  ../a.c\n")).unwrap();
        assert!(read_manifest(root.path()).is_empty());
    }
}
