#!/usr/bin/env bash
# Vendors the JavaScript library that report.html inlines (Leaflet, pinned with its integrity
# hash in export/web/package-lock.json) into DEST (the build calls it with build/vendor), so the
# report opens offline: nothing is fetched when the page is viewed. Quiet when DEST is up to date.
# Usage: scripts/vendor_js.sh DEST
set -euo pipefail
DEST="${1:?usage: vendor_js.sh DEST}"
mkdir -p "$DEST"
DEST="$(cd "$DEST" && pwd)"
WEB="$(cd "$(dirname "$0")/../export/web" && pwd)"
if ! command -v npm >/dev/null 2>&1; then
  echo "vendor_js: npm not found (scripts/setup.sh installs nodejs and npm)" >&2
  exit 1
fi
if [ -f "$DEST/node_modules/leaflet/dist/leaflet.js" ] && cmp -s "$WEB/package-lock.json" "$DEST/vendored.lock"; then
  exit 0
fi
cp "$WEB/package.json" "$WEB/package-lock.json" "$DEST/"
(cd "$DEST" && npm ci --ignore-scripts --no-audit --no-fund --loglevel=error >/dev/null)
test -f "$DEST/node_modules/leaflet/dist/leaflet.js"
test -f "$DEST/node_modules/leaflet/dist/leaflet.css"
cp "$WEB/package-lock.json" "$DEST/vendored.lock"  # what is installed (npm may rewrite its lock)
echo "vendor_js: Leaflet $(node -p "require('$DEST/node_modules/leaflet/package.json').version") in $DEST"
