#!/usr/bin/python3
"""Counts the options the front ends still define by hand (issue 38: near zero when every option is a
row of a library table that the front ends lift).

    scripts/count_option_definitions.py [ROOT] [--list]   (ROOT: the project, default: this script's parent)

What counts as one hand-written option definition:
  cli     an option name written as a literal in src/cli/*.cpp: ("name", ...) in an add_options() chain;
  python  a keyword with a default in a .def(...) of src/python/*.cpp (py::arg("name") = value), and a
          keyword taken out of **kwargs by name (pop<T>(kwargs, "name", ...), kwargs.contains("name"));
  ros     a parameter row written in ros/*.cpp ({"name", ...} pushed into a table) or a parameter name
          held in a constant (constexpr const char* kXParameter = "name").
Rows lifted from a table (add_option_rows(), rows_within(), the keyword lists made from rows) are not
counted: their names are written once, next to their struct. --list prints every definition counted.
"""
import os
import re
import sys

CLI = re.compile(r'(?:add_options\(\)\s*|^\s*)\(\s*"([a-z][a-z0-9-]*)(?:,[a-z])?"\s*,', re.M)
PY_KEYWORD = re.compile(r'py::arg\("([a-z_0-9]+)"\)\s*=')
PY_POPPED = re.compile(r'(?:pop<[^>]+>\(kwargs,\s*|kwargs\.contains\()"([a-z_0-9]+)"')
ROS_ROW = re.compile(r'push_back\(\{\s*"([a-z_0-9]+)"')
ROS_CONSTANT = re.compile(r'constexpr const char\* k\w*Parameter\s*=\s*"([a-z_0-9]+)"')


def files(root, folder, ending):
    base = os.path.join(root, folder)
    if not os.path.isdir(base):
        return []
    return sorted(os.path.join(base, f) for f in os.listdir(base) if f.endswith(ending))


def python_keywords(text):
    """The keywords with defaults of the .def(...) statements (not dict keys or other calls)."""
    found = []
    for statement in text.split(';'):
        if 'def(' in statement and 'py::dict(' not in statement:
            found += PY_KEYWORD.findall(statement)
    return found + PY_POPPED.findall(text)


def count(root):
    counted = {'cli': [], 'python': [], 'ros': []}
    for path in files(root, 'src/cli', '.cpp'):
        counted['cli'] += [(path, n) for n in CLI.findall(open(path, encoding='utf-8').read())]
    for path in files(root, 'src/python', '.cpp'):
        counted['python'] += [(path, n) for n in python_keywords(open(path, encoding='utf-8').read())]
    for path in files(root, 'ros', '.cpp'):
        text = open(path, encoding='utf-8').read()
        counted['ros'] += [(path, n) for n in ROS_ROW.findall(text) + ROS_CONSTANT.findall(text)]
    return counted


def main(argv):
    listing = '--list' in argv
    rest = [a for a in argv if a != '--list']
    root = rest[0] if rest else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    counted = count(root)
    for front, found in counted.items():
        print(f'{front}: {len(found)}')
        if listing:
            for path, name in found:
                print(f'  {os.path.relpath(path, root)}: {name}')
    print(f'total: {sum(len(found) for found in counted.values())}')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
