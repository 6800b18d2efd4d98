#!/usr/bin/env bash
# Runs loci's fuzz targets one after the other and summarises each.
#
#   fuzz/run.sh [SECONDS_PER_TARGET] [TARGETS...]
#
# SECONDS_PER_TARGET defaults to 60; TARGETS to all of json, slvs, c_abi, resolve, sketch_file
# and assembly_file.
# New inputs go to fuzz/work/corpus/<target> (the committed seeds in fuzz/corpus/<target> are
# read, never written), crashes to fuzz/artifacts/<target>, logs to fuzz/work/logs.
# Exit status: 0 when no target crashed, 1 when one did, 2 on a usage or build error.
#
# Environment: CARGO_TARGET_DIR (where to build), LOCI_FUZZ_TIMEOUT (seconds one input may
# take before it counts as a finding, default 20), LOCI_FUZZ_SANITIZER (default address).
set -uo pipefail

here=$(cd "$(dirname "$0")" && pwd)
secs=${1:-60}
if ! [[ $secs =~ ^[0-9]+$ ]]; then
    echo "usage: $0 [SECONDS_PER_TARGET] [TARGETS...]" >&2
    exit 2
fi
shift $(($# > 0 ? 1 : 0))
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
    targets=(json slvs c_abi resolve sketch_file assembly_file)
fi
timeout=${LOCI_FUZZ_TIMEOUT:-20}
sanitizer=${LOCI_FUZZ_SANITIZER:-address}

if ! cargo +nightly fuzz --version >/dev/null 2>&1; then
    echo "cargo-fuzz is missing; installing it (a few minutes)" >&2
    cargo install cargo-fuzz || exit 2
fi

cd "$here" || exit 2
mkdir -p work/logs
for t in "${targets[@]}"; do
    if [ ! -f "fuzz_targets/$t.rs" ]; then
        echo "no fuzz target '$t' (have: $(ls fuzz_targets | sed 's/\.rs$//' | tr '\n' ' '))" >&2
        exit 2
    fi
done
echo "building: ${targets[*]}" >&2
for t in "${targets[@]}"; do
    cargo +nightly fuzz build -s "$sanitizer" "$t" >&2 || exit 2
done

# The longest input each target reads: JSON, sketch, assembly and .slvs files of a few pages; the structured
# targets use a few hundred bytes.
max_len() {
    case $1 in
        json | slvs | sketch_file | assembly_file) echo 16384 ;;
        c_abi) echo 4096 ;;
        *) echo 1024 ;;
    esac
}

status=0
summary=""
for t in "${targets[@]}"; do
    mkdir -p "work/corpus/$t" "corpus/$t" "artifacts/$t"
    stamp=$(mktemp)
    log="work/logs/$t.log"
    args=(-max_total_time="$secs" -rss_limit_mb=4096 -timeout="$timeout"
        -max_len="$(max_len "$t")" -print_final_stats=1)
    if [ -f "dict/$t.dict" ]; then
        args+=(-dict="dict/$t.dict")
    fi
    echo "fuzzing $t for ${secs}s" >&2
    cargo +nightly fuzz run -s "$sanitizer" "$t" "work/corpus/$t" "corpus/$t" -- "${args[@]}" \
        >"$log" 2>&1
    rc=$?
    execs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | tail -1 | grep -o '[0-9]*$')
    rate=$(grep -oE 'stat::average_exec_per_sec: *[0-9]+' "$log" | tail -1 | grep -o '[0-9]*$')
    # A crash ends the run before all the final stats: take the last status line.
    last=$(grep -E '^#[0-9]+' "$log" | tail -1)
    if [ -z "$execs" ]; then
        execs=$(echo "$last" | grep -oE '^#[0-9]+' | tr -d '#')
    fi
    if [ -z "$rate" ] || [ "$rate" = 0 ]; then
        rate=$(echo "$last" | grep -oE 'exec/s: [0-9]+' | grep -oE '[0-9]+')
    fi
    corpus=$(find "work/corpus/$t" "corpus/$t" -type f | wc -l)
    findings=$(find "artifacts/$t" -type f -newer "$stamp" | sort)
    rm -f "$stamp"
    line=$(printf '%-8s executions %-10s exec/s %-7s corpus %-6s findings %s' \
        "$t" "${execs:-?}" "${rate:-?}" "$corpus" "$(echo -n "$findings" | grep -c . || true)")
    summary+="$line"$'\n'
    if [ -n "$findings" ]; then
        status=1
        for f in $findings; do
            summary+="    $f"$'\n'
            msg=$(grep -m1 -E "panicked at|ERROR: libFuzzer|SUMMARY:" "$log")
            [ -n "$msg" ] && summary+="      $msg"$'\n'
        done
        summary+="    reproduce: cargo +nightly fuzz run $t <file>; log: fuzz/$log"$'\n'
    elif [ $rc -ne 0 ]; then
        status=1
        summary+="    libFuzzer exited with status $rc without an artifact; see fuzz/$log"$'\n'
    fi
done
printf '%s' "$summary"
exit $status
