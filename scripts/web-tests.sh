#!/usr/bin/env bash
# The WebAssembly package and the browser sketcher, end to end: installs what they need (the
# wasm32 target, wasm-bindgen-cli, the npm tools, Debian's chromium), builds the npm package,
# runs the Node tests of its API, type-checks an example of all three layers with
# `tsc --strict` against the packed tarball and runs it, loads the bundler entry, and drives
# the sketcher in headless chromium. A piece whose tools cannot be installed is skipped with
# the reason; a test that fails makes the script fail.
set -uo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$root/target}
crate=crates/loci-wasm
t0=$(date +%s)
failed=0
say() { echo "web-tests: $*"; }
skip_all() {
  say "skipped: the WebAssembly package and browser tests, because $*"
  exit 0
}
run() {
  local what=$1
  shift
  if "$@"; then say "ok: $what"; else say "FAILED: $what"; failed=1; fi
}

# Tools.
if ! rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown; then
  rustup target add wasm32-unknown-unknown >/dev/null 2>&1 \
    || skip_all "the wasm32-unknown-unknown target cannot be installed (rustup target add wasm32-unknown-unknown)"
fi
want=$(awk '/^name = "wasm-bindgen"$/{getline; gsub(/[^0-9.]/, ""); print; exit}' Cargo.lock)
if [ "$(wasm-bindgen --version 2>/dev/null | awk '{print $2}')" != "$want" ]; then
  say "installing wasm-bindgen-cli $want (cargo install)"
  cargo install -q wasm-bindgen-cli --version "$want" >/dev/null 2>&1 \
    || skip_all "wasm-bindgen-cli $want cannot be installed (cargo install wasm-bindgen-cli --version $want)"
fi
command -v node >/dev/null 2>&1 && command -v npm >/dev/null 2>&1 || skip_all "node and npm are not installed"
(cd $crate && npm ci --no-audit --no-fund --loglevel=error >/dev/null 2>&1) \
  || skip_all "npm ci in $crate failed (binaryen, typescript and playwright-core from the npm registry)"

# The package.
scripts/build-wasm.sh || { say "FAILED: scripts/build-wasm.sh"; exit 1; }
tarball=$(ls $crate/pkg/loci-wasm-*.tgz)

run "node tests of the package API" node --test $crate/tests-js/

tsc_example() {
  local dir
  dir=$(mktemp -d)
  cp $crate/example/example.ts $crate/example/node.d.ts $crate/example/tsconfig.json $crate/example/package.json "$dir/"
  (cd "$dir" && npm install --no-audit --no-fund --loglevel=error "$root/$tarball" >/dev/null) \
    && "$root/$crate/node_modules/.bin/tsc" -p "$dir" \
    && node "$dir/out/example.js"
  local rc=$?
  rm -rf "$dir"
  return $rc
}
run "tsc --strict on an example of all three layers, against the tarball, and run" tsc_example

bundler_entry() {
  node --experimental-wasm-modules --no-warnings --input-type=module -e "
    import { Sketch } from '$root/$crate/pkg/index.js';
    const s = new Sketch();
    const a = s.addPoint(0, 0), b = s.addPoint(3, 4);
    s.addConstraint({ type: 'fix', point: a });
    s.addConstraint({ type: 'distance', a, b, value: 10 });
    if (s.solve().outcome !== 'okay' || Math.abs(Math.hypot(...s.point(b)) - 10) > 1e-9) process.exit(1);
  "
}
run "the bundler entry loads and solves (node --experimental-wasm-modules)" bundler_entry

# The browser.
if [ ! -x "${CHROMIUM:-/usr/bin/chromium}" ] && command -v apt-get >/dev/null 2>&1; then
  (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium) >/dev/null 2>&1 || true
fi
if [ -x "${CHROMIUM:-/usr/bin/chromium}" ]; then
  run "the sketcher in headless chromium" node --test web/test/browser.test.mjs
else
  say "skipped: the browser test, because chromium cannot be installed (apt-get install chromium)"
fi

say "done in $(( $(date +%s) - t0 )) s"
exit $failed
