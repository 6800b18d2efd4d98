#!/usr/bin/env bash
# Solves the same C chain benchmark (bench/chain.c) with loci's libloci_slvs and with
# SolveSpace's libslvs, and prints the time of each and their ratio.
#
# Usage: crates/loci-slvs/bench/run.sh [SIZES...]      (default: 10 100 1000)
# libslvs needs about a minute for 1000 segments on a desktop machine; loci well under 0.1 s.
set -euo pipefail
root="$(cd "$(dirname "$0")/../../.." && pwd)"
target="${CARGO_TARGET_DIR:-$root/target}"
sizes=("${@:-10 100 1000}")
[ $# -eq 0 ] && sizes=(10 100 1000)
(cd "$root" && cargo build --release -p loci-slvs >/dev/null)
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
cc -O2 -I "$root/crates/loci-slvs/include" -o "$tmp/chain_loci" "$root/crates/loci-slvs/bench/chain.c" \
  "$target/release/libloci_slvs.a" -lm -lpthread -ldl
have_slvs=0
if [ -f /usr/include/slvs.h ] && cc -O2 -o "$tmp/chain_slvs" "$root/crates/loci-slvs/bench/chain.c" -lslvs -lm 2>/dev/null; then
  have_slvs=1
else
  echo "libslvs not available (install libslvs1-dev): timing loci only"
fi
printf "%-9s %-26s %-26s %s\n" segments "loci best ms (result/dof)" "libslvs best ms (result/dof)" "libslvs/loci"
for n in "${sizes[@]}"; do
  reps=3; [ "$n" -ge 1000 ] && reps=1
  read -r _ lr ld _ lbest _ lerr < <("$tmp/chain_loci" "$n" 3)
  if [ $have_slvs = 1 ]; then
    if out="$(timeout "${SLVS_TIMEOUT:-600}" "$tmp/chain_slvs" "$n" "$reps" 2>&1 | tail -1)" && [ -n "$out" ]; then
      read -r _ sr sd _ sbest _ serr <<<"$out"
      ratio="$(awk -v a="$sbest" -v b="$lbest" 'BEGIN { printf "%.0fx", a / b }')"
      printf "%-9s %-26s %-26s %s\n" "$n" "$lbest ($lr/$ld)" "$sbest ($sr/$sd)" "$ratio"
    else
      printf "%-9s %-26s %-26s %s\n" "$n" "$lbest ($lr/$ld)" "refused or timed out" "-"
    fi
  else
    printf "%-9s %-26s\n" "$n" "$lbest ($lr/$ld)"
  fi
done
