"""The size limits of docs/dev/CODING_STYLE.md, checked on the module sources.

Tests (each module's Testing/) are not counted: a test is a list of cases.

No function over 150 lines, no source file over 1000 lines. Prints the
longest functions (so a reviewer sees where the code is heading) and fails
when a limit is broken. Function extents come from Universal Ctags.

    vtkPhongStructureCheck.py <source root> [--functions 150] [--file-lines 1000]
"""

import argparse
import os
import subprocess
import sys

SOURCE_DIRECTORIES = ("Module", "ParaView")
SOURCE_SUFFIXES = (".h", ".cxx", ".glsl")


def source_files(root):
    """Every C++ and GLSL file of the modules and the ParaView plugin, tests aside."""
    for directory in SOURCE_DIRECTORIES:
        for folder, subfolders, names in os.walk(os.path.join(root, directory)):
            subfolders[:] = sorted(name for name in subfolders if name != "Testing")
            for name in sorted(names):
                if name.endswith(SOURCE_SUFFIXES):
                    yield os.path.join(folder, name)


def function_lengths(path):
    """(length, name, first line) of each function ctags finds in a C++ file."""
    output = subprocess.run(
        ["ctags", "--language-force=C++", "--c++-kinds=f", "--fields=+ne", "-f", "-", path],
        check=True, capture_output=True, text=True).stdout
    for line in output.splitlines():
        fields = line.split("\t")
        extents = dict(field.split(":", 1) for field in fields[3:] if ":" in field)
        if "line" in extents and "end" in extents:
            first, last = int(extents["line"]), int(extents["end"])
            yield last - first + 1, fields[0], first


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("root")
    parser.add_argument("--functions", type=int, default=150)
    parser.add_argument("--file-lines", type=int, default=1000)
    args = parser.parse_args()

    functions, problems = [], []
    for path in source_files(args.root):
        relative = os.path.relpath(path, args.root)
        with open(path, encoding="utf-8") as stream:
            lines = sum(1 for _ in stream)
        if lines > args.file_lines:
            problems.append("%s has %d lines (limit %d)" % (relative, lines, args.file_lines))
        if path.endswith(".cxx"):
            functions += [(length, "%s:%d %s" % (relative, first, name))
                          for length, name, first in function_lengths(path)]
    functions.sort(reverse=True)
    print("%d functions; longest:" % len(functions))
    for length, where in functions[:10]:
        print("  %4d  %s" % (length, where))
    problems += ["%s is %d lines long (limit %d)" % (where, length, args.functions)
                 for length, where in functions if length > args.functions]
    for problem in problems:
        print("ERROR: " + problem)
    return 1 if problems or not functions else 0


if __name__ == "__main__":
    sys.exit(main())
