#!/usr/bin/env bash
# apt-install-missing.sh LABEL PACKAGE...
# Installs those Debian packages that are not installed yet; `apt-get
# update` runs first whenever something is missing (package lists may be
# stale or empty). Uses sudo when not root. LABEL prefixes the messages.
set -euo pipefail
label=$1
shift
missing=()
for p in "$@"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
if [ ${#missing[@]} -eq 0 ]; then
  echo "$label: all $# packages present"
else
  echo "$label: installing ${missing[*]}"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
