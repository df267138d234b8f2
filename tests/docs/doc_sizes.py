#!/usr/bin/python3
"""The reference documents stay references: each document in LIMITS has at most its number of
lines (as `wc -l` counts them). A document that grows past its limit is collecting history: move
the past measurements, the session-by-session records and the superseded before/after numbers to
its history file (docs/PERFORMANCE.md's is bench/HISTORY.md) and keep what a reader looks up.

    doc_sizes.py [SOURCE_DIR]

Exits 1 naming each document over its limit (or missing). First it checks that the check can fail:
a made-up document one line over a limit must be reported, and one at the limit must not.
"""
import os
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

# Document (relative to the source root) -> its most lines; the history it sheds goes where the
# message says.
LIMITS = {
    "docs/PERFORMANCE.md": (250, "bench/HISTORY.md"),
}


def line_count(path):
    with open(path, encoding="utf-8") as f:
        return len(f.read().splitlines())


def size_problems(root, limits):
    problems = []
    for doc, (most, history) in limits.items():
        path = os.path.join(root, doc)
        if not os.path.isfile(path):
            problems.append(f"{doc}: missing (tests/docs/doc_sizes.py limits it to {most} lines)")
            continue
        lines = line_count(path)
        if lines > most:
            problems.append(f"{doc}: {lines} lines, more than its {most}: move history (past measurements, "
                            f"session records, superseded numbers) to {history}")
    return problems


def check_can_fail():
    problems = []
    with tempfile.TemporaryDirectory() as tree:
        for name, lines in (("at.md", 5), ("over.md", 6)):
            with open(os.path.join(tree, name), "w", encoding="utf-8") as f:
                f.write("".join(f"line {k}\n" for k in range(lines)))
        found = size_problems(tree, {"at.md": (5, "H.md"), "over.md": (5, "H.md"), "gone.md": (5, "H.md")})
    if len(found) != 2 or not found[0].startswith("over.md: 6 lines") or not found[1].startswith("gone.md"):
        problems.append(f"self-test: a document over its limit, or a missing one, went unnoticed: {found}")
    return problems


def main():
    root = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else ROOT
    problems = check_can_fail() + size_problems(root, LIMITS)
    for p in problems:
        print(f"doc_sizes: FAIL: {p}", file=sys.stderr)
    if not problems:
        print("doc_sizes: ok: " + ", ".join(f"{doc} {line_count(os.path.join(root, doc))}/{most} lines"
                                            for doc, (most, _) in LIMITS.items()))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
