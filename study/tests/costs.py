#!/usr/bin/python3
"""Every figure of ns per particle-step in the study's documents and sweep files (study/*.md,
study/sweeps/*.md and *.toml) is within 25 % of bench/costs.csv's figure for the bed and thread
count its line names: tools/docs/costs.py's check of the program's documents (ctest docs_costs),
on the study's folders.

    costs.py

Exits 1 naming each figure that is not. Fix: correct the figure, or say which bed and thread count
it is of. The check's own self-test (a figure 30 % off reported, one 10 % off not) is docs_costs's.
"""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools", "docs"))
import costs  # noqa: E402

STUDY_DIRS = [("study", ".md"), ("study/sweeps", ".md"), ("study/sweeps", ".toml")]


def main():
    documents = list(costs.scanned_files(ROOT, STUDY_DIRS))
    problems = [] if len(documents) > 30 else [f"only {len(documents)} documents found under study/"]
    problems += costs.check_figures(ROOT, dirs=STUDY_DIRS)
    print("\n".join(problems + [f"study costs: {len(problems)} figures in {len(documents)} study documents "
                                 "off bench/costs.csv"]))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
