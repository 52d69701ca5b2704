#!/usr/bin/env python3
"""check_guide.py GUIDE SOURCE... — every line of the guide's ```cpp blocks must be a line of one
of the sources (whitespace runs collapsed), so the guide shows only code that is compiled and
tested. Exit 1 naming the first line that is not found."""
import re
import sys


def normalized(line):
    return re.sub(r"\s+", " ", line.strip())


guide, sources = sys.argv[1], sys.argv[2:]
known = set()
for path in sources:
    with open(path, encoding="utf-8") as f:
        known.update(normalized(line) for line in f)
inside, checked = False, 0
with open(guide, encoding="utf-8") as f:
    for number, line in enumerate(f, 1):
        if line.startswith("```"):
            inside = line.strip() == "```cpp"
            continue
        if inside and line.strip():
            checked += 1
            if normalized(line) not in known:
                print(f"{guide}:{number}: not in the sources: {line.rstrip()}")
                sys.exit(1)
print(f"guide consistent: {checked} code lines found in {len(sources)} sources")
