#!/usr/bin/env bash
# The README's first command: installs the tools the demo runs where they are missing (scripts/install-tools.sh, the
# script the test command uses too: Debian's packages, the pinned PyPI venv under target/), builds bumprtl, then runs
# the demo with every path (the f64 ideal, the bit-exact model, rust-hdl, Verilator, synthesis on the UP5K and the
# ECP5). Arguments go to `bumprtl demo` (`bash demo.sh --help`); the page is out/demo/index.html.
set -euo pipefail
cd "$(dirname "$0")"
bash scripts/install-tools.sh
cargo build --release --quiet
exec target/release/bumprtl demo "$@"
