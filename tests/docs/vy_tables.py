#!/usr/bin/python3
"""The documents' V_y tables are what tools/study/vy_tables.py makes from the committed results.

    vy_tables.py

Fails (exit 1, one line per changed table line) when a table between `<!-- vy_tables: NAME -->`
markers in docs/VALIDATION.md or docs/PERFORMANCE.md differs from what the script makes from
results/, when a marker names no declared table or a declared table has no markers. Fix: run
`tools/study/vy_tables.py` and commit the documents. First it checks that the check can fail: a
document with one digit of a table changed must be reported.
"""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools", "study"))
import vy_tables  # noqa: E402


def check_can_fail():
    """A changed digit inside a marked table must be replaced by the regeneration."""
    spec = vy_tables.TABLES[0]
    table = vy_tables.render(spec)
    text = "\n".join([f"<!-- vy_tables: {spec['name']} -->"] + table + [f"<!-- /vy_tables: {spec['name']} -->"])
    row = next(i for i, line in enumerate(table) if line.startswith("| ") and any(ch.isdigit() for ch in line))
    digit = next(ch for ch in table[row] if ch.isdigit())
    changed = text.replace(table[row], table[row].replace(digit, str((int(digit) + 1) % 10), 1))
    tables = {spec["name"]: table}
    again, problems = vy_tables.regenerate(changed, tables, "self-test")
    return [] if again == text and again != changed and not problems else ["self-test: a changed table went unnoticed"]


def main():
    problems = check_can_fail() + vy_tables.run(check=True)
    for p in problems:
        print(p)
    print(f"vy_tables: {len(problems)} differences between the documents' tables and results/")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
