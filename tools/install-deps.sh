#!/usr/bin/env bash
# Installs the Debian packages scalecert needs, only those that are missing.
set -euo pipefail
PKGS=(build-essential cmake pkg-config libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev
      libboost-test-dev nlohmann-json3-dev libcli11-dev libccd-dev libfcl-dev libbullet-dev libmujoco-dev libgtest-dev python3 python3-matplotlib
      python3-dev pybind11-dev python3-numpy python3-pytest python3-venv libopenmpi-dev openmpi-bin
      clang-format libjs-three python3-pil chromium ninja-build)
missing=()
for p in "${PKGS[@]}" "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
