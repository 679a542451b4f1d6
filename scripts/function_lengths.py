#!/usr/bin/env python3
"""Lists functions longer than a limit in C++ sources (clang-formatted code).

A function is a definition whose body opens at the end of a line and whose closing brace
sits at the same indentation as the line the definition starts on (what clang-format
writes). Lambdas inside a function count as part of it. Usage:

    python3 scripts/function_lengths.py [--limit 80] DIR_OR_FILE...

Prints "lines  file:line  name" for each function over the limit, longest first, and exits 1
when there is any.
"""
import argparse
import os
import re
import sys

HEAD = re.compile(r"^(\s*)(?!if\b|for\b|while\b|switch\b|else\b|do\b|namespace\b|struct\b|"
                  r"class\b|enum\b|union\b|extern\b|return\b|case\b)"
                  r"[^;{}()]*?([~\w:<>,\s\*&\[\]=+\-!/|]+?)\s*\((.|\n)*?\)\s*"
                  r"(const\s*)?(noexcept\s*)?(override\s*)?(->\s*[^{;]+)?(:\s*[^;{]*)?\{\s*$")


def functions(path):
    lines = open(path, encoding="utf-8").read().split("\n")
    out = []
    i = 0
    while i < len(lines):
        line = lines[i]
        stripped = line.strip()
        # A definition opens with '{' at the end of its (possibly multi-line) head; the head
        # starts at an unindented or namespace-level line that is not a control statement.
        if stripped.endswith("{") and not stripped.startswith(("if", "for", "while", "switch",
                                                                 "}", "else", "do", "namespace",
                                                                 "struct", "class", "enum",
                                                                 "case", "return", "try", "#")):
            # walk back to the start of the head (lines ending without ; { })
            start = i
            while start > 0 and lines[start - 1].strip() and not lines[start - 1].strip().endswith(
                    (";", "{", "}", "*/", ":")) and not lines[start - 1].strip().startswith(("//", "#")):
                start -= 1
            head = " ".join(l.strip() for l in lines[start:i + 1])
            indent = len(lines[start]) - len(lines[start].lstrip())
            if "(" in head and "=" not in head.split("(")[0] and indent <= 2:
                depth = 0
                j = i
                while j < len(lines):
                    depth += lines[j].count("{") - lines[j].count("}")
                    if depth <= 0 and j > i or (depth == 0 and j == i):
                        break
                    j += 1
                name = head.split("(")[0].split()[-1] if head.split("(")[0].split() else "?"
                out.append((j - start + 1, start + 1, name))
                i = j + 1
                continue
        i += 1
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--limit", type=int, default=80)
    ap.add_argument("paths", nargs="+")
    a = ap.parse_args()
    found = []
    for p in a.paths:
        files = [p] if os.path.isfile(p) else [
            os.path.join(d, f) for d, _, fs in os.walk(p) for f in fs if f.endswith((".cc", ".h"))]
        for f in sorted(files):
            for n, line, name in functions(f):
                if n > a.limit:
                    found.append((n, f, line, name))
    for n, f, line, name in sorted(found, reverse=True):
        print(f"{n:5d}  {f}:{line}  {name}")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
