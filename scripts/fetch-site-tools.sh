#!/usr/bin/env bash
# Installs what the site tests check `rosarch site` with into <dest>: puppeteer-core (drives
# Debian's chromium), vnu-jar (the Nu HTML Checker, run with Java) and axe-core, at the
# versions and integrity hashes pinned in tests/support/site/package-lock.json, from the npm
# registry. Nothing is committed.
set -euo pipefail
dest=${1:?usage: fetch-site-tools.sh <dest-dir>}
src="$(cd "$(dirname "$0")/.." && pwd)/tests/support/site"
mkdir -p "$dest"
sum=$(cat "$src/package.json" "$src/package-lock.json" | sha256sum | cut -d' ' -f1)
if [ -f "$dest/.sha256" ] && [ "$(cat "$dest/.sha256")" = "$sum" ] &&
  [ -d "$dest/node_modules/puppeteer-core" ]; then
  exit 0
fi
echo "fetch-site-tools: npm ci (puppeteer-core, vnu-jar, axe-core)"
cp "$src/package.json" "$src/package-lock.json" "$dest/"
# --ignore-scripts: puppeteer-core downloads no browser anyway; the tests use Debian's chromium.
(cd "$dest" && npm ci --no-audit --no-fund --ignore-scripts --loglevel=error)
echo "$sum" > "$dest/.sha256"
