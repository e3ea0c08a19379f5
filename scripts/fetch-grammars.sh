#!/usr/bin/env bash
# Fetches the tree-sitter grammars rosarch compiles in, at pinned versions, from the npm
# registry, checks their sha256 and unpacks them into the build tree. Nothing is committed.
set -euo pipefail
dest=${1:?usage: fetch-grammars.sh <dest-dir>}
mkdir -p "$dest"
registry=${NPM_REGISTRY:-https://registry.npmjs.org}
# name version sha256 (language ABI 14, compatible with the tree-sitter 0.20.7 runtime)
grammars=(
  "tree-sitter-python 0.23.6 aab5b860d93dbf84b37fed532f7dacc0468ede5387d0c74911d68f964287662a"
  "tree-sitter-cpp 0.23.4 615d152f70e7a6bed8f15a93c3c0c264c40dc71c1b6a1445646fff9439e776bc"
)
for g in "${grammars[@]}"; do
  read -r name version sum <<<"$g"
  dir="$dest/$name"
  if [ -f "$dir/.sha256" ] && [ "$(cat "$dir/.sha256")" = "$sum" ] && [ -f "$dir/src/parser.c" ]; then
    continue
  fi
  tgz="$dest/$name-$version.tgz"
  echo "fetch-grammars: $name $version"
  curl -sSfL --retry 3 -o "$tgz.part" "$registry/$name/-/$name-$version.tgz"
  actual=$(sha256sum "$tgz.part" | cut -d' ' -f1)
  if [ "$actual" != "$sum" ]; then
    echo "fetch-grammars: checksum mismatch for $name $version (got $actual)" >&2
    rm -f "$tgz.part"; exit 1
  fi
  mv "$tgz.part" "$tgz"
  rm -rf "$dir"; mkdir -p "$dir"
  tar -xzf "$tgz" -C "$dir" --strip-components=1 package/src package/LICENSE 2>/dev/null \
    || tar -xzf "$tgz" -C "$dir" --strip-components=1 package/src
  echo "$sum" > "$dir/.sha256"
done
