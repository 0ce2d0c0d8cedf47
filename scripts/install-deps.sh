#!/usr/bin/env bash
# Installs what building and testing Thyrix needs on Debian 12 (bookworm).
set -euo pipefail
packages=(cmake g++ make libgtest-dev libbenchmark-dev doxygen)
# The Python package (python/) and its tests and examples.
packages+=(pybind11-dev python3-dev python3-numpy python3-pytest python3-deap python3-matplotlib)
# MPI: evaluation over the ranks of a job (thyrix::EvolutionMpi), its tests, and Python's mpi4py.
packages+=(openmpi-bin libopenmpi-dev python3-mpi4py)
# clang: a second compiler (the float build) and libFuzzer with its sanitizers (fuzz/).
packages+=(clang-14 libclang-rt-14-dev libfuzzer-14-dev)
# The GUI: wxWidgets to build it; Xvfb, xdotool and python3 for its tests (tests/gui/).
if [ "${THYRIX_WITH_GUI:-0}" = 1 ]; then packages+=(libwxgtk3.2-dev xvfb xdotool python3); fi
missing=()
for p in "${packages[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
sudo=""
if [ "$(id -u)" != 0 ]; then sudo=sudo; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
