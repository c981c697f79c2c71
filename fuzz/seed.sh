#!/bin/sh
# Builds the seed corpora of the cargo-fuzz targets from the project's own fixtures (no third-party files):
# fuzz/corpus/<target>/. Run from anywhere; needs python3 and cargo (the drive images are compiled by
# `ladderc drive build`).
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
c="$root/fuzz/corpus"
mkdir -p "$c/il" "$c/st" "$c/xml" "$c/template" "$c/drive_script" "$c/drive_image"
for f in "$root"/examples/*/*.il "$root"/tests/tests/motion/*.il "$root"/crates/il-frontend/tests/samples/*.il; do
    cp "$f" "$c/il/$(basename "$(dirname "$f")")_$(basename "$f")"
done
for f in "$root"/crates/ladder-compiler/tests/fixtures/*.xml "$root"/tests/tests/fixtures/*.xml \
    "$root"/tests/tests/fixtures/sfc/*.xml "$root"/tests/tests/motion/*.xml; do
    cp "$f" "$c/xml/$(basename "$(dirname "$f")")_$(basename "$f")"
done
cp "$root"/templates/*.xml "$c/template/"
cp "$root"/crates/drive-script/tests/scripts/*.ds "$c/drive_script/"
# The ST bodies of the XML fixtures.
python3 - "$c/xml" "$c/st" <<'PY'
import os, re, sys
src, dst = sys.argv[1], sys.argv[2]
n = 0
for name in sorted(os.listdir(src)):
    text = open(os.path.join(src, name), encoding="utf-8", errors="replace").read()
    for m in re.finditer(r"<ST>(.*?)</ST>", text, re.S):
        body = m.group(1)
        cd = re.search(r"<!\[CDATA\[(.*)\]\]>", body, re.S)
        open(os.path.join(dst, f"st_{n}.st"), "w").write(cd.group(1) if cd else body)
        n += 1
PY
for f in "$c"/drive_script/*.ds; do
    (cd "$root" && cargo run -q -p ladderc -- drive build "$f" -o "$c/drive_image/$(basename "$f" .ds).img")
done
# Minimised inputs of past findings (committed under fuzz/regressions/<target>/; each is also a regression
# test in tests/tests/fuzz_inprocess.rs).
for d in "$root"/fuzz/regressions/*/; do
    cp "$d"* "$c/$(basename "$d")/"
done
ls "$c" | while read -r t; do echo "$t: $(ls "$c/$t" | wc -l) seeds"; done
