#!/usr/bin/env python3
"""Rewrite committed results JSON compact, and prove the rewrite kept every record.

    python3 .ci/results-compact.py write FILE...        # rewrite each FILE compact, in place
    python3 .ci/results-compact.py check REV FILE...    # FILE now == `git show REV:FILE`, as JSON
    python3 .ci/results-compact.py summary REV:FULL SUMMARY  # each record of SUMMARY is FULL's

`write` drops the whitespace outside strings and nothing else: every other byte (each
number's digits, key order, escapes) stays as it was, so the file is the same JSON token
for token, on one line with a final newline, as `torus-cull` now writes them (issue 53).

`check` parses each file and its version at REV and compares them as JSON values (objects
key by key, arrays element by element, numbers by value); it prints one line per file and
exits 1 on the first difference it names. `torus-cull compare REV-version FILE` giving 0
changes is the lab's own check of the same (results/README.md, "Compact files").
"""
import json
import subprocess
import sys


def minify(text):
    out = []
    in_string = False
    escaped = False
    for ch in text:
        if in_string:
            out.append(ch)
            if escaped:
                escaped = False
            elif ch == "\\":
                escaped = True
            elif ch == '"':
                in_string = False
        elif ch == '"':
            in_string = True
            out.append(ch)
        elif ch not in " \t\r\n":
            out.append(ch)
    return "".join(out) + "\n"


def first_difference(a, b, where="$"):
    if type(a) is not type(b) and not (
        isinstance(a, (int, float)) and isinstance(b, (int, float))
    ):
        return f"{where}: {type(a).__name__} vs {type(b).__name__}"
    if isinstance(a, dict):
        if list(a) != list(b):
            return f"{where}: keys {list(a)} vs {list(b)}"
        for k in a:
            d = first_difference(a[k], b[k], f"{where}.{k}")
            if d:
                return d
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{where}: {len(a)} vs {len(b)} elements"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{where}[{i}]")
            if d:
                return d
        return None
    return None if a == b else f"{where}: {a!r} vs {b!r}"


def main(argv):
    if len(argv) >= 2 and argv[0] == "write":
        for path in argv[1:]:
            with open(path, encoding="utf-8") as f:
                text = f.read()
            compact = minify(text)
            json.loads(compact)  # still JSON
            with open(path, "w", encoding="utf-8") as f:
                f.write(compact)
            print(f"{path}: {len(text.encode())} -> {len(compact.encode())} bytes")
        return 0
    if len(argv) >= 3 and argv[0] == "check":
        rev = argv[1]
        for path in argv[2:]:
            old = subprocess.run(
                ["git", "show", f"{rev}:{path}"], check=True, capture_output=True
            ).stdout.decode("utf-8")
            with open(path, encoding="utf-8") as f:
                new = f.read()
            diff = first_difference(json.loads(old), json.loads(new))
            if diff:
                print(f"{path}: DIFFERS from {rev}: {diff}")
                return 1
            records = sum(
                len(v) for v in json.loads(new).values() if isinstance(v, list)
            )
            lines = new.count("\n")
            print(f"{path}: same JSON as {rev} ({records} records; {lines} line)")
        return 0
    if len(argv) == 3 and argv[0] == "summary":
        full = json.loads(
            subprocess.run(["git", "show", argv[1]], check=True, capture_output=True).stdout
        )
        with open(argv[2], encoding="utf-8") as f:
            summary = json.load(f)
        meta = dict(summary["meta"])
        meta.pop("summary_of", None)
        d = first_difference(full["meta"], meta, "$.meta")
        if d:
            print(f"{argv[2]}: DIFFERS from {argv[1]}: {d}")
            return 1
        counts = []
        for section, records in summary.items():
            if not isinstance(records, list):
                continue
            # Each summary record is the full file's record at the same position among
            # those the summary kept: walk the full section in order.
            source = iter(full.get(section, []))
            for i, r in enumerate(records):
                for candidate in source:
                    if first_difference(candidate, r) is None:
                        break
                else:
                    print(f"{argv[2]}: {section}[{i}] is not a record of {argv[1]}")
                    return 1
            counts.append(f"{section} {len(records)}/{len(full.get(section, []))}")
        print(f"{argv[2]}: every record is {argv[1]}'s, in order ({', '.join(counts)})")
        return 0
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
