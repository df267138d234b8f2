#!/usr/bin/python3
"""Every cost figure agrees with the one measured cost table, bench/costs.csv.

    costs.py

Fails (exit 1, one line per problem) when a cost block (`<!-- costs: NAME -->` in README.md and
docs/, `# costs: NAME` in configs/) differs from what tools/docs/costs.py makes from the table, or
when a figure of ns per particle-step anywhere else in README.md, docs/*.md or configs/ is more than
25 % from the table's figure for the bed and thread count its line names. Fix: run
`tools/docs/costs.py` and commit, or correct the figure. First it checks that the check can fail:
a changed digit in a block, and a figure 30 % off, must both be reported.
"""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools", "docs"))
import costs  # noqa: E402
import marked  # noqa: E402


def check_can_fail():
    rows = costs.load()
    problems = []
    block = costs.BLOCKS["study_costs"][1](rows)
    text = "\n".join(["<!-- costs: study_costs -->"] + block + ["<!-- /costs: study_costs -->"])
    row = next(line for line in block if line.startswith("| `") and any(ch.isdigit() for ch in line))
    digit = next(ch for ch in row if ch.isdigit())
    changed = text.replace(row, row.replace(digit, str((int(digit) + 1) % 10), 1))
    again, found = marked.regenerate(changed, {"study_costs": block}, "self-test.md", "costs")
    if again != text or again == changed or found:
        problems.append("self-test: a changed cost block went unnoticed")
    small = costs.ns(rows, "small")
    lines = [(1, f"the small bed runs at {small * 1.3:.1f} ns per particle-step on one core"),
             (2, f"the small bed runs at {small * 1.1:.1f} ns per particle-step on one core")]
    found = costs.figure_problems(rows, "self-test.md", lines)
    if len(found) != 1 or ":1:" not in found[0]:
        problems.append(f"self-test: a figure 30 % off the table was not told from one 10 % off: {found}")
    return problems


def main():
    problems = check_can_fail() + costs.run(check=True)
    for p in problems:
        print(p)
    print(f"costs: {len(problems)} differences between the documents' cost figures and bench/costs.csv")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
