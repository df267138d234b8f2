#!/usr/bin/python3
"""Every path a document names exists: in each Markdown file of the tree (README, docs/, study/,
the results' records, ...), each path that starts at one of the tree's top folders (configs/,
docs/, results/, study/, src/, tests/, tools/, ...) and each relative Markdown link. A path counts
when it exists from the tree's root or from the document's own folder; `{h,cpp}` is expanded and
`*` globbed; a path with a placeholder (DIR, SWEEP, FOLDER, KEY, NAME, seedN, ...) is not a path.
Files that move leave their documents pointing at nothing; this says where.

    doc_paths.py [SOURCE_DIR]

Exits 1 naming each document, line and missing path. First it checks that the check can fail: a
made-up document naming a missing file, and a broken link, must be reported; the same naming
files that exist must not.
"""
import glob
import os
import re
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

TOP_FOLDERS = ("apps", "bench", "cmake", "configs", "docs", "examples", "notebooks", "python",
               "results", "src", "study", "tests", "tools")
# A path: a top folder, then path characters, ending on a word character or a closing brace.
PATH = re.compile(r"(?<![\w./-])((?:" + "|".join(TOP_FOLDERS) + r")/[\w./+{},*=-]*[\w}*])")
LINK = re.compile(r"\]\(([^)#\s]+)")
# Words a document uses for "the one you choose" inside a path.
PLACEHOLDER = re.compile(r"(?<![A-Za-z])(DIR|SWEEP|FOLDER|KEY|NAME|CONFIG|FILE|PATH|OUT|K|N)(?![A-Za-z])|[a-z]N(?![a-z])")
SKIP_DIRS = {".git", "build", "node_modules", "__pycache__"}


def markdown_files(root):
    for top, dirs, files in os.walk(root):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("build"))
        for name in sorted(files):
            if name.endswith(".md"):
                yield os.path.relpath(os.path.join(top, name), root)


def expand_braces(path):
    m = re.search(r"\{([^{}]*)\}", path)
    if not m:
        return [path]
    return [p for alt in m.group(1).split(",") for p in expand_braces(path[:m.start()] + alt + path[m.end():])]


def exists(root, doc_dir, path):
    for base in (root, os.path.join(root, doc_dir)):
        for candidate in expand_braces(path):
            full = os.path.join(base, candidate)
            if (glob.glob(full) if "*" in candidate else os.path.exists(full)):
                return True
    return False


def missing_paths(root):
    problems = []
    for doc in markdown_files(root):
        doc_dir = os.path.dirname(doc)
        with open(os.path.join(root, doc), encoding="utf-8", errors="replace") as f:
            for number, line in enumerate(f, 1):
                named = [m.group(1).rstrip(".,") for m in PATH.finditer(line)]
                linked = [t for t in LINK.findall(line) if not re.match(r"[a-z]+:", t)]
                for path in named:
                    if not PLACEHOLDER.search(path) and not exists(root, doc_dir, path):
                        problems.append(f"{doc}:{number}: names {path}, which does not exist")
                for target in linked:
                    if not os.path.exists(os.path.normpath(os.path.join(root, doc_dir, target))):
                        problems.append(f"{doc}:{number}: links to {target}, which does not exist")
    return problems


def check_can_fail():
    with tempfile.TemporaryDirectory() as tree:
        os.makedirs(os.path.join(tree, "docs"))
        os.makedirs(os.path.join(tree, "src", "geometry"))
        for name in ("Shape.h", "Shape.cpp"):
            open(os.path.join(tree, "src", "geometry", name), "w").close()
        with open(os.path.join(tree, "docs", "GOOD.md"), "w", encoding="utf-8") as f:
            f.write("See `src/geometry/Shape.{h,cpp}`, src/geometry/*.h, [up](../docs/GOOD.md), "
                    "`wiggle sweep configs/sweeps/SWEEP.toml --out results/FOLDER` and results/seedN/x.\n")
        with open(os.path.join(tree, "docs", "BAD.md"), "w", encoding="utf-8") as f:
            f.write("Run `study/sweeps/gone.toml`.\nSee [it](../docs/GONE.md).\n")
        found = missing_paths(tree)
    expected = ["docs/BAD.md:1: names study/sweeps/gone.toml, which does not exist",
                "docs/BAD.md:2: links to ../docs/GONE.md, which does not exist"]
    return [] if found == expected else [f"self-test: expected {expected}, found {found}"]


def main():
    root = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else ROOT
    problems = check_can_fail() + missing_paths(root)
    for p in problems:
        print(f"doc_paths: FAIL: {p}", file=sys.stderr)
    if not problems:
        print(f"doc_paths: ok: every path named in {sum(1 for _ in markdown_files(root))} documents exists")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
