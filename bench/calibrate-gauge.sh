#!/usr/bin/env bash
# The gauge's time at the speed of 2026-11-27 (REFERENCE in
# benches/work_precision/gauge.rs): the fixed workload of
# benches/work_precision/frozen.rs run in turn with the library four-bar's
# kinetostatics as the code of that day has it (14e2c9d, the code issue
# 50's targets were set on), which took 1.37 µs a position then. Prints
# each pair and the median of gauge × 1.37 / four-bar; the same read
# against the library cam with friction (3.06 µs that day, in the
# four-bar's section) and K1 (1.07 µs, in another section) as checks.
# Needs the repository's history (not a shallow clone); checks 14e2c9d out
# in target/calibrate-then/tree and builds it there (about 5 minutes on two
# cores the first time). Usage: bench/calibrate-gauge.sh [PAIRS]
set -euo pipefail
pairs=${1:-15}
root=$(git rev-parse --show-toplevel)
then_dir=$(mktemp -d)
then_target="$root/target/calibrate-then"
tree="$then_target/tree"
git -C "$root" worktree remove --force "$tree" >/dev/null 2>&1 || true
trap 'git -C "$root" worktree remove --force "$tree" >/dev/null 2>&1 || true; rm -rf "$then_dir"' EXIT
git -C "$root" worktree add --detach "$tree" 14e2c9d >/dev/null
cp "$root/bench/calibrate/then.rs" "$tree/examples/calibrate_then.rs"
(cd "$tree" && CARGO_TARGET_DIR="$then_target" cargo build --quiet --profile bench --example calibrate_then)
(cd "$root" && cargo bench --quiet --bench work_precision --no-run)
now() { (cd "$root" && cargo bench --quiet --bench work_precision -- gauge 2>/dev/null); }
for _ in $(seq "$pairs"); do
  echo "$("$then_target/release/examples/calibrate_then") | $(now)"
done | tee "$then_dir/pairs"
ratios="$then_dir/ratios"
awk '{ print $18 * 1.37 / $2, $18 * 3.06 / $12, $18 * 1.07 / $7 }' "$then_dir/pairs" >"$ratios"
median() { sort -g | awk '{ v[NR] = $1 } END { printf "%.4f", v[int((NR + 1) / 2)] }'; }
echo "gauge at the speed of 2026-11-27: $(cut -d' ' -f1 "$ratios" | median) µs a position by the four-bar" \
  "(median of $pairs pairs), $(cut -d' ' -f2 "$ratios" | median) by the cam, $(cut -d' ' -f3 "$ratios" | median) by K1"
