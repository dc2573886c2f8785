#!/usr/bin/env python3
"""Weaves the page of every tutorial step, as deal.II shows its steps.

    weave.py            write doc/tutorials/step-N/README.md for every step
                        and the index doc/tutorials/README.md
    weave.py --check    fail (exit 1) if a page is not what this script
                        makes, or if fewer than a third of the lines of a
                        step-N.cc are comments

A step's page is: its intro.md; "The commented program", where the comment
blocks of step-N.cc become the text (`// @sect3{Title}` a heading) and the
code between them code blocks; its results.md; and "The plain program",
the code without its comments. The index lists every step with the summary
line of its intro (an HTML comment `<!-- summary: ... -->`) and the first
figure of its results.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def steps():
    found = []
    for name in os.listdir(HERE):
        m = re.fullmatch(r"step-(\d+)", name)
        if m and os.path.exists(os.path.join(HERE, name, name + ".cc")):
            found.append((int(m.group(1)), name))
    return [name for _, name in sorted(found)]


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def is_comment(line):
    return line.strip().startswith("//")


def comment_text(line):
    text = line.strip()[2:]
    return text[1:] if text.startswith(" ") else text


def blocks(source):
    """Split a program into ('text', lines) and ('code', lines) blocks."""
    out = []
    for line in source.splitlines():
        kind = "text" if is_comment(line) else "code"
        if not out or out[-1][0] != kind:
            out.append((kind, []))
        out[-1][1].append(comment_text(line) if kind == "text" else line)
    return out


def markdown_of_text(lines):
    md = []
    for line in lines:
        m = re.match(r"@sect(\d)\{(.*)\}\s*$", line)
        if m:
            md.append("#" * (int(m.group(1))) + " " + m.group(2))
        else:
            md.append(line)
    return "\n".join(md).strip("\n")


def commented_program(source):
    parts = []
    for kind, lines in blocks(source):
        if kind == "text":
            parts.append(markdown_of_text(lines))
        else:
            code = "\n".join(lines).strip("\n")
            if code.strip():
                parts.append("```cpp\n" + code + "\n```")
    return "\n\n".join(parts)


def plain_program(source):
    lines = [l for l in source.splitlines() if not is_comment(l)]
    text = re.sub(r"\n{3,}", "\n\n", "\n".join(lines)).strip("\n")
    return "```cpp\n" + text + "\n```"


def comment_fraction(source):
    lines = [l for l in source.splitlines() if l.strip()]
    return sum(is_comment(l) for l in lines) / max(1, len(lines))


BANNER = re.compile(r"\s*//\s*(-{5,}|dpana: .*)\s*$")


def without_banner(source):
    """The program without the project's file banner (dashed lines and the
    one-line description of dpana) at its top."""
    lines = source.splitlines()
    while lines and (BANNER.fullmatch(lines[0]) or not lines[0].strip()):
        lines.pop(0)
    return "\n".join(lines) + "\n"


def page(step):
    folder = os.path.join(HERE, step)
    source = without_banner(read(os.path.join(folder, step + ".cc")))
    results = os.path.join(folder, "results.md")
    return "\n\n".join(
        [
            "<!-- Made by doc/tutorials/weave.py from intro.md, %s.cc and "
            "results.md: edit those, then run weave.py. -->" % step,
            read(os.path.join(folder, "intro.md")).strip("\n"),
            "# The commented program",
            commented_program(source),
            read(results).strip("\n") if os.path.exists(results) else "",
            "# The plain program",
            plain_program(source),
        ]
    ) + "\n"


def summary_of(step):
    intro = read(os.path.join(HERE, step, "intro.md"))
    title = next((l.lstrip("# ").strip() for l in intro.splitlines() if l.startswith("# ")), step)
    m = re.search(r"<!--\s*summary:\s*(.*?)\s*-->", intro, re.S)
    summary = " ".join(m.group(1).split()) if m else ""
    return title, summary


def first_figure(step):
    results = os.path.join(HERE, step, "results.md")
    if not os.path.exists(results):
        return None
    m = re.search(r"!\[[^\]]*\]\(([^)]+\.png)\)", read(results))
    return m.group(1) if m else None


def index():
    rows = [
        "<!-- Made by doc/tutorials/weave.py: edit the steps, then run weave.py. -->",
        "# Tutorials",
        "",
        "Numbered programs that teach the dual condensed formulation by running it, in",
        "the manner of the deal.II tutorial steps: each folder holds a literate program",
        "`step-N.cc` on the dpana library, its introduction, the results of its run and",
        "the woven page (`README.md`) that reads top to bottom. Run one with",
        "`./run.sh --tutorial N` (or `build/doc/tutorials/step-N` from its run folder",
        "`build/doc/tutorials/step-N/`); `ctest -R tutorial` runs them all.",
        "",
        "| step | what it teaches | picture |",
        "|---|---|---|",
    ]
    for step in steps():
        title, summary = summary_of(step)
        figure = first_figure(step)
        picture = "![%s](%s/%s)" % (step, step, figure) if figure else ""
        rows.append("| [%s](%s/README.md) | **%s**. %s | %s |" % (step, step, title, summary, picture))
    return "\n".join(rows) + "\n"


def main():
    check = "--check" in sys.argv[1:]
    pages = {os.path.join(HERE, s, "README.md"): page(s) for s in steps()}
    pages[os.path.join(HERE, "README.md")] = index()
    failed = False
    for s in steps():
        fraction = comment_fraction(read(os.path.join(HERE, s, s + ".cc")))
        if fraction < 1 / 3:
            print("%s.cc: only %.0f %% of its lines are comments (at least a third)" % (s, 100 * fraction))
            failed = True
    for path, text in pages.items():
        if check:
            if not os.path.exists(path) or read(path) != text:
                print("%s is not the woven page: run doc/tutorials/weave.py" % os.path.relpath(path, HERE))
                failed = True
        else:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
    if check and not failed:
        print("every tutorial page is woven from its sources (%d steps)" % len(steps()))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
