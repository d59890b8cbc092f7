#!/usr/bin/env bash
# Builds the page into web/dist/: the library compiled to WebAssembly
# (crates/pendulum-wasm) beside the page's own files. Needs Debian's
# rustc-web (its standard library's source is compiled for the browser,
# -Zbuild-std: rustup cannot fetch that target here); installs it when
# run as root and it is missing. The rustup toolchain stays first on PATH
# for the native build: this script calls Debian's by its full path.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ ! -x /usr/bin/cargo ] || [ ! -d /usr/lib/rustlib/src ] || ! command -v wasm-ld >/dev/null; then
  if [ "$(id -u)" = 0 ]; then
    apt-get update -qq
    DEBIAN_FRONTEND=noninteractive apt-get install -y -qq rustc-web cargo-web rust-web-src lld >/dev/null
  else
    echo "error: the WebAssembly build needs Debian's rustc-web, cargo-web, rust-web-src and lld:" >&2
    echo "  sudo apt-get install rustc-web cargo-web rust-web-src lld" >&2
    exit 2
  fi
fi
# (Its own target directory: the two toolchains' builds do not mix. The
# standard library without its default features: the backtrace's
# readers, which this target cannot use, are 10 CPU-s of the build.)
RUSTC=/usr/bin/rustc RUSTC_BOOTSTRAP=1 \
  CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_LINKER=wasm-ld \
  CARGO_PROFILE_RELEASE_DEBUG=false CARGO_PROFILE_RELEASE_STRIP=symbols CARGO_PROFILE_RELEASE_OPT_LEVEL=s \
  /usr/bin/cargo build --release --locked -q -p pendulum-wasm \
    --target wasm32-unknown-unknown -Zbuild-std=std,panic_abort -Zbuild-std-features= \
    --target-dir target/wasm
dist=web/dist
rm -rf "$dist"
mkdir -p "$dist"
cp target/wasm/wasm32-unknown-unknown/release/pendulum_wasm.wasm "$dist/pendulum.wasm"
cp web/index.html web/style.css web/app.js web/lab.js web/figure.js web/pendulum.js web/capture-worklet.js web/listener-worker.js \
  web/manifest.webmanifest web/icon.svg "$dist/"
# The cache is named after what it holds, so that a new build replaces it.
version=$(cat "$dist"/* | sha256sum | cut -c1-12)
sed "s/const VERSION = \"pendulum-dev\";/const VERSION = \"pendulum-$version\";/" web/sw.js > "$dist/sw.js"
echo "$dist/index.html"
