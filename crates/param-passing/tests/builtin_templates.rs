//! The shipped templates: they load, their bodies use only declared names and motion-library symbols, and
//! the IL method's static library compiles with the system C compiler against the real motion_lib.h.

use diagnostics::{render, Diagnostics, MessageFormat, SourceMap};
use param_passing::library::{self, Library};
use param_passing::lower::{il_layout, TmWindow};
use param_passing::static_lib;
use std::process::Command;

fn builtin() -> (SourceMap, Library, Diagnostics) {
    let mut map = SourceMap::new();
    let mut diags = Diagnostics::new();
    let lib = Library::builtin(&mut map, &mut diags);
    (map, lib, diags)
}

#[test]
fn every_builtin_template_loads_and_its_body_checks_clean() {
    let (map, lib, mut diags) = builtin();
    assert!(
        diags.is_empty(),
        "{}",
        render(&map, &diags.clone().into_vec(), MessageFormat::Short)
    );
    assert_eq!(lib.templates().len(), library::BUILTIN.len());
    assert!(lib.check_bodies(library::runtime_symbol_set(), &mut diags));
    assert!(
        diags.is_empty(),
        "{}",
        render(&map, &diags.into_vec(), MessageFormat::Short)
    );
    // Every block of the motion library's single-axis C ABI that has a template names a real function.
    for t in lib.templates() {
        assert!(
            library::MOTION_HEADER.contains(&format!("}} {}_C;", t.block)),
            "{}",
            t.block
        );
    }
}

/// `Library::builtin` reads the built-ins lazily and answers `get` for a name that is no built-in's file
/// stem without reading them: that holds only if every built-in's block name is its file's stem, and
/// each loads without diagnostics.
#[test]
fn builtin_block_names_are_their_file_stems() {
    let mut map = SourceMap::new();
    for (name, text) in library::BUILTIN {
        let mut diags = Diagnostics::new();
        let file = map.add(*name, *text);
        let t = param_passing::template::load(file, text, &mut diags).expect(name);
        assert!(
            diags.is_empty(),
            "{}",
            render(&map, &diags.into_vec(), MessageFormat::Short)
        );
        assert_eq!(Some(t.block.as_str()), name.strip_suffix(".xml"), "{name}");
    }
    // A lookup reads them only for a built-in's name, and finds it whatever its case.
    let (_, lib, _) = builtin();
    assert!(lib.get("TON").is_none());
    assert_eq!(
        lib.get("mc_stop").map(|t| t.block.as_str()),
        Some("MC_Stop")
    );
    assert!(lib.get("TON").is_none());
}

#[test]
fn move_absolute_tm_layout_is_reported_with_its_size() {
    let (_, lib, _) = builtin();
    let t = lib.get("mc_moveabsolute").unwrap();
    let window = TmWindow {
        offset: 3840,
        bytes: 256,
        element_addressing: true,
    };
    let l = il_layout(t, &window).unwrap();
    // 5 LREAL + 2 state LWORD (56) + AXIS_REF (4) + ErrorID (2) + 2 bool inputs, 2 enum bytes, 5 bool outputs.
    assert_eq!(l.total, 56 + 4 + 2 + 2 + 2 + 5);
    for s in &l.slots {
        assert_eq!(s.offset % s.bytes, 0, "{} is aligned to its size", s.param);
    }
}

#[test]
fn static_library_compiles_warning_free_with_the_real_header() {
    let (_, lib, _) = builtin();
    let window = TmWindow {
        offset: 3840,
        bytes: 256,
        element_addressing: true,
    };
    let layouts: Vec<_> = lib
        .templates()
        .iter()
        .map(|t| il_layout(t, &window).unwrap())
        .collect();
    let names: Vec<&str> = lib.templates().iter().map(|t| t.block.as_str()).collect();
    let c = static_lib::library_c(lib.templates().iter().zip(layouts.iter()), &names);
    let dir = tempfile::tempdir().unwrap();
    // A minimal runtime header with the process-image helpers the functions use.
    std::fs::write(
        dir.path().join("ladderc_rt.h"),
        "#include <stdint.h>\n#include <stdbool.h>\nextern uint8_t ladderc_M[4096];\n#define LADDERC_TM (ladderc_M + 3840)\n\
         static inline uint64_t ladderc_load(const uint8_t *a, uint32_t o, unsigned n) { uint64_t v = 0; for (unsigned i = 0; i < n; i++) v |= (uint64_t)a[o + i] << (8 * i); return v; }\n\
         static inline void ladderc_store(uint8_t *a, uint32_t o, unsigned n, uint64_t v) { for (unsigned i = 0; i < n; i++) a[o + i] = (uint8_t)(v >> (8 * i)); }\n\
         struct McEngine *ladderc_motion_engine(void);\n",
    )
    .unwrap();
    std::fs::write(dir.path().join("lib.c"), &c).unwrap();
    let include = concat!(env!("CARGO_MANIFEST_DIR"), "/../motion-lib/include");
    let out = Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()))
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-c", "-o"])
        .arg(dir.path().join("lib.o"))
        .arg("-I")
        .arg(dir.path())
        .arg("-I")
        .arg(include)
        .arg(dir.path().join("lib.c"))
        .output()
        .expect("a C compiler is installed");
    assert!(
        out.status.success(),
        "{}\n{}",
        String::from_utf8_lossy(&out.stderr),
        c
    );
}

#[test]
fn every_builtin_template_function_compiles_alone_with_werror() {
    // The load-time check users' templates get (E4210): the function of each template, compiled alone with
    // `cc -std=c99 -Wall -Wextra -Werror -fsyntax-only` against motion_lib.h.
    let (map, lib, mut diags) = builtin();
    assert!(lib.compile_all(&mut diags));
    assert!(
        diags.is_empty(),
        "{}",
        render(&map, &diags.into_vec(), MessageFormat::Short)
    );
}
