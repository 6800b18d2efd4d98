#!/usr/bin/env bash
# Builds the loci WebAssembly package: the .wasm (wasm32-unknown-unknown, size-optimised
# profile), wasm-bindgen's glue for bundlers and for plain ES modules, the typed wrapper and
# package.json, then `npm pack`. Output: crates/loci-wasm/pkg/ and its tarball
# crates/loci-wasm/pkg/loci-wasm-<version>.tgz; the plain ES module build is also copied to
# web/pkg/ for the browser sketcher.
#
# usage: scripts/build-wasm.sh [--small]
#   --small  optimise for size (opt-level "s", wasm-opt -Os) instead of speed (3, -O3)
#
# Needs: the wasm32-unknown-unknown target (rustup target add wasm32-unknown-unknown),
# wasm-bindgen-cli of the same version as the wasm-bindgen crate in Cargo.lock (cargo install
# wasm-bindgen-cli --version X), npm. wasm-opt from binaryen's npm build is used when
# `npm ci` has installed it in crates/loci-wasm/node_modules.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
crate=crates/loci-wasm
out=$crate/pkg
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$root/target}
level=3
if [ "${1:-}" = "--small" ]; then
  level=s
  export CARGO_PROFILE_WASM_RELEASE_OPT_LEVEL=s
fi

want=$(awk '/^name = "wasm-bindgen"$/{getline; gsub(/[^0-9.]/, ""); print; exit}' Cargo.lock)
have=$(wasm-bindgen --version 2>/dev/null | awk '{print $2}')
if [ "$have" != "$want" ]; then
  echo "build-wasm: wasm-bindgen-cli $want is needed (found: ${have:-none}); run: cargo install wasm-bindgen-cli --version $want" >&2
  exit 1
fi

cargo build --profile wasm-release --target wasm32-unknown-unknown -p loci-wasm
wasm=$CARGO_TARGET_DIR/wasm32-unknown-unknown/wasm-release/loci_wasm.wasm

rm -rf "$out"
mkdir -p "$out"
wasm-bindgen --target bundler --out-dir "$out/bundler" "$wasm"
wasm-bindgen --target web --out-dir "$out/web" "$wasm"

opt=$crate/node_modules/.bin/wasm-opt
for dir in bundler web; do
  rm -f "$out/$dir/.gitignore" "$out/$dir/package.json"
  if [ -x "$opt" ]; then
    # The Rust profile's level; the wasm features rustc emits by default must stay enabled.
    # Both targets at once: binaryen's npm build runs on one core.
    f=$out/$dir/loci_wasm_bg.wasm
    "$opt" "-O$level" --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
      --enable-mutable-globals --enable-reference-types --enable-multivalue "$f" -o "$f.opt" &
  fi
done
wait
for dir in bundler web; do
  f=$out/$dir/loci_wasm_bg.wasm
  if [ -f "$f.opt" ]; then mv "$f.opt" "$f"; fi
done
[ -x "$opt" ] || echo "build-wasm: wasm-opt not installed (npm ci in $crate); the .wasm is not post-optimised"

cp $crate/js/loci.js $crate/js/loci.d.ts $crate/js/index.js $crate/js/index.d.ts \
  $crate/js/web.js $crate/js/web.d.ts "$out/"
cp $crate/README.npm.md "$out/README.md"
version=$(awk -F'"' '/^version = /{print $2; exit}' Cargo.toml)
cat > "$out/package.json" <<JSON
{
  "name": "loci-wasm",
  "version": "$version",
  "description": "loci, a geometric constraint solver for CAD, as WebAssembly: the SolveSpace model, a 2D sketcher with dragging, and assemblies, with TypeScript types.",
  "license": "MIT OR Apache-2.0",
  "type": "module",
  "main": "./index.js",
  "module": "./index.js",
  "types": "./index.d.ts",
  "exports": {
    ".": { "types": "./index.d.ts", "default": "./index.js" },
    "./web": { "types": "./web.d.ts", "default": "./web.js" },
    "./web/loci_wasm_bg.wasm": "./web/loci_wasm_bg.wasm"
  },
  "sideEffects": ["./index.js", "./bundler/loci_wasm.js"],
  "files": ["index.js", "index.d.ts", "web.js", "web.d.ts", "loci.js", "loci.d.ts", "bundler/", "web/", "README.md"]
}
JSON
(cd "$out" && npm pack --silent >/dev/null 2>&1 || npm pack)
rm -rf web/pkg
mkdir -p web/pkg/web
cp "$out"/web.js "$out"/loci.js web/pkg/
cp "$out"/web/loci_wasm.js "$out"/web/loci_wasm_bg.wasm web/pkg/web/
# The gallery's examples, served beside the page.
mkdir -p web/pkg/examples
cp -r examples/sketches examples/assembly web/pkg/examples/

raw=$(wc -c < "$out/web/loci_wasm_bg.wasm")
gz=$(gzip -9 -c "$out/web/loci_wasm_bg.wasm" | wc -c)
echo "build-wasm: $(ls "$out"/*.tgz) ; loci_wasm_bg.wasm $raw bytes, $gz bytes gzipped"
