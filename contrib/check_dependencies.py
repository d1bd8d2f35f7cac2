#!/usr/bin/env python3
"""Check the library dependency graph: base <- pd, base <- fem, {pd, fem} <- coupling.

A header or source file of a library may include only its own headers and those of the
libraries it depends on. Exits non-zero, naming each offending include, otherwise.
"""
import pathlib
import re
import sys

ALLOWED = {
    "base": {"base"},
    "pd": {"base", "pd"},
    "fem": {"base", "fem"},
    "coupling": {"base", "pd", "fem", "coupling"},
}

top = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
include = re.compile(r'#\s*include\s*<perideal/(\w+)/')
errors = []
for area, allowed in ALLOWED.items():
    for folder in (top / "include" / "perideal" / area, top / "source" / area):
        if not folder.is_dir():
            continue
        for path in sorted(folder.rglob("*")):
            if path.suffix not in (".h", ".cc"):
                continue
            for number, line in enumerate(path.read_text().splitlines(), 1):
                match = include.search(line)
                if match and match.group(1) not in allowed:
                    errors.append(f"{path.relative_to(top)}:{number}: library '{area}' must not "
                                  f"include perideal/{match.group(1)}/ (allowed: "
                                  f"{', '.join(sorted(allowed))})")
for error in errors:
    print(error)
print(f"dependency graph: {'violated' if errors else 'ok'}")
sys.exit(1 if errors else 0)
