"""Generated blocks inside hand-written files: the lines between a start and an end marker are made
by a script (study/tools/vy_tables.py, tools/docs/costs.py), the rest is left as it is.

In Markdown a block is

    <!-- TAG: NAME -->
    ...
    <!-- /TAG: NAME -->

and in TOML (comments only)

    # TAG: NAME
    # ...
    # /TAG: NAME
"""
import difflib
import os


def markers(tag, path):
    """The (start prefix, start suffix, end format) of a block of `tag` in the file at `path`."""
    if path.endswith(".toml"):
        return f"# {tag}: ", "", f"# /{tag}: {{name}}"
    return f"<!-- {tag}: ", " -->", f"<!-- /{tag}: {{name}} -->"


def regenerate(text, blocks, where, tag="vy_tables"):
    """The text with every marked block replaced by `blocks[name]` (a list of lines), and the problems
    found (a marker without an end, a name not in blocks). Each block used is set to None in blocks,
    so that the caller can name those that have no markers."""
    start, suffix, end_format = markers(tag, where)
    out, problems, lines, i = [], [], text.split("\n"), 0
    while i < len(lines):
        line = lines[i]
        out.append(line)
        i += 1
        if not (line.startswith(start) and line.endswith(suffix)):
            continue
        name = line[len(start):len(line) - len(suffix)]
        end = end_format.format(name=name)
        if end not in lines[i:]:
            problems.append(f"{where}: block {name} has no end marker {end}")
            continue
        j = lines.index(end, i)
        if name not in blocks:
            problems.append(f"{where}: block {name} is not declared")
            out += lines[i:j]
        else:
            out += blocks[name]
            blocks[name] = None   # used
        i = j
    return "\n".join(out), problems


def outside_blocks(text, tag, where):
    """(line number, line) of every line of text that is not inside a block of `tag`."""
    start, suffix, end_format = markers(tag, where)
    inside, kept = None, []
    for number, line in enumerate(text.split("\n"), 1):
        if inside is None and line.startswith(start) and line.endswith(suffix):
            inside = end_format.format(name=line[len(start):len(line) - len(suffix)])
        elif inside is not None and line == inside:
            inside = None
        elif inside is None:
            kept.append((number, line))
    return kept


def differences(old, new):
    """The lines of old that new changes, and what new has instead (difflib's unified diff)."""
    return [d for d in difflib.unified_diff(old.split("\n"), new.split("\n"), "committed", "generated", n=0, lineterm="")
            if d[:1] in "+-" and d[:3] not in ("+++", "---")]


def rewrite(root, documents, blocks, tag, check):
    """Regenerate (or, with check, compare) the blocks of `tag` in each document under root; the
    problems, one line each (with check, every line that differs)."""
    problems = []
    for doc in documents:
        path = os.path.join(root, doc)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        new, found = regenerate(text, blocks, doc, tag)
        problems += found
        if new != text:
            if check:
                problems += [f"{doc}: {line}" for line in differences(text, new)]
            else:
                with open(path + ".tmp", "w", encoding="utf-8") as f:
                    f.write(new)
                os.replace(path + ".tmp", path)
                print(f"{tag}: {doc} rewritten")
    problems += [f"{tag}: block {name} has no markers in {', '.join(documents)}"
                 for name, lines in blocks.items() if lines is not None]
    return problems
