#!/usr/bin/env python3
"""After a ctest run (contrib/run_tests.sh): print the ten slowest cases, fail if a case ran past
its tier's budget, and close with the pass/fail count.

Usage: test_times.py CTEST_LOG BUILD_DIR

CTEST_LOG is ctest's printed output; BUILD_DIR holds test_budgets.json (written by
tests/CMakeLists.txt: seconds per case of the default tier and of the cases labelled "long").
"""
import json
import re
import subprocess
import sys


def main():
    log, build = sys.argv[1], sys.argv[2]
    with open(f"{build}/test_budgets.json") as f:
        budgets = json.load(f)
    listing = subprocess.run(["ctest", "-N", "-L", "long"], cwd=build, capture_output=True,
                             text=True, check=True).stdout
    long_cases = set(re.findall(r"Test +#\d+: (\S+)", listing))

    result = re.compile(r"Test +#\d+: (\S+) \.*\s*(?:\*\*\*)?(\w+).*?([\d.]+) sec")
    times = {}
    outcomes = {}
    with open(log) as f:
        for line in f:
            match = result.search(line)
            if match:
                times[match.group(1)] = float(match.group(3))
                outcomes[match.group(1)] = match.group(2)
    if not times:
        print("test_times.py: no test ran", file=sys.stderr)
        return 1

    print("\nThe ten slowest cases:")
    for name, seconds in sorted(times.items(), key=lambda item: -item[1])[:10]:
        print(f"  {seconds:8.1f} s  {name}")
    print(f"Summed case time: {sum(times.values()):.0f} s")

    over = []
    for name, seconds in times.items():
        tier = "long" if name in long_cases else "default"
        if seconds > budgets[tier]:
            over.append(f"  {name}: {seconds:.1f} s, over the {tier} tier's budget of "
                        f"{budgets[tier]} s per case")
    if over:
        print("\nCases past their tier's budget (make them smaller, or label them long with "
              "perideal_label_long_tests in their tests/<area>/CMakeLists.txt):")
        print("\n".join(over))

    passed = sum(1 for outcome in outcomes.values() if outcome == "Passed")
    print(f"ctest: {passed} passed, {len(outcomes) - passed} failed")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
