//! `ladderc build --report json`: what each PLCopen block type cost (paper A's comparison).
//!
//! Input: the lowering (per-block method, calls, TM bytes, IL instructions), the library and the generated
//! C project. Output: a JSON document `{ "blocks": [ { "block", "method", "calls", "tm_bytes",
//! "il_instructions", "c_bytes" } ] }`, blocks in name order. `c_bytes` is the size of the C the block
//! contributes: its guarded static-library function (IL method, one per block type) or the definitions of
//! its synthesised functions in `program.c` (template method, one per call). `object_bytes` is the code
//! size of the same functions compiled (`cc -std=c99 -O2 -fno-inline -c`, symbol sizes from `nm -S`);
//! `null` when no C compiler or `nm` is available.
//! `code_size` measures the whole program as its Makefile builds it (`-O2 -ffunction-sections
//! -fdata-sections`, linked with `-Wl,--gc-sections -s` and the motion library when it uses one):
//! `program_code_bytes` is the machine code of the program's own C (`program.c`, `embedded.c`),
//! `runtime_code_bytes` that of ladderc's C runtime and scan harness, `executable_bytes` the size of the
//! linked, stripped executable file, `motion_lib_bytes` what the motion library's sections kept by
//! `--gc-sections` occupy in it (code, constants, unwind tables; summed from the GNU ld link map; `null`
//! without a motion library or with a linker whose map is not GNU ld's), and each is `null` when no C
//! compiler is available. `motion_lib_std` says how the embedded library's std was built
//! ([`crate::motion_link::EMBEDDED_STD`]; `null` when `LADDERC_MOTION_LIB` replaces the library).
//! Invariant: the figures are measured on the generated text and objects, never estimated.

use crate::pipeline::Lowered;
use param_passing::lower::Method;
use std::collections::HashMap;
use std::process::Command;

/// The C definition of `static void name(` in `c` (from its signature to the closing brace line).
fn definition_len(c: &str, name: &str) -> usize {
    let sig = format!("static void {name}(");
    let Some(start) = c
        .match_indices(&sig)
        .map(|(i, _)| i)
        .find(|&i| !c[i..].lines().next().unwrap_or("").ends_with(';'))
    else {
        return 0;
    };
    match c[start..].find("\n}\n") {
        Some(end) => end + 3,
        None => c.len() - start,
    }
}

/// Code sizes of the functions defined in the project's `program.c` and `embedded.c`, by symbol name
/// (`None`: the project could not be compiled or inspected here).
fn symbol_sizes(program: &c_backend::CProgram) -> Option<HashMap<String, u64>> {
    let dir = tempfile::tempdir().ok()?;
    c_backend::toolchain::write_files(program, dir.path()).ok()?;
    let cc = std::env::var("CC")
        .ok()
        .filter(|s| !s.trim().is_empty())
        .unwrap_or_else(|| "cc".into());
    let mut words = cc.split_whitespace();
    let mut sizes = HashMap::new();
    for src in ["program.c", "embedded.c"] {
        if program.file(src).is_none() {
            continue;
        }
        let obj = src.replace(".c", ".o");
        let ok = Command::new(words.next().unwrap_or("cc"))
            .args(words.clone())
            .args(["-std=c99", "-O2", "-fno-inline", "-c", src, "-o", &obj])
            .current_dir(dir.path())
            .output()
            .ok()?
            .status
            .success();
        words = cc.split_whitespace();
        if !ok {
            return None;
        }
        let nm = Command::new("nm")
            .args(["-S", "--defined-only", &obj])
            .current_dir(dir.path())
            .output()
            .ok()?;
        for line in String::from_utf8_lossy(&nm.stdout).lines() {
            let f: Vec<&str> = line.split_whitespace().collect();
            if let [_, size, kind, name] = f.as_slice() {
                if kind.eq_ignore_ascii_case("t") {
                    if let Ok(n) = u64::from_str_radix(size, 16) {
                        sizes.insert(name.to_string(), n);
                    }
                }
            }
        }
    }
    Some(sizes)
}

/// The C compiler command: `$CC`, else `cc` (may hold arguments).
fn cc_words() -> Vec<String> {
    std::env::var("CC")
        .ok()
        .filter(|s| !s.trim().is_empty())
        .unwrap_or_else(|| "cc".into())
        .split_whitespace()
        .map(str::to_string)
        .collect()
}

/// The machine code in an object file: the sum of its text symbols' sizes (`nm -S`).
fn text_bytes(dir: &std::path::Path, obj: &str) -> Option<u64> {
    let nm = Command::new("nm")
        .args(["-S", "--defined-only", obj])
        .current_dir(dir)
        .output()
        .ok()?;
    if !nm.status.success() {
        return None;
    }
    let mut total = 0;
    for line in String::from_utf8_lossy(&nm.stdout).lines() {
        let f: Vec<&str> = line.split_whitespace().collect();
        if let [_, size, kind, _] = f.as_slice() {
            if kind.eq_ignore_ascii_case("t") {
                total += u64::from_str_radix(size, 16).unwrap_or(0);
            }
        }
    }
    Some(total)
}

/// The bytes that input sections from `archive` occupy in the loaded image, from a GNU ld link map
/// (`-Wl,-Map=FILE`): the kept input sections under every allocated output section except `.bss`/`.tbss`
/// (which take no file bytes). `None` when the map has no memory map part (another linker).
pub fn archive_bytes(map: &str, archive: &str) -> Option<u64> {
    let (_, body) = map.split_once("Linker script and memory map")?;
    let member = format!("{archive}(");
    let mut output = "";
    let mut pending = false;
    let mut total = 0u64;
    let counted = |out: &str| {
        !out.is_empty()
            && !out.starts_with(".debug")
            && !matches!(out, ".bss" | ".tbss" | ".comment" | ".note.GNU-stack")
            && !out.starts_with(".gnu.build.attributes")
    };
    for line in body.lines() {
        if line.starts_with('.') {
            output = line.split_whitespace().next().unwrap_or("");
            pending = false;
            continue;
        }
        let t: Vec<&str> = line.split_whitespace().collect();
        let (size, file) = match t.as_slice() {
            // ` .text.name` alone: its address, size and file are on the next line
            [name] if line.starts_with(" .") || line.starts_with(" *") => {
                pending = !name.is_empty();
                continue;
            }
            [name, _addr, size, file] if line.starts_with(" .") && !name.is_empty() => {
                (*size, *file)
            }
            [addr, size, file] if pending && addr.starts_with("0x") && size.starts_with("0x") => {
                (*size, *file)
            }
            _ => {
                pending = false;
                continue;
            }
        };
        pending = false;
        if counted(output) && file.contains(&member) {
            total += u64::from_str_radix(size.trim_start_matches("0x"), 16).unwrap_or(0);
        }
    }
    Some(total)
}

/// (program code, runtime code, executable file, motion library in it) in bytes, built as the project's
/// Makefile does; `extra` are the files the build adds (the motion library).
pub fn code_size(
    program: &c_backend::CProgram,
    extra: &[(String, Vec<u8>)],
) -> Option<(u64, u64, u64, Option<u64>)> {
    let dir = tempfile::tempdir().ok()?;
    c_backend::toolchain::write_files(program, dir.path()).ok()?;
    for (name, bytes) in extra {
        std::fs::write(dir.path().join(name), bytes).ok()?;
    }
    let cc = cc_words();
    let (first, rest) = cc.split_first()?;
    let (mut own, mut runtime, mut objects) = (0, 0, Vec::new());
    for src in program.sources() {
        let obj = format!("{src}.o");
        let ok = Command::new(first)
            .args(rest)
            .args([
                "-std=c99",
                "-O2",
                "-ffunction-sections",
                "-fdata-sections",
                "-c",
                src,
            ])
            .args(["-o", &obj])
            .current_dir(dir.path())
            .output()
            .ok()?
            .status
            .success();
        if !ok {
            return None;
        }
        let bytes = text_bytes(dir.path(), &obj)?;
        if src == "program.c" || src == "embedded.c" {
            own += bytes;
        } else {
            runtime += bytes;
        }
        objects.push(obj);
    }
    let link = if program.link.is_empty() {
        vec!["-lm".to_string()]
    } else {
        program.link.clone()
    };
    let ok = Command::new(first)
        .args(rest)
        .args(["-o", "program"])
        .args(&objects)
        .args(&link)
        .args(["-Wl,--gc-sections", "-s", "-Wl,-Map=program.map"])
        .current_dir(dir.path())
        .output()
        .ok()?
        .status
        .success();
    if !ok {
        return None;
    }
    let exe = std::fs::metadata(dir.path().join("program")).ok()?.len();
    let library = extra
        .iter()
        .find(|(name, _)| name.ends_with(".a"))
        .and_then(|(name, _)| {
            let map = std::fs::read_to_string(dir.path().join("program.map")).ok()?;
            archive_bytes(&map, name)
        });
    Some((own, runtime, exe, library))
}

/// The report as JSON text; `extra` are the files the build adds to the project (the motion library).
pub fn json(
    lowered: &Lowered,
    program: &c_backend::CProgram,
    extra: &[(String, Vec<u8>)],
) -> String {
    json_with(lowered, program, extra, true)
}

/// [`json`]; `measure`: whether the object and code sizes are measured (by compiling the C with `$CC` and
/// reading `nm`); without it they are `null` and no process is started.
pub fn json_with(
    lowered: &Lowered,
    program: &c_backend::CProgram,
    extra: &[(String, Vec<u8>)],
    measure: bool,
) -> String {
    let program_c = program.file("program.c").unwrap_or("");
    let symbols = if measure { symbol_sizes(program) } else { None };
    let mut blocks = Vec::new();
    for r in &lowered.lowering.reports {
        let c_bytes = match r.method {
            Method::Il => match (
                lowered.library.get(&r.block),
                lowered.lowering.static_functions.get(&r.block),
            ) {
                (Some(t), Some(layout)) => param_passing::static_lib::function_c(t, layout).len(),
                _ => 0,
            },
            Method::Template => lowered
                .lowering
                .synthesized
                .iter()
                .filter(|s| {
                    s.name
                        .strip_prefix(r.block.as_str())
                        .is_some_and(|rest| rest.starts_with('_'))
                })
                .map(|s| definition_len(program_c, &s.name))
                .sum(),
        };
        let object_bytes = symbols.as_ref().map(|syms| -> u64 {
            syms.iter()
                .filter(|(name, _)| {
                    name.as_str() == r.block
                        || name
                            .strip_prefix(r.block.as_str())
                            .and_then(|rest| rest.strip_prefix('_'))
                            .is_some_and(|n| n.bytes().all(|b| b.is_ascii_digit()))
                })
                .map(|(_, n)| *n)
                .sum()
        });
        blocks.push(serde_json::json!({
            "block": r.block,
            "method": match r.method { Method::Il => "il", Method::Template => "template" },
            "calls": r.calls,
            "tm_bytes": r.tm_bytes,
            "il_instructions": r.il_instructions,
            "c_bytes": c_bytes,
            "object_bytes": object_bytes,
        }));
    }
    let size = if measure {
        code_size(program, extra)
    } else {
        None
    };
    let doc = serde_json::json!({
        "blocks": blocks,
        "code_size": {
            "program_code_bytes": size.map(|s| s.0),
            "runtime_code_bytes": size.map(|s| s.1),
            "executable_bytes": size.map(|s| s.2),
            "motion_lib_bytes": size.and_then(|s| s.3),
            "motion_lib_std": match crate::motion_link::source() {
                crate::motion_link::Source::Embedded => Some(crate::motion_link::EMBEDDED_STD),
                crate::motion_link::Source::Override(_) => None,
            },
        },
    });
    serde_json::to_string_pretty(&doc).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::{archive_bytes, definition_len};

    #[test]
    fn the_librarys_kept_sections_are_summed_from_the_link_map() {
        // the shapes of GNU ld's map: a member pulled in, a name on its own line, name and size on one
        // line, fill, a symbol line, debug and bss sections (not counted)
        let map = "Archive member included to satisfy reference by file (symbol)\n\
            libm.a(x.o)  0x0000000000000100 0x999 libm.a(x.o)\n\
            Discarded input sections\n \
            .text.gone     0x0000000000000000       0x500 libm.a(x.o)\n\
            Linker script and memory map\n\
            .text           0x0000000000001000     0x2000\n \
            .text.mc_engine_step_with_a_long_name\n                \
            0x0000000000001000      0x100 libm.a(x.o)\n                \
            0x0000000000001000                mc_engine_step\n \
            .text.main     0x0000000000001100       0x40 main.o\n \
            *fill*         0x0000000000001140        0x10 \n \
            .text          0x0000000000001150       0x20 libm.a(y.o)\n\
            .eh_frame       0x0000000000004000      0x100\n \
            .eh_frame      0x0000000000004000       0x30 libm.a(x.o)\n\
            .bss            0x0000000000008000      0x100\n \
            .bss.state     0x0000000000008000       0x80 libm.a(x.o)\n\
            .debug_info     0x0000000000000000      0x100\n \
            .debug_info    0x0000000000000000       0x70 libm.a(x.o)\n";
        assert_eq!(archive_bytes(map, "libm.a"), Some(0x100 + 0x20 + 0x30));
        assert_eq!(archive_bytes(map, "libother.a"), Some(0));
        assert_eq!(archive_bytes("no map here", "libm.a"), None);
    }

    #[test]
    fn the_definition_not_the_prototype_is_measured() {
        let c =
            "static void F_1(P *self);\nint x;\nstatic void F_1(P *self) {\n    x = 1;\n}\nrest";
        assert_eq!(
            definition_len(c, "F_1"),
            "static void F_1(P *self) {\n    x = 1;\n}\n".len()
        );
        assert_eq!(definition_len(c, "G"), 0);
    }
}
