#!/usr/bin/env bash
# Installs every build and test dependency of crux from Debian packages.
# Idempotent: packages already present are skipped, so both README commands can call it.
set -euo pipefail

packages=(
  build-essential cmake ninja-build git
  libeigen3-dev liburdfdom-dev libcli11-dev nlohmann-json3-dev libtomlplusplus-dev
  libfmt-dev libtbb-dev libabsl-dev libgtest-dev libgmock-dev libbenchmark-dev
  # Student's t distribution of the statistics (Boost.Math, header-only).
  libboost-math-dev
  # crux sweep across processes and machines (mpirun).
  libopenmpi-dev openmpi-bin
  # SHA-256 of the inputs a run records (libcrypto).
  libssl-dev
  # Independent kinematics reference for tests and the benchmark peer.
  liborocos-kdl-dev libkdl-parser-dev
  # Independent dynamics reference for tests (MuJoCo reads the body's URDF).
  libmujoco-dev
  # The linear programs of the static-equilibrium model (COIN-OR CLP).
  coinor-libclp-dev
  # check_urdf validates the body model in tests
  liburdfdom-tools
  # Fuzzing the readers: clang's libFuzzer (the fuzz preset); llvm-14's profile tools
  # measure what a harness reaches (scripts/fuzz_coverage.sh).
  clang libfuzzer-14-dev llvm-14
  # The one formatter of the C++ sources (.clang-format), checked by the tests.
  clang-format
  # The Python module, built for and tested with Debian's /usr/bin/python3; its examples
  # use pandas and matplotlib, crux.gym's rgb_array rendering matplotlib, and the vendored
  # Gymnasium 1.4.0 (../shared/third_party) that its tests run needs cloudpickle and
  # typing-extensions; the deep-RL baseline (examples/python/dqn_baseline.py) torch, its
  # statistics scipy.
  python3-dev pybind11-dev python3-numpy python3-pytest python3-pandas python3-matplotlib
  python3-cloudpickle python3-typing-extensions python3-torch python3-scipy
  # The report's browser tests run Debian's Chromium headless.
  chromium fonts-dejavu-core
)
# The report's scripts (three.js, esbuild, playwright-core) come from npm, pinned in
# web/package-lock.json. A machine with its own Node.js keeps it; otherwise Debian's.
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages already installed"
  bash "$here/setup_web.sh"
  exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
  echo "setup: missing packages (${missing[*]}); run this script as root" >&2
  exit 1
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
bash "$here/setup_web.sh"
