#!/usr/bin/env bash
# Makes the book's committed figures (book/src/images/*.png) with the
# release binary, from the list in tools/figures/figures.txt.
# Usage: bash tools/figures/make_figures.sh [OUT_DIR]   (default: book/src/images)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="${1:-$root/book/src/images}"
mkdir -p "$out"
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
bin="$root/target/release/pendulum"
while read -r name args; do
  case "$name" in ''|'#'*) continue ;; esac
  # shellcheck disable=SC2086 # the arguments are words
  "$bin" $args --plot "$out/$name" >/dev/null
  echo "wrote $out/$name"
done < "$root/tools/figures/figures.txt"
