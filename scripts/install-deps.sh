#!/usr/bin/env bash
# Installs what insmc needs from Debian 12's archive, only what is missing.
# Idempotent and quiet on success; run as root (no sudo needed or used).
#   scripts/install-deps.sh          build + run dependencies
#   scripts/install-deps.sh --test   also GoogleTest, Random123 (test oracle),
#                                    Open MPI (the MPI build's tests), clang,
#                                    libFuzzer and ccache (scripts/fuzz.sh)
#   scripts/install-deps.sh --numpy  also NumPy with OpenBLAS (the reference
#                                    study of scripts/bench-numpy.sh)
set -euo pipefail

packages=(g++ cmake make libeigen3-dev libtbb-dev libboost-program-options-dev libboost-dev libfmt-dev nlohmann-json3-dev)
# gnuplot renders the plots of `insmc run` (envelope, sweep) to SVG and PNG
# from the script insmc writes beside them (montecarlo/report/plot/gnuplot.h).
packages+=(gnuplot-nox)
if [[ " $* " == *" --numpy "* ]]; then
  packages+=(python3 python3-numpy libopenblas0-pthread)
fi
if [[ " $* " == *" --test "* ]]; then
  # openssh-client: Open MPI's mpirun refuses to start without an rsh/ssh agent,
  # even on one machine (Debian only recommends it).
  packages+=(libgtest-dev librandom123-dev openmpi-bin libopenmpi-dev openssh-client)
  # tests/python: the Python entry (apps/python/insmc.py), standard library only.
  packages+=(python3)
  # scripts/fuzz.sh: clang with libFuzzer (libclang-rt-14-dev), builds through ccache.
  packages+=(clang libclang-rt-14-dev ccache)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

if [[ $(id -u) -ne 0 ]]; then
  echo "install-deps: missing Debian packages: ${missing[*]}; run this script as root to install them" >&2
  exit 1
fi
log=$(mktemp)
export DEBIAN_FRONTEND=noninteractive
if ! { apt-get update -q && apt-get install -y -q --no-install-recommends "${missing[@]}"; } >"$log" 2>&1; then
  cat "$log" >&2
  echo "install-deps: apt-get failed installing: ${missing[*]}" >&2
  exit 1
fi
rm -f "$log"
