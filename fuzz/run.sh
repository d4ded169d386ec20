#!/usr/bin/env bash
# Fuzz the scene pipeline (fuzz_targets/scene.rs: liftoff::load → liftoff::run) for a fixed time budget.
#
#   fuzz/run.sh [SECONDS]        default 600
#
# Environment:
#   FUZZ_JOBS      parallel fuzzing jobs (default 1; the machine is shared)
#   FUZZ_TIMEOUT   per-input timeout in seconds (default 60: since the target runs whole analyses,
#                  valid coarse Pasternak scenes take 11–67 s under ASan on a shared CPU at nice
#                  19, about 1 s in release — tests/fuzz_regressions.rs; a real hang still trips it)
#   FUZZ_RSS_MB    RSS limit in MiB (default 4096)
#   FUZZ_SANITIZER address (default) or none; changing it rebuilds every dependency
#
# Works on stable Rust: RUSTC_BOOTSTRAP=1 lets cargo-fuzz pass its nightly-only flags
# (-Zsanitizer=address, -Cpasses=sancov-module, ...). The build also turns on debug assertions
# and overflow checks (`--debug-assertions`). Installs cargo-fuzz from crates.io when missing.
#
# Seeds (fuzz/seeds, committed) are copied into fuzz/corpus/scene (ignored) before the run; the
# corpus grows across runs. Crashes, timeouts and OOMs land in fuzz/artifacts/scene (cargo-fuzz's
# -artifact_prefix). Exits
# non-zero when libFuzzer reports one (or fails in any other way).
set -euo pipefail

SECONDS_BUDGET="${1:-600}"
if ! [[ "$SECONDS_BUDGET" =~ ^[0-9]+$ ]] || [ "$SECONDS_BUDGET" -lt 1 ]; then
    echo "usage: $0 [SECONDS]   (a positive whole number of seconds, default 600)" >&2
    exit 2
fi
JOBS="${FUZZ_JOBS:-1}"
TIMEOUT="${FUZZ_TIMEOUT:-60}"
RSS_MB="${FUZZ_RSS_MB:-4096}"
SANITIZER="${FUZZ_SANITIZER:-address}"
TARGET=scene

FUZZ_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
CORPUS="$FUZZ_DIR/corpus/$TARGET"
ARTIFACTS="$FUZZ_DIR/artifacts/$TARGET"
LOG="$FUZZ_DIR/artifacts/$TARGET-run.log"

export RUSTC_BOOTSTRAP=1
# Flags shared by build and run, so the run does not rebuild.
CARGO_FUZZ_FLAGS=(--sanitizer "$SANITIZER" --debug-assertions --release)

if ! cargo fuzz --version >/dev/null 2>&1; then
    echo "== installing cargo-fuzz from crates.io"
    cargo install cargo-fuzz --locked
fi

mkdir -p "$CORPUS" "$ARTIFACTS"
cp "$FUZZ_DIR"/seeds/*.toml "$CORPUS"/
# Artifacts already present are reported as old, not as found by this run.
before="$(find "$ARTIFACTS" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' \) | sort)"

# Run from the artifacts directory (ignored by git): with -jobs, libFuzzer writes fuzz-N.log
# files to the working directory.
cd "$ARTIFACTS"
rm -f "$ARTIFACTS"/fuzz-*.log
echo "== building fuzz target '$TARGET' ($(cargo fuzz --version))"
cargo fuzz build --fuzz-dir "$FUZZ_DIR" "${CARGO_FUZZ_FLAGS[@]}" "$TARGET"

echo "== fuzzing '$TARGET' for ${SECONDS_BUDGET} s (sanitizer ${SANITIZER}, jobs ${JOBS}, timeout ${TIMEOUT} s, rss ${RSS_MB} MiB); log: $LOG"
start="$(date -u +%Y-%m-%dT%H:%M:%SZ)"
t0="$(date +%s)"
LIBFUZZER_ARGS=(
    -max_total_time="$SECONDS_BUDGET"
    -timeout="$TIMEOUT"
    -rss_limit_mb="$RSS_MB"
    -max_len=8192
    -dict="$FUZZ_DIR/scene.dict"
    -print_final_stats=1
)
if [ "$JOBS" -gt 1 ]; then
    LIBFUZZER_ARGS+=(-jobs="$JOBS" -workers="$JOBS")
fi
set +e
cargo fuzz run --fuzz-dir "$FUZZ_DIR" "${CARGO_FUZZ_FLAGS[@]}" "$TARGET" "$CORPUS" -- "${LIBFUZZER_ARGS[@]}" 2>&1 | tee "$LOG"
status="${PIPESTATUS[0]}"
set -e
t1="$(date +%s)"

after="$(find "$ARTIFACTS" -maxdepth 1 -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' \) | sort)"
new="$(comm -13 <(printf '%s\n' "$before" | sed '/^$/d') <(printf '%s\n' "$after" | sed '/^$/d'))"
n_new="$(printf '%s\n' "$new" | sed '/^$/d' | wc -l)"
# With -jobs the statistics are in fuzz-N.log files; otherwise in the log above.
stats_src=("$LOG")
if [ "$JOBS" -gt 1 ]; then stats_src=("$ARTIFACTS"/fuzz-*.log); fi
# (grep finds nothing when libFuzzer stopped early: `|| true` keeps pipefail from exiting.)
execs="$({ grep -h 'stat::number_of_executed_units' "${stats_src[@]}" 2>/dev/null || true; } | awk '{s += $2} END {print s + 0}')"
rate="$({ grep -h 'stat::average_exec_per_sec' "${stats_src[@]}" 2>/dev/null || true; } | awk '{s += $2} END {print s + 0}')"
peak="$({ grep -h 'stat::peak_rss_mb' "${stats_src[@]}" 2>/dev/null || true; } | awk '$2 > m {m = $2} END {print m + 0}')"
cov="$({ grep -ho 'cov: [0-9]*' "${stats_src[@]}" 2>/dev/null || true; } | awk '$2 > m {m = $2} END {print m + 0}')"
corpus_n="$(find "$CORPUS" -maxdepth 1 -type f | wc -l)"

echo
echo "== fuzz summary"
echo "target:           $TARGET"
echo "started (UTC):    $start"
echo "wall time:        $((t1 - t0)) s (budget ${SECONDS_BUDGET} s)"
echo "executions:       $execs (${rate}/s)"
echo "coverage (edges): $cov"
echo "peak RSS:         ${peak} MiB"
echo "corpus size:      $corpus_n files in $CORPUS"
echo "new artifacts:    $n_new"
if [ "$n_new" -gt 0 ]; then
    printf '  %s\n' $new
    echo "reproduce: RUSTC_BOOTSTRAP=1 cargo fuzz run --fuzz-dir $FUZZ_DIR ${CARGO_FUZZ_FLAGS[*]} $TARGET <artifact>"
    echo "minimise:  RUSTC_BOOTSTRAP=1 cargo fuzz tmin --fuzz-dir $FUZZ_DIR ${CARGO_FUZZ_FLAGS[*]} $TARGET <artifact>"
fi
echo "libFuzzer exit:   $status"

if [ "$status" -ne 0 ] || [ "$n_new" -gt 0 ]; then
    echo "RESULT: FAIL (libFuzzer reported a crash, timeout or OOM)" >&2
    exit 1
fi
echo "RESULT: OK (no crashes)"
