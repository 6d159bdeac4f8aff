#!/usr/bin/python3
"""Counts the options the front ends still define by hand (issue 38: near zero when every option is a
row of a table that the front ends lift).

    scripts/count_option_definitions.py [ROOT] [--list]   (ROOT: the project, default: this script's parent)

What counts as one hand-written option definition (the total):
  cli     an option name written as a literal in src/cli/*.cpp: ("name", ...) in an add_options() chain
          (what is left: the parser's own --help and --config, written once for every command);
  python  a keyword with a default in a .def(...) of src/python/*.cpp (py::arg("name") = value), and a
          keyword taken out of **kwargs by name (pop<T>(kwargs, "name", ...), kwargs.contains("name")),
          unless it is data (below);
  ros     a parameter row written in ros/*.cpp ({"name", ...} pushed into a table) or a parameter name
          held in a constant (constexpr const char* kXParameter = "name").
Rows lifted from a table (add_option_rows(), add_text_rows(), rows_within(), keywords made from rows,
py::arg(row.name.c_str())) are not counted: their names are written once, next to their struct.

Not options, so not counted, but listed apart:
  rows    the rows a front end declares for its own structs (path_row, text_row, field_row, switch_row,
          inverted_switch_row, choice_row in src/cli, src/python, ros): the files a command reads and
          writes, its output switches, the node's settle time. Each is a row like the library's, added,
          read and checked by the same functions; they are printed as "front-end rows", not hidden;
  data    a Python function's data arguments: the array or polygon it is given and how to read it
          (resolution, origin, row_order, holes, free, range_min, range_max: a grid's frame and
          layout, a polygon's holes, a mask, a scan's valid ranges), which have no options struct and
          no command-line flag.
--list prints every definition counted, then the front-end rows and the data arguments.
"""
import argparse
import os
import re
import sys

CLI = re.compile(r'(?:add_options\(\)\s*|^\s*)\(\s*"([a-z][a-z0-9-]*)(?:,[a-z])?"\s*,', re.M)
PY_KEYWORD = re.compile(r'py::arg\("([a-z_0-9]+)"\)\s*=')
PY_POPPED = re.compile(r'(?:pop<[^>]+>\(kwargs,\s*|kwargs\.contains\()"([a-z_0-9]+)"')
ROS_ROW = re.compile(r'push_back\(\{\s*"([a-z_0-9]+)"')
ROS_CONSTANT = re.compile(r'constexpr const char\* k\w*Parameter\s*=\s*"([a-z_0-9]+)"')
FRONT_END_ROW = re.compile(r'\b(?:path_row|text_row|field_row|switch_row|inverted_switch_row|choice_row)(?:<[^>(]*>)?\(\s*"([a-z][a-z0-9_-]*)"')
DATA_KEYWORDS = {'resolution', 'origin', 'row_order', 'holes', 'free', 'range_min', 'range_max'}


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
    """(counted, apart): the hand-written definitions per front end, and the front-end rows and data
    arguments listed beside them."""
    counted = {'cli': [], 'python': [], 'ros': []}
    apart = {'front-end rows': [], 'data': []}
    for folder in ('src/cli', 'src/python', 'ros'):
        for path in files(root, folder, '.cpp'):
            apart['front-end rows'] += [(path, n) for n in FRONT_END_ROW.findall(open(path, encoding='utf-8').read())]
    for path in files(root, 'src/cli', '.cpp'):
        counted['cli'] += [(path, n) for n in CLI.findall(open(path, encoding='utf-8').read())]
    for path in files(root, 'src/python', '.cpp'):
        for name in python_keywords(open(path, encoding='utf-8').read()):
            (apart['data'] if name in DATA_KEYWORDS else counted['python']).append((path, name))
    for path in files(root, 'ros', '.cpp'):
        text = open(path, encoding='utf-8').read()
        counted['ros'] += [(path, n) for n in ROS_ROW.findall(text) + ROS_CONSTANT.findall(text)]
    return counted, apart


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0].replace('\n', ' '),
                                     epilog='Prints one line per front end and the total; --list adds every definition.')
    parser.add_argument('root', nargs='?', default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                        help="the project's checkout (default: this script's)")
    parser.add_argument('--list', action='store_true', help='print every definition counted, file and name')
    args = parser.parse_args(argv)
    # A root without the command line's sources would count nothing and print a total of 0.
    if not os.path.isdir(os.path.join(args.root, 'src', 'cli')):
        parser.exit(2, f'count_option_definitions: {args.root} is not a topocut checkout (no src/cli)\n')
    counted, apart = count(args.root)

    def show(label, found):
        print(f'{label}: {len(found)}')
        if args.list:
            for path, name in found:
                print(f'  {os.path.relpath(path, args.root)}: {name}')

    for front, found in counted.items():
        show(front, found)
    print(f'total: {sum(len(found) for found in counted.values())}')
    for kind, found in apart.items():
        show(f'not counted, {kind}', found)
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
