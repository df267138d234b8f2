#!/usr/bin/python3
"""The documents' tables of measured V_y and the answer's sentences, made from the committed results
(results/, and the one small-preset results.csv under study/figures/).

    study/tools/vy_tables.py            rewrite every table in place, between its markers
    study/tools/vy_tables.py --check    change nothing; exit 1 naming each table that differs

A table sits in its document between two marker lines,

    <!-- vy_tables: NAME -->
    ...
    <!-- /vy_tables: NAME -->

and is declared in the TABLES of the module that makes it, by what it makes:

    measured_tables.py   the measured tables (study/VALIDATION.md, docs/PERFORMANCE.md, results/*/README.md)
    findings_table.py    study/FINDINGS.md's table of the paper's findings, its evidence, the answer's verdicts
    table1_blocks.py     the answer's Table 1 by the paper's clock and Table 1 in the paper's own box
    factor_tables.py     the protocol block and the coupling screen
    answer_sentences.py  the answer's sentences, the paragraph of README.md and study/README.md, and the
                         table of the coupling factors' cases in the paper's own box

on cases.py (the committed results read as cases and cells), table_kinds.py (pivot, listing, ...)
and scatter.py (one bed's sigma and a cell in its standard errors). The statistics are findings.py's,
tested in study/tests/test_findings.py; the sentences' choices are tested in
study/tests/test_study_sentences.py. A cell of a table gives the number of beds and, from two beds
on, the mean and the standard error of the mean (the standard deviation over sqrt(n)).
"""
import os
import sys

# The marked blocks are the program's (tools/docs/marked.py, which tools/docs/costs.py uses too).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools", "docs"))
import answer_sentences  # noqa: E402
import factor_tables  # noqa: E402
import findings  # noqa: E402
import findings_table  # noqa: E402
import marked  # noqa: E402
import measured_tables  # noqa: E402
import table1_blocks  # noqa: E402
from answer_sentences import course_words  # noqa: E402
from cases import ROOT, PhaseProfile  # noqa: E402
from factor_tables import own_scatter_caveat  # noqa: E402
from findings import on_paper_side  # noqa: E402

# Besides the command: what study/tests/vy_tables.py checks by name here, as before the modules were
# split out (the rule through `findings`, the phase profile, the sentences' words it tries).
__all__ = ["TABLES", "DOCUMENTS", "render", "run", "main", "marked", "findings", "PhaseProfile", "own_scatter_caveat",
           "on_paper_side", "course_words"]

TABLES = (measured_tables.TABLES + findings_table.TABLES + table1_blocks.TABLES + factor_tables.TABLES
          + answer_sentences.TABLES)

DOCUMENTS = ["study/VALIDATION.md", "study/FINDINGS.md", "docs/PERFORMANCE.md", "README.md", "study/README.md",
             "results/paper_depth/box/README.md", "results/paper_depth/fig5/README.md",
             "results/paper_depth/table1_t1000/README.md", "results/paper_depth/runlength_t300/README.md"]


def render(spec):
    """The table's lines, then the line that names its sources."""
    lines, sources = spec["kind"](spec)
    if spec.get("bare"):   # prose in a document that names its source itself
        return lines
    return lines + ["", "(made by `study/tools/vy_tables.py` from " + ", ".join(sources)
                    + "; a cell is one bed's V_y, or the mean +- standard error of the mean over the beds it counts)"]


def run(check):
    """Regenerate (or, with check, compare) every document; the problems, one line each."""
    tables = {spec["name"]: render(spec) for spec in TABLES}
    return marked.rewrite(ROOT, DOCUMENTS, tables, "vy_tables", check)


def main():
    args = sys.argv[1:]
    if args not in ([], ["--check"]):
        sys.exit("usage: study/tools/vy_tables.py [--check]")
    try:
        problems = run(check=args == ["--check"])
    except (OSError, KeyError, ValueError) as e:
        problems = [f"{type(e).__name__}: {e}"]
    for p in problems:
        print(p)
    if args:
        print(f"vy_tables: {len(problems)} differences between the documents' tables and results/")
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
