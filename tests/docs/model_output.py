#!/usr/bin/python3
"""docs/MODEL.md's sample output is what `wiggle model` prints: every fenced block of the document
whose first line is a `$ wiggle model ...` command holds one or more commands, each followed by its
output; each command is run with the given binary and its standard output compared line by line.

    model_output.py WIGGLE_BINARY [MODEL_MD]

Exits 1 naming the first line that differs (or a block with no command). First it checks that the
check can fail: a sample with one changed digit must be reported.
"""
import os
import shlex
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
LEAST_SAMPLES = 5  # the document's samples: the table, its csv, the rates, two asymmetric shapes


def samples(text):
    """[(command, expected output lines)] of every fenced block that starts with '$ wiggle'."""
    found, block, inside = [], None, False
    for line in text.splitlines():
        if line.startswith("```"):
            if inside and block and block[0].startswith("$ wiggle"):
                command, output = None, []
                for b in block + ["$ "]:  # a last prompt closes the last command
                    if b.startswith("$ "):
                        while output and output[-1] == "":  # the blank line between two commands
                            output.pop()
                        if command:
                            found.append((command, output))
                        command, output = b[2:], []
                    else:
                        output.append(b)
            inside, block = not inside, []
        elif inside:
            block.append(line)
    return found


def differences(binary, found):
    problems = []
    for command, expected in found:
        args = shlex.split(command)
        run = subprocess.run([binary] + args[1:], capture_output=True, text=True)
        got = run.stdout.rstrip("\n").split("\n")
        if run.returncode != 0:
            problems.append(f"`{command}` exited {run.returncode}: {run.stderr.strip()}")
            continue
        for k in range(max(len(got), len(expected))):
            g = got[k] if k < len(got) else "<nothing>"
            e = expected[k] if k < len(expected) else "<nothing>"
            if g != e:
                problems.append(f"`{command}`, line {k + 1}: docs/MODEL.md has\n  {e}\nwiggle prints\n  {g}")
                break
    return problems


def main():
    binary = sys.argv[1]
    path = sys.argv[2] if len(sys.argv) > 2 else os.path.join(ROOT, "docs", "MODEL.md")
    found = samples(open(path, encoding="utf-8").read())
    # The check can fail: one digit changed in the first sample must be reported.
    command, expected = found[0]
    altered = [line.replace("3.500", "3.501", 1) for line in expected]
    if altered == expected or not differences(binary, [(command, altered)]):
        sys.exit("model_output: the self-check did not catch a changed digit")
    problems = differences(binary, found)
    if len(found) < LEAST_SAMPLES:
        problems.append(f"{path}: {len(found)} samples with a `$ wiggle model` command, expected at least {LEAST_SAMPLES}")
    for p in problems:
        print("model_output: FAIL:", p)
    if problems:
        sys.exit(1)
    print(f"model_output: ok: {len(found)} samples of {os.path.relpath(path, ROOT)} are what wiggle prints")


if __name__ == "__main__":
    main()
