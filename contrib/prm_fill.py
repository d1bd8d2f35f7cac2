#!/usr/bin/env python3
"""Write a copy of a parameter file with some of its marked fields changed.

The studies of doc/ run one shipped .prm in many variants. Each variable part of such a file has
a working default and a mark, so that the file runs as shipped and a script can change the part:

- an entry whose line ends in the comment `# @KEY@`: the value after `=` is the field KEY;
- the lines between `# @KEY@ {` and `# }` (each mark on a line of its own): the field KEY is
  these lines (a block of entries or subsections).

usage: prm_fill.py SOURCE TARGET KEY=VALUE ...   (or fill() from Python)
A KEY that the file does not mark is an error, so a study cannot silently run the default.
"""

import re
import sys

ENTRY = re.compile(r"^(\s*set\s+[^=]+=\s*)(.*?)(\s*#\s*@([A-Z0-9_]+)@\s*)$")
BLOCK_BEGIN = re.compile(r"^\s*#\s*@([A-Z0-9_]+)@\s*\{\s*$")
BLOCK_END = re.compile(r"^\s*#\s*\}\s*$")


def fill_text(text, fields, name="the parameter file"):
    """Return text with the marked fields in the dict fields replaced by their values."""
    lines = text.split("\n")
    result, used, block = [], set(), None
    for line in lines:
        if block is not None:
            if BLOCK_END.match(line):
                result.append(line)
                block = None
            elif block not in fields:
                result.append(line)
            continue
        begin = BLOCK_BEGIN.match(line)
        if begin:
            block = begin.group(1)
            result.append(line)
            if block in fields:
                result.extend(fields[block].split("\n"))
                used.add(block)
            continue
        entry = ENTRY.match(line)
        if entry and entry.group(4) in fields:
            result.append(entry.group(1) + fields[entry.group(4)] + entry.group(3))
            used.add(entry.group(4))
            continue
        result.append(line)
    if block is not None:
        raise SystemExit(f"{name}: the block @{block}@ is not closed by '# }}'")
    unknown = sorted(set(fields) - used)
    if unknown:
        raise SystemExit(f"{name}: no field marked {', '.join('@' + k + '@' for k in unknown)}")
    return "\n".join(result)


def fill(source, fields, target):
    """Write source with the fields changed to target."""
    with open(source) as f:
        text = fill_text(f.read(), fields, source)
    with open(target, "w") as f:
        f.write(text)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    pairs = {}
    for arg in sys.argv[3:]:
        key, sep, value = arg.partition("=")
        if not sep:
            raise SystemExit(f"prm_fill.py: '{arg}' is not KEY=VALUE")
        pairs[key] = value
    fill(sys.argv[1], pairs, sys.argv[2])
