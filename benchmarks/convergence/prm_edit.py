"""Edits the entries of a deal.II ParameterHandler (.prm) text.

A sweep level is a copy of a scene file with a few entries changed (the
subdivisions of a rectangle, the global refinements of a disc, ...). An entry
is named by its path, the subsections and the entry name joined by '/', e.g.
'Body 1/Geometry/Rectangle/Subdivisions'. An entry that the file sets is
replaced in place; one it does not set is added at the end of its
subsection, and subsections that do not exist are created at the end of
their parent. Comments and layout of the rest of the file are kept.
"""

import re

_SUBSECTION = re.compile(r"^\s*subsection\s+(.+?)\s*(#.*)?$")
_END = re.compile(r"^\s*end\s*(#.*)?$")
_SET = re.compile(r"^(\s*)set\s+(.+?)\s*=\s*(.*?)\s*(#.*)?$")


def _scan(lines):
    """Yields (index, kind, stack, match) for every line; stack is the list
    of enclosing subsections of that line (for 'end': the one it closes)."""
    stack = []
    for i, line in enumerate(lines):
        m = _SUBSECTION.match(line)
        if m:
            yield i, "subsection", list(stack), m
            stack.append(m.group(1))
            continue
        if _END.match(line):
            yield i, "end", list(stack), None
            stack.pop()
            continue
        m = _SET.match(line)
        if m:
            yield i, "set", list(stack), m


def set_entry(text, path, value):
    """Returns text with the entry at path set to value (a string)."""
    parts = [p.strip() for p in path.split("/")]
    sections, name = parts[:-1], parts[-1]
    lines = text.splitlines()
    for i, kind, stack, m in _scan(lines):
        if kind == "set" and stack == sections and m.group(2) == name:
            lines[i] = f"{m.group(1)}set {name} = {value}"
            return "\n".join(lines) + "\n"
    # Not set: add it at the end of the deepest existing subsection.
    depth, insert_at = 0, len(lines)
    for i, kind, stack, _ in _scan(lines):
        if kind == "end" and len(stack) > depth \
                and stack == sections[: len(stack)]:
            depth, insert_at = len(stack), i
    new = []
    for level in range(depth, len(sections)):
        new.append("  " * level + f"subsection {sections[level]}")
    new.append("  " * len(sections) + f"set {name} = {value}")
    for level in reversed(range(depth, len(sections))):
        new.append("  " * level + "end")
    lines[insert_at:insert_at] = new
    return "\n".join(lines) + "\n"


def get_entry(text, path):
    """The value the text sets for path, or None."""
    parts = [p.strip() for p in path.split("/")]
    for _, kind, stack, m in _scan(text.splitlines()):
        if kind == "set" and stack == parts[:-1] and m.group(2) == parts[-1]:
            return m.group(3)
    return None
