use diagnostics::{render, Diagnostics, MessageFormat, SourceMap};
#[test]
fn scratch() {
    let dir = [
        "/../../../shared/corpus/il",
        "/../../../../shared/corpus/il",
    ]
    .iter()
    .map(|d| format!("{}{d}", env!("CARGO_MANIFEST_DIR")))
    .find(|d| std::path::Path::new(d).is_dir())
    .unwrap();
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|f| f.unwrap().path())
        .collect();
    files.sort();
    for p in files {
        let src = std::fs::read_to_string(&p).unwrap();
        let mut map = SourceMap::new();
        let id = map.add(p.file_name().unwrap().to_str().unwrap(), src.clone());
        let mut d = Diagnostics::new();
        let u = il_frontend::parse(id, &src, &mut d);
        println!("=== {} items={}", p.display(), u.items.len());
        println!("{}", render(&map, &d.into_sorted(), MessageFormat::Short));
    }
}
#[test]
fn scratch2() {
    let src = "LD a\nST b\n";
    let mut d = Diagnostics::new();
    let u = il_frontend::parse(diagnostics::FileId(0), src, &mut d);
    println!("{}", serde_json::to_string_pretty(&u).unwrap());
    println!("{:?}", d);
}
