#!/usr/bin/env bash
# The Python package's tests: builds the loci wheel with maturin (in the workspace's target
# directory, so the Rust dependencies are not built twice), installs it in a virtual
# environment ($CARGO_TARGET_DIR/py-venv, or target/py-venv), runs the pytest suite and
# `mypy --strict` on the examples. Where Python 3.9+ with venv and pip cannot be had, it says
# why it skipped and exits 0; a failing build, test or type check exits non-zero.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
target="${CARGO_TARGET_DIR:-$root/target}"
venv="$target/py-venv"
start=$(date +%s)

skip() {
  echo "skipped: the Python tests (crates/loci-py), because $*"
  exit 0
}

py="$(command -v python3 || true)"
[ -n "$py" ] || skip "python3 is not installed"
"$py" -c 'import sys; sys.exit(sys.version_info < (3, 9))' || skip "python3 is older than 3.9"
if ! [ -x "$venv/bin/python" ]; then
  "$py" -m venv "$venv" >/dev/null 2>&1 || {
    rm -rf "$venv"
    skip "python3 -m venv failed (Debian: apt-get install python3-venv)"
  }
fi
"$venv/bin/python" -m pip install -q --disable-pip-version-check maturin numpy pytest mypy \
  >/dev/null 2>&1 || skip "pip could not install maturin, numpy, pytest and mypy (no network?)"
# SolveSpace's own module, for the side-by-side tests of loci.slvs (they skip without it).
"$venv/bin/python" -c 'import slvs' >/dev/null 2>&1 \
  || "$venv/bin/python" -m pip install -q --disable-pip-version-check slvs==3.3 >/dev/null 2>&1 \
  || echo "warning: could not install PyPI slvs 3.3; loci.slvs is tested without it alongside"

wheels="$target/wheels/loci-py"
rm -rf "$wheels"
CARGO_TARGET_DIR="$target" "$venv/bin/maturin" build --release --quiet \
  -m "$here/Cargo.toml" -o "$wheels"
wheel="$(ls "$wheels"/loci-*.whl)"
"$venv/bin/python" -m pip install -q --disable-pip-version-check --force-reinstall --no-deps "$wheel"
echo "wheel: $(basename "$wheel") ($(du -k "$wheel" | cut -f1) KiB)"

cd "$here"
"$venv/bin/python" -m pytest -q -p no:cacheprovider tests
"$venv/bin/python" -m mypy --strict --no-incremental examples
echo "python tests: done in $(( $(date +%s) - start )) s"
