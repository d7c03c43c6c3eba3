#!/bin/sh
# The design report of examples/delta-60-physical.toml rendered by a real
# browser (headless Chromium; Debian: apt-get install -y chromium) into
# docs/figures/design-report.png: the check that a user's own design gets
# a page like the note's (`delta-stability report CONFIG`).
#
#   scripts/screenshot-design-report.sh [OUT.png]
#
# Run from anywhere; writes the report into a temporary directory.
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
png=${1:-$root/docs/figures/design-report.png}
case $png in /*) ;; *) png=$(pwd)/$png ;; esac
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$root"
cargo run -q --release -p delta-stability -- \
    report examples/delta-60-physical.toml --out "$dir/report"
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars \
    --screenshot="$png" --window-size=1200,3000 \
    "file://$dir/report/index.html"
ls -l "$png"
