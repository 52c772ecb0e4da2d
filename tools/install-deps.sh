#!/bin/sh
# Installs the Debian packages named on the command line that are not installed yet.
# Uses apt-get as root, or through sudo; says what to do when neither is possible.
set -eu
missing=""
for pkg in "$@"; do
    status=$(dpkg-query -W -f='${db:Status-Status}' "$pkg" 2>/dev/null || true)
    [ "$status" = "installed" ] || missing="$missing $pkg"
done
[ -z "$missing" ] && exit 0

echo "mirage: installing Debian packages:$missing"
if [ "$(id -u)" -eq 0 ]; then
    run=""
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    run="sudo"
elif command -v sudo >/dev/null 2>&1; then
    run="sudo"
    echo "mirage: sudo will ask for your password to install them."
else
    echo "mirage: cannot install:$missing" >&2
    echo "mirage: run as root, install sudo, or install them by hand:" >&2
    echo "    apt-get install$missing" >&2
    exit 1
fi
export DEBIAN_FRONTEND=noninteractive
$run apt-get update -q
# shellcheck disable=SC2086
$run apt-get install -y -q --no-install-recommends $missing
