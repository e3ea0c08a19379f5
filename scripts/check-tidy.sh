#!/usr/bin/env bash
# Runs clang-tidy with the repository's .clang-tidy over our own sources (model/, document/,
# widgets/, app/, tools/; not the tests, not the generated moc files), from the compilation
# database of a configured build.
#
#   scripts/check-tidy.sh [build dir]          what changed since the tidy base (CI)
#   scripts/check-tidy.sh --all [build dir]    every file (the scheduled full run)
#   scripts/check-tidy.sh --list [build dir]   only say what would be checked, and why
#
# The tidy base is the last commit at which a full run passed: ROSARCH_TIDY_BASE if set, else the
# commit in .ci/tidy-base. Without --all only the .cpp files that a change since the base can
# reach are checked: the changed .cpp files, and those that include a changed header directly or
# through other headers (their #include lines, and the build's ninja dependencies when it has
# been built). Every file is checked instead when there is no usable base (none, not a commit of
# this clone, not an ancestor of HEAD), or when what decides how a file is compiled or checked
# changed since it: a .clang-tidy, a CMakeLists.txt, cmake/, CMakePresets.json or this script.
# ROSARCH_TIDY_ALL=1 is the same as --all. The default build dir is build/.
set -euo pipefail
cd "$(dirname "$0")/.."
all=${ROSARCH_TIDY_ALL:-0}
list=0
build_dir=
for arg in "$@"; do
  case "$arg" in
    --all) all=1 ;;
    --list) list=1 ;;
    -h|--help) sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "check-tidy: unknown option $arg (usage: scripts/check-tidy.sh [--all] [--list] [build dir])" >&2; exit 2 ;;
    *) build_dir=$arg ;;
  esac
done
build_dir=${build_dir:-build}
if [ ! -f "$build_dir/compile_commands.json" ]; then
  echo "check-tidy: $build_dir/compile_commands.json not found; configure first (cmake --preset dev)" >&2
  exit 2
fi
jobs=$(nproc 2>/dev/null || echo 2)
all_files='^'"$PWD"'/(model|document|widgets|app|tools)/.*\.cpp$'

# Decide what to check: writes the regex of the files for run-clang-tidy into $selection (empty
# when nothing needs checking) and says on stdout what is checked and why.
selection=$(mktemp)
trap 'rm -f "$selection"' EXIT
python3 - "$PWD" "$build_dir" "$all" "$all_files" "$selection" <<'EOF'
import json, os, re, shlex, subprocess, sys

root, build_dir, want_all, all_files, out = sys.argv[1], sys.argv[2], sys.argv[3] == "1", sys.argv[4], sys.argv[5]
tidied = re.compile(all_files)
# What decides how every file is compiled or which checks run: a change to it checks everything.
config = re.compile(r"(^|/)\.clang-tidy$|(^|/)CMakeLists\.txt$|^cmake/|^CMakePresets\.json$|^scripts/check-tidy\.sh$")
searched = ("model", "document", "widgets", "app", "tools")


def git(*args):
    return subprocess.run(["git", *args], cwd=root, capture_output=True, text=True)


def rel(path):
    return os.path.relpath(path, root)


def absolute(entry):
    return os.path.normpath(os.path.join(entry["directory"], entry["file"]))


database = json.load(open(os.path.join(build_dir, "compile_commands.json")))
files = sorted({absolute(e) for e in database if tidied.search(absolute(e))})


def check_all(reason):
    print(f"check-tidy: checking all {len(files)} files ({reason})")
    with open(out, "w") as f:
        f.write(all_files)
    sys.exit(0)


if want_all:
    check_all("asked for a full run")

base, origin = os.environ.get("ROSARCH_TIDY_BASE", "").strip(), "ROSARCH_TIDY_BASE"
if not base:
    origin = ".ci/tidy-base"
    try:
        base = open(os.path.join(root, ".ci/tidy-base")).read().split()[0]
    except (OSError, IndexError):
        check_all("no tidy base (.ci/tidy-base is missing and ROSARCH_TIDY_BASE is not set)")
commit = git("rev-parse", "--verify", "--quiet", base + "^{commit}")
if commit.returncode != 0:
    check_all(f"the tidy base {base} ({origin}) is not a commit of this clone")
commit = commit.stdout.strip()
short = git("rev-parse", "--short", commit).stdout.strip()
if git("merge-base", "--is-ancestor", commit, "HEAD").returncode != 0:
    check_all(f"the tidy base {short} ({origin}) is not an ancestor of HEAD")

# Changed since the base: committed, uncommitted and new files alike.
diff = git("diff", "--name-only", "--no-renames", commit, "--")
untracked = git("ls-files", "--others", "--exclude-standard")
if diff.returncode != 0 or untracked.returncode != 0:
    check_all(f"git diff against the tidy base {short} failed: {diff.stderr.strip()}")
changed = sorted(set(diff.stdout.split("\n") + untracked.stdout.split("\n")) - {""})
said = f"base {short} ({origin})"
configs = [p for p in changed if config.search(p)]
if configs:
    more = f" and {len(configs) - 3} more" if len(configs) > 3 else ""
    check_all(f"{', '.join(configs[:3])}{more} changed since the {said}")

changed_abs = {os.path.realpath(os.path.join(root, p)) for p in changed}
why = {}  # checked file -> reason


def reach(path, cause):
    if path not in why:
        why[path] = cause


for f in files:
    if os.path.realpath(f) in changed_abs:
        reach(f, "changed")

# Includers of a changed header, through every #include line of our sources. Each rosarch
# include names its library folder ("launch/launchexecutor.h", relative to model/ or to the top
# folder); tools name their own headers bare, relative to the including file.
known = set(git("ls-files", "--cached", "--others", "--exclude-standard", "--", *searched).stdout.split("\n")) - {""}
include_line = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]', re.M)
# A name found none of these ways (a header of another tool's folder, which its target exports)
# stands for every file of that name.
existing = known | set(changed)
by_name = {}
for path in existing:
    by_name.setdefault(os.path.basename(path), set()).add(path)
includers = {}  # header (relative) -> files that include it
for path in known:
    if not path.endswith((".h", ".hpp", ".cpp", ".cc", ".inc")):
        continue
    try:
        text = open(os.path.join(root, path), errors="replace").read()
    except OSError:
        continue
    for name in include_line.findall(text):
        candidates = {os.path.normpath(c) for c in (os.path.join(os.path.dirname(path), name), "model/" + name, name)}
        found = candidates & existing
        if not found:
            found = {p for p in by_name.get(os.path.basename(name), ()) if p.endswith("/" + name)}
        for header in found:
            includers.setdefault(header, set()).add(path)
tidied_rel = {rel(f): f for f in files}
for header in changed:
    seen, todo = {header}, [header]
    while todo:
        for includer in includers.get(todo.pop(), ()):
            if includer not in seen:
                seen.add(includer)
                todo.append(includer)
                if includer in tidied_rel:
                    reach(tidied_rel[includer], f"includes {header}")

# The build's own record of every header each object read, when it has been built with Ninja:
# it also knows generated headers and includes the scan above cannot name.
deps_note = "#include lines"
if os.path.isfile(os.path.join(build_dir, ".ninja_deps")):
    objects = {}
    for e in database:
        if not tidied.search(absolute(e)):
            continue
        args = e.get("arguments") or shlex.split(e["command"])
        if "-o" in args:
            objects[os.path.normpath(args[args.index("-o") + 1])] = absolute(e)
    deps = subprocess.run(["ninja", "-C", build_dir, "-t", "deps"], capture_output=True, text=True)
    if deps.returncode == 0:
        deps_note += " and ninja's dependencies"
        source = None
        for line in deps.stdout.split("\n"):
            if line and not line[0].isspace():
                source = objects.get(os.path.normpath(line.split(": #deps")[0]))
            elif source and line.strip():
                header = os.path.realpath(os.path.join(build_dir, line.strip()))
                if header in changed_abs and header != os.path.realpath(source):
                    reach(source, f"includes {rel(header)}")


def files_count(n):
    return f"{n} file" if n == 1 else f"{n} files"


print(f"check-tidy: {files_count(len(changed))} changed since the {said} (reach through {deps_note})")
unknown = [p for p in changed if tidied.search(os.path.join(root, p)) and os.path.isfile(os.path.join(root, p))
           and os.path.join(root, p) not in files]
if unknown:
    print(f"check-tidy: not in {build_dir}/compile_commands.json, so not checked (configure again): {', '.join(unknown)}")
if not why:
    print(f"check-tidy: no file to check: nothing changed since the {said} reaches a checked .cpp")
    open(out, "w").close()
    sys.exit(0)
print(f"check-tidy: checking {len(why)} of {files_count(len(files))} (scripts/check-tidy.sh --all checks every one):")
for f in sorted(why):
    print(f"  {rel(f)}: {why[f]}")
with open(out, "w") as f:
    f.write("^(" + "|".join(re.escape(p) for p in sorted(why)) + ")$")
EOF
regex=$(cat "$selection")
[ -n "$regex" ] && [ "$list" = 0 ] || exit 0
run-clang-tidy -quiet -p "$build_dir" -j "$jobs" "$regex"
