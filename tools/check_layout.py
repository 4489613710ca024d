#!/usr/bin/env python3
"""Holds docs/layout.md and labs/README.md to the tree they describe.

  tools/check_layout.py ROOT

docs/layout.md's map of the code names one folder a line (`app/util/   ...`): each must exist, and
every folder of app/ must be named there. labs/README.md's table of a lab's files names paths and
patterns (`labs/<id>/<id>_lab.cpp`): each plain path must exist, and each pattern must match a file
of some lab. Exits 1 with one line per problem, naming the file and the path.
"""
import glob
import os
import re
import sys


def layout_problems(root):
    doc = os.path.join(root, "docs", "layout.md")
    text = open(doc, encoding="utf-8").read()
    block = re.search(r"^```\n(.*?)^```", text, re.S | re.M)
    if not block:
        return [f"{doc}: no code block holding the map of the code"]
    named = [m.group(1) for m in re.finditer(r"^(\S+/)\s", block.group(1), re.M)]
    problems = [f"{doc}: names {p}, which is not a folder" for p in named
                if not os.path.isdir(os.path.join(root, p))]
    for entry in sorted(os.listdir(os.path.join(root, "app"))):
        folder = f"app/{entry}/"
        if os.path.isdir(os.path.join(root, folder)) and folder not in named:
            problems.append(f"{doc}: does not name {folder}")
    return problems


def labs_problems(root):
    doc = os.path.join(root, "labs", "README.md")
    text = open(doc, encoding="utf-8").read()
    table = text[text.index("## The files"):text.index("## The steps")] if "## The files" in text else ""
    problems = []
    for cell in re.findall(r"^\| `([^`]+)`", table, re.M):
        for path in re.split(r"`?,\s*`", cell):
            path = path.strip("`")
            if "<id>" in path:
                pattern = path.replace("<id>", "*").replace("*_lab.cpp", "*_lab.cpp")
                if not glob.glob(os.path.join(root, pattern)):
                    problems.append(f"{doc}: names {path}, which no lab has")
            elif not path.startswith("_") and not glob.glob(os.path.join(root, path.rstrip("/"))):
                problems.append(f"{doc}: names {path}, which does not exist")
    return problems


def main():
    if len(sys.argv) != 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    problems = layout_problems(sys.argv[1]) + labs_problems(sys.argv[1])
    for p in problems:
        print(p)
    print(f"check_layout: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
