#!/usr/bin/env bash
# Installs what dmhs needs (when missing), then configures and builds it.
# Sourced by scripts/run.sh and scripts/test.sh; usable alone: scripts/setup.sh
# Environment: DMHS_BUILD_DIR (default: build), DMHS_BUILD_TYPE (default: Release).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${DMHS_BUILD_DIR:-$repo/build}"

# Debian packages: compilers, MPI, PETSc 3.18, parallel HDF5, METIS, GSL, cmocka,
# and Debian's own python3 with numpy/h5py/matplotlib for scripts/post and tests;
# clang-format for the style check (ctest format_check); MkDocs for the
# documentation site (scripts/docs.sh, ctest doc_site).
packages=(build-essential cmake pkg-config openmpi-bin libopenmpi-dev petsc-dev
          libhdf5-openmpi-dev libmetis-dev libgsl-dev libcmocka-dev clang-format
          python3 python3-numpy python3-h5py python3-matplotlib mkdocs python3-pymdownx)
"$repo/scripts/debian_packages.sh" setup "${packages[@]}"

cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE="${DMHS_BUILD_TYPE:-Release}" >/dev/null
cmake --build "$build" --parallel "$(nproc)"
