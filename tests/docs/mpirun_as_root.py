#!/usr/bin/python3
"""Every mpirun command the documents give says, in the same code block, what root needs: OpenMPI
refuses to start as root without --allow-run-as-root (issue 53: docs/LAMMPS-EXPORT.md's line failed
as written on this project's machines, where everything runs as root).

    mpirun_as_root.py SOURCE_DIR

A command is `mpirun` at the start of a line of a fenced code block or after a colon, `;`, `&&` or
`|` (`# or: mpirun -np 2 lmp ...`), not a mention in passing ("also under mpirun -np N"). Exits 1
naming each block that gives one without the flag."""
import glob
import os
import re
import sys

COMMAND = re.compile(r"(^|[:;&|]\s*)mpirun\s", re.M)


def main():
    source = os.path.abspath(sys.argv[1])
    documents = [os.path.join(source, "README.md"), os.path.join(source, "python", "README.md")]
    documents += sorted(glob.glob(os.path.join(source, "docs", "*.md")))
    failures = []
    for path in documents:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        for block in re.finditer(r"^```[^\n]*\n(.*?)^```", text, re.M | re.S):
            body = block.group(1)
            if COMMAND.search(body) and "--allow-run-as-root" not in body:
                line = text.count("\n", 0, block.start()) + 1
                failures.append(f"{os.path.relpath(path, source)}:{line}: an mpirun command without a word on "
                                "--allow-run-as-root (OpenMPI refuses root without it)")
    for f in failures:
        print(f"mpirun_as_root: FAIL: {f}", file=sys.stderr)
    if not failures:
        print(f"mpirun_as_root: ok: {len(documents)} documents")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
