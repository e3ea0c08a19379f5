#!/usr/bin/env python3
"""Draws a random sample of a recovery's findings, per finding code, for judging by hand.

    findingsample.py <out>/diagnostics.json [--seed N] [--per-code 8] [--codes a,b]
                     [--workspace <ws>] [--counts] [--output table.md]

The precision rule of the architecture checks (blueprint §4) is measured this way: for every
code, a sample of at least `--per-code` findings (all of them where there are fewer) is drawn
with a fixed seed, so that a sample can be drawn again and compared. The table it writes has
an empty verdict column for the judge: `true`, `false-model` (the model is wrong or
incomplete) or `false-scope` (the finding is out of scope), and a column for the `file:line`
evidence of the verdict. With `--workspace`, each row quotes the source line it cites.

`--counts` prints only the number of findings per code. `--score table.md` reads a judged
table back and prints the precision per code.
"""
import argparse
import collections
import json
import random
import sys

# The codes of stage 3's architecture checks and of the parameter checks: the findings whose
# precision the blueprint measures. Other codes (syntax errors, skipped files) are facts about
# the input, not judgements about the architecture.
ARCHITECTURE_CODES = [
    "topic-unpublished", "topic-unheard", "remap-target-unused", "remap-unmatched",
    "type-mismatch", "duplicate-server", "unserved-client", "qos-incompatible",
    "duplicate-node-name", "process-renamed", "namespace-doubled", "duplicate-package",
    "parameter-undeclared", "parameter-type",
    "parameter-missing", "parameter-range",
]

VERDICTS = ("true", "false-model", "false-scope")


def cell(text):
    """One Markdown table cell: no pipes, no newlines, no control characters."""
    text = "".join(c if c.isprintable() else "\\x%02x" % ord(c) for c in str(text))
    return text.replace("|", "\\|")


def source_line(workspace, evidence):
    if not workspace or not evidence.get("file") or evidence.get("line", 0) < 1:
        return ""
    try:
        with open(f"{workspace}/{evidence['file']}", encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                if number == evidence["line"]:
                    return line.strip()[:160]
    except OSError:
        return ""
    return ""


def load(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)["diagnostics"]


def by_code(diagnostics, codes):
    groups = collections.OrderedDict((c, []) for c in codes)
    for d in diagnostics:
        if d["code"] in groups:
            groups[d["code"]].append(d)
    return groups


def sample(groups, seed, per_code):
    rng = random.Random(seed)
    out = []
    for code, found in groups.items():
        picked = found if len(found) <= per_code else rng.sample(found, per_code)
        out.extend((code, d) for d in picked)
    return out


def write_table(rows, groups, seed, workspace, stream):
    stream.write(f"Seed {seed}. Findings per code: "
                 + ", ".join(f"{c} {len(f)}" for c, f in groups.items() if f) + ".\n\n")
    stream.write("| # | code | finding | at | systems | source | verdict | evidence |\n")
    stream.write("|---|---|---|---|---|---|---|---|\n")
    for i, (code, d) in enumerate(rows, 1):
        e = d.get("evidence", {})
        at = f"{e.get('file', '')}:{e.get('line', 0)}"
        # how many systems report it, and the first of them, for the judge to start from
        contexts = d.get("contexts", [])
        systems = f"{len(contexts)}: {contexts[0]}" if contexts else ""
        stream.write(f"| {i} | {code} | {cell(d['message'])} | {cell(at)} | {systems} | "
                     f"`{cell(source_line(workspace, e))}` |  |  |\n")


def score(path):
    judged = collections.OrderedDict()
    with open(path, encoding="utf-8") as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
            if len(cells) < 8 or not cells[0].isdigit():
                continue
            code, verdict = cells[1], cells[6]
            counts = judged.setdefault(code, collections.Counter())
            counts[verdict if verdict in VERDICTS else "unjudged"] += 1
    for code, counts in judged.items():
        done = sum(counts[v] for v in VERDICTS)
        precision = f"{counts['true'] / done:.0%}" if done else "-"
        print(f"{code}: {counts['true']}/{done} true ({precision}); false-model "
              f"{counts['false-model']}, false-scope {counts['false-scope']}, unjudged "
              f"{counts['unjudged']}")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("diagnostics", nargs="?")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--per-code", type=int, default=8)
    p.add_argument("--codes", help="comma-separated codes (default: the architecture checks)")
    p.add_argument("--workspace", help="quote each finding's source line from this workspace")
    p.add_argument("--counts", action="store_true", help="only count findings per code")
    p.add_argument("--output", help="write the table here (default: standard output)")
    p.add_argument("--score", metavar="TABLE", help="print the precision of a judged table")
    args = p.parse_args()
    if args.score:
        score(args.score)
        return 0
    if not args.diagnostics:
        p.error("the diagnostics.json of a recovery is needed")
    codes = args.codes.split(",") if args.codes else ARCHITECTURE_CODES
    groups = by_code(load(args.diagnostics), codes)
    if args.counts:
        for code, found in groups.items():
            if found:
                print(f"{code} {len(found)}")
        print(f"total {sum(len(f) for f in groups.values())}")
        return 0
    rows = sample(groups, args.seed, args.per_code)
    if args.output:
        with open(args.output, "w", encoding="utf-8") as f:
            write_table(rows, groups, args.seed, args.workspace, f)
    else:
        write_table(rows, groups, args.seed, args.workspace, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
