//! Atomic output: files are written into a temporary directory beside the destination and moved into place
//! only when everything succeeded, so an error never leaves partial output.

use std::path::{Path, PathBuf};

/// Writes `files` (relative path, contents) into `dir`, atomically per directory: either every file is in
/// place afterwards or none of them changed.
pub fn write_dir_atomically(dir: &Path, files: &[(String, Vec<u8>)]) -> std::io::Result<()> {
    let parent = match dir.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    std::fs::create_dir_all(&parent)?;
    let staging = tempfile::Builder::new()
        .prefix(".ladderc-out-")
        .tempdir_in(&parent)?;
    for (rel, contents) in files {
        let path = staging.path().join(rel);
        if let Some(p) = path.parent() {
            std::fs::create_dir_all(p)?;
        }
        std::fs::write(&path, contents)?;
    }
    if dir.exists() {
        // Replace the old directory: move it aside first so a failure can be undone.
        let old = tempfile::Builder::new()
            .prefix(".ladderc-old-")
            .tempdir_in(&parent)?;
        let aside = old.path().join("old");
        std::fs::rename(dir, &aside)?;
        if let Err(e) = std::fs::rename(staging.path(), dir) {
            std::fs::rename(&aside, dir)?;
            return Err(e);
        }
    } else {
        std::fs::rename(staging.path(), dir)?;
    }
    // The staging directory was renamed away; keep its guard from deleting the new location.
    let _ = staging.keep();
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directory_is_replaced_whole() {
        let root = tempfile::tempdir().unwrap();
        let out = root.path().join("out");
        write_dir_atomically(
            &out,
            &[
                ("a.c".into(), b"1".to_vec()),
                ("sub/b.h".into(), b"2".to_vec()),
            ],
        )
        .unwrap();
        assert_eq!(std::fs::read(out.join("sub/b.h")).unwrap(), b"2");
        write_dir_atomically(&out, &[("c.c".into(), b"3".to_vec())]).unwrap();
        assert!(!out.join("a.c").exists());
        assert_eq!(std::fs::read(out.join("c.c")).unwrap(), b"3");
        let leftovers: Vec<_> = std::fs::read_dir(root.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(leftovers, vec![std::ffi::OsString::from("out")]);
    }
}
