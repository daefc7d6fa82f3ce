#!/usr/bin/env bash
# The README's first command: installs the tools the demo runs where they are missing (scripts/install-tools.sh, the
# script the test command uses too: Debian's packages, the pinned PyPI venv under target/), builds bumprtl, then runs
# the demo with every path (the f64 ideal, the bit-exact model, rust-hdl, Verilator, synthesis on the ECP5). Arguments
# go to `bumprtl demo` (`bash demo.sh --help`); the page is out/demo/index.html. Each phase's time is said as it ends.
set -euo pipefail
cd "$(dirname "$0")"
t=$SECONDS
bash scripts/install-tools.sh
echo "set-up: $((SECONDS - t)) s"
t=$SECONDS
cargo build --release --quiet
echo "build: $((SECONDS - t)) s"
exec target/release/bumprtl demo "$@"
