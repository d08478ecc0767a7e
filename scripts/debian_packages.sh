#!/usr/bin/env bash
# Installs the Debian packages given that are missing (as root, with apt-get);
# otherwise lists them and exits 1. Used by scripts/setup.sh and scripts/docs.sh.
#   scripts/debian_packages.sh WHO PACKAGE...    (WHO prefixes the messages)
set -euo pipefail
who="${1:?usage: debian_packages.sh WHO PACKAGE...}"
shift
missing=()
for p in "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
if [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null; then
  echo "$who: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
else
  echo "$who: missing Debian packages: ${missing[*]}" >&2
  echo "$who: install them (as root: apt-get install ${missing[*]}) and run again" >&2
  exit 1
fi
